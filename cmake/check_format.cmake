# The format check: every C++ file under the given folders matches the
# committed .clang-format (clang-format --dry-run --Werror), listing the
# files that do not and how to fix them.
#   cmake -D ROOT=<source dir> -D DIRS="src;tests" [-D STYLE_FILE=...] -P check_format.cmake
find_program(CLANG_FORMAT NAMES clang-format clang-format-14 REQUIRED)
if(NOT STYLE_FILE)
  set(STYLE_FILE "${ROOT}/.clang-format")
endif()
set(files "")
foreach(dir IN LISTS DIRS)
  file(GLOB_RECURSE found "${ROOT}/${dir}/*.h" "${ROOT}/${dir}/*.cpp")
  list(APPEND files ${found})
endforeach()
# Fixtures under tests/data are inputs (some deliberately broken), not our code.
list(FILTER files EXCLUDE REGEX "/tests/data/")
if(FORMAT_BAD_FIXTURE)
  file(GLOB files "${ROOT}/tests/data/format_bad/*.cpp")
endif()
list(LENGTH files count)
if(count EQUAL 0)
  message(FATAL_ERROR "format: no C++ files found under ${DIRS} in ${ROOT}")
endif()
# One clang-format process for every file; its diagnostics name the files.
execute_process(COMMAND "${CLANG_FORMAT}" --style=file:${STYLE_FILE} --dry-run --Werror ${files}
                RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE diagnostics)
set(bad "")
if(NOT result EQUAL 0)
  string(REGEX MATCHALL "[^\n]+:[0-9]+:[0-9]+: error: code should be clang-formatted" lines
         "${diagnostics}")
  foreach(line IN LISTS lines)
    string(REGEX REPLACE ":[0-9]+:[0-9]+: error: code should be clang-formatted$" "" file "${line}")
    file(RELATIVE_PATH relative "${ROOT}" "${file}")
    list(APPEND bad "${relative}")
  endforeach()
  list(REMOVE_DUPLICATES bad)
  if(NOT bad)
    message(FATAL_ERROR "format: clang-format failed (${result}):\n${diagnostics}")
  endif()
endif()
if(bad)
  list(JOIN bad "\n  " listed)
  message(FATAL_ERROR "format: these files differ from .clang-format:\n  ${listed}\n"
                      "fix with: clang-format -i <file>")
endif()
message(STATUS "format: ${count} files match .clang-format")
