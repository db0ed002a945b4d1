# Script mode, run after a test binary is built: writes OUTPUT, a ctest file
# with one add_test per suite of EXECUTABLE (see gtest_suites.cmake).
execute_process(COMMAND "${EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${result})")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(content "")
set(count 0)
foreach(line IN LISTS lines)
  # Suite lines start in column 0 and end with '.', maybe followed by a comment.
  if(line MATCHES "^([^ #][^ ]*)\\.")
    set(suite "${CMAKE_MATCH_1}")
    string(APPEND content
      "add_test([=[${PREFIX}:${suite}]=] [==[${EXECUTABLE}]==] [=[--gtest_filter=${suite}.*]=])\n"
      "set_tests_properties([=[${PREFIX}:${suite}]=] PROPERTIES LABELS ${LABEL})\n")
    math(EXPR count "${count} + 1")
  endif()
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} lists no test suites")
endif()
file(WRITE "${OUTPUT}" "${content}")
