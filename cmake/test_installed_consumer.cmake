# install:consumer (ctest): proves shadelab works as a library of another
# project, from the INSTALLED tree. Installs the build into a temporary
# prefix, builds examples/headless_capture against it twice (CMake's
# find_package and pkg-config), runs it, and checks that the image it rendered
# through the library is byte-identical to the installed shadelab binary's
# `render` of the same scene and settings (shadows off: the library's
# FrameSettings default, where the CLI defaults to pcf3).
# With SANITIZE (the asan preset) the installed libraries hold ASan and UBSan
# calls, so the consumer is compiled and linked with the same sanitizers (and
# runs without the leak check, see below).
# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DBUILD_TYPE=... [-DVALIDATE=ON]
#       [-DSANITIZE=ON] -P this
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR BUILD_TYPE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "test_installed_consumer.cmake: -D${var}=... is required")
  endif()
endforeach()

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(sanitize_flags "")
if(SANITIZE)
  set(sanitize_flags -fsanitize=address,undefined)
  # The consumer lacks tests/sanitizers/keep_modules.cpp, so lavapipe's and
  # LLVM's leaks come from unloaded modules LSan cannot match to the
  # suppressions; the library's own leaks are checked by every other test.
  set(ENV{ASAN_OPTIONS} detect_leaks=0)
endif()
set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
run_step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
if(SANITIZE)
  # ASan intercepts dlopen, so the search runs with libasan's RUNPATH, not the
  # consumer's: under the sanitizers the module is named outright.
  file(GLOB_RECURSE sanitized_module ${prefix}/*/libshadelab_oiio.so)
  set(ENV{SHADELAB_OIIO_MODULE} ${sanitized_module})
endif()

# 1. CMake: find_package(shadelab CONFIG) and shadelab::shadelab.
run_step("configure the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/headless_capture
         -B ${WORK_DIR}/consumer -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
         "-DCMAKE_CXX_FLAGS=${sanitize_flags}" "-DCMAKE_EXE_LINKER_FLAGS=${sanitize_flags}")
run_step("build the consumer" ${CMAKE_COMMAND} --build ${WORK_DIR}/consumer)
set(validate_flag "")
if(VALIDATE)
  set(validate_flag --validate)
endif()
run_step("run the consumer" ${WORK_DIR}/consumer/headless_capture ${WORK_DIR}/library.png default
         --size 320x180 ${validate_flag})
message(STATUS "${step_output}")
run_step("installed shadelab render" ${prefix}/bin/shadelab render default --size 320x180
         --mode phong --shadows off --output ${WORK_DIR}/cli.png)
file(MD5 ${WORK_DIR}/library.png library_md5)
file(MD5 ${WORK_DIR}/cli.png cli_md5)
if(NOT library_md5 STREQUAL cli_md5)
  message(FATAL_ERROR "the library's image (${library_md5}) differs from `shadelab render`'s "
                      "(${cli_md5}): ${WORK_DIR}/library.png, ${WORK_DIR}/cli.png")
endif()
message(STATUS "library image == shadelab render image (md5 ${cli_md5})")

# EXR needs the OpenImageIO module: the installed binary finds it beside its
# own folder (../lib/shadelab), the consumer through the RUNPATH the package
# gave it. Neither may reach the build tree's copy.
run_step("run the consumer, EXR" ${WORK_DIR}/consumer/headless_capture ${WORK_DIR}/library.exr
         default --size 320x180 ${validate_flag})
run_step("installed shadelab render, EXR" ${prefix}/bin/shadelab render default --size 320x180
         --mode phong --shadows off --output ${WORK_DIR}/cli.exr)
file(MD5 ${WORK_DIR}/library.exr library_exr_md5)
file(MD5 ${WORK_DIR}/cli.exr cli_exr_md5)
if(NOT library_exr_md5 STREQUAL cli_exr_md5)
  message(FATAL_ERROR "the library's EXR (${library_exr_md5}) differs from `shadelab render`'s "
                      "(${cli_exr_md5})")
endif()
file(GLOB_RECURSE installed_module ${prefix}/*/libshadelab_oiio.so)
if(NOT installed_module)
  message(FATAL_ERROR "libshadelab_oiio.so is not installed under ${prefix}")
endif()
message(STATUS "EXR through the installed module (${installed_module}): md5 ${cli_exr_md5}")

# 2. pkg-config: the same program compiled by hand from shadelab.pc.
find_program(PKG_CONFIG pkg-config REQUIRED)
find_program(CXX_COMPILER c++ REQUIRED)
set(ENV{PKG_CONFIG_PATH} ${prefix}/share/pkgconfig)
run_step("pkg-config" ${PKG_CONFIG} --cflags --libs shadelab)
string(STRIP "${step_output}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
run_step("compile with pkg-config flags" ${CXX_COMPILER}
         ${SOURCE_DIR}/examples/headless_capture/main.cpp -o ${WORK_DIR}/capture_pc ${flags}
         ${sanitize_flags})
run_step("run the pkg-config build" ${WORK_DIR}/capture_pc ${WORK_DIR}/pc.png default
         --size 320x180 ${validate_flag})
file(MD5 ${WORK_DIR}/pc.png pc_md5)
if(NOT pc_md5 STREQUAL cli_md5)
  message(FATAL_ERROR "the pkg-config build's image (${pc_md5}) differs from ${cli_md5}")
endif()
message(STATUS "pkg-config build image == shadelab render image")
run_step("run the pkg-config build, EXR" ${WORK_DIR}/capture_pc ${WORK_DIR}/pc.exr default
         --size 320x180 ${validate_flag})
file(MD5 ${WORK_DIR}/pc.exr pc_exr_md5)
if(NOT pc_exr_md5 STREQUAL cli_exr_md5)
  message(FATAL_ERROR "the pkg-config build's EXR (${pc_exr_md5}) differs from ${cli_exr_md5}")
endif()
message(STATUS "pkg-config build EXR == shadelab render EXR")
