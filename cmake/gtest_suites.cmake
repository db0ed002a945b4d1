# One ctest test per GoogleTest *suite* instead of per test.
#
# Every test process paid ~0.35 s to load OpenImageIO's 260 shared libraries
# (now only shadelab_unit_tests links it; the rest load it on first use, see
# docs/ARCHITECTURE.md), and a GPU test process ~0.8 s more to create a Vulkan instance with the
# validation layer. Per-test processes made that 75% of the suite's time
# (73 s on 2 cores for ~250 tests). Suites are listed from the built binary at
# build time, like gtest_discover_tests, so a new suite can never be missed;
# the failing test's name is in the suite's output.
#
#   shadelab_add_gtest_suites(TARGET LABEL)
function(shadelab_add_gtest_suites target label)
  set(listing "${CMAKE_CURRENT_BINARY_DIR}/${target}_suites.cmake")
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND "${CMAKE_COMMAND}" -D "EXECUTABLE=$<TARGET_FILE:${target}>" -D "OUTPUT=${listing}"
            -D "LABEL=${label}" -D "PREFIX=${target}"
            -P "${PROJECT_SOURCE_DIR}/cmake/gtest_suites_list.cmake"
    BYPRODUCTS "${listing}"
    VERBATIM)
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${listing}")
endfunction()
