# shadelab as a library for other projects: `cmake --install` puts the layer
# libraries, their headers and the shadelab binary under a prefix, with a
# CMake package (find_package(shadelab CONFIG), targets shadelab::shadelab and
# one shadelab::<layer> per library) and a pkg-config file (shadelab.pc).
# The installed-tree consumer test (tests/CMakeLists.txt, install:consumer)
# builds examples/headless_capture against what this installs.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# Everything a program using the headless renderer links: the layers, and the
# embedded SPIR-V the Vulkan layer links privately (a static library's private
# links still reach the final link, so they are exported too).
set(shadelab_library_targets
  shadelab_base shadelab_scene shadelab_metrics shadelab_trace shadelab_shaders shadelab_vulkan
  shadelab_passes shadelab_measure)
foreach(target IN LISTS shadelab_library_targets)
  string(REPLACE "shadelab_" "" export_name "${target}")
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
endforeach()
# shadelab::shadelab: the whole headless API in one name.
add_library(shadelab_library INTERFACE)
set_target_properties(shadelab_library PROPERTIES EXPORT_NAME shadelab)
target_link_libraries(shadelab_library INTERFACE shadelab_measure)

install(TARGETS ${shadelab_library_targets} shadelab_library EXPORT shadelabTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS shadelab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The OpenImageIO module, loaded on first use (src/core/base/oiio_module.h):
# the installed binary finds it from its own folder, programs built against
# the package through a RUNPATH (shadelab_base's INSTALL_INTERFACE link
# option, and the -rpath in shadelab.pc).
install(TARGETS shadelab_oiio LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/shadelab)
# Headers keep their paths under include/shadelab ("core/base/image.h"), next
# to interface.h, the header shared with GLSL. The viewer and the CLI are not
# part of the library.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadelab
        FILES_MATCHING PATTERN "*.h"
        PATTERN "app" EXCLUDE PATTERN "view" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/shaders/interface.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shadelab)
target_include_directories(shadelab_scene INTERFACE
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/shadelab>)

set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/shadelab)
install(EXPORT shadelabTargets NAMESPACE shadelab:: DESTINATION ${config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/shadelabConfig.cmake.in
  ${PROJECT_BINARY_DIR}/shadelabConfig.cmake INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/shadelabConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/shadelabConfig.cmake
              ${PROJECT_BINARY_DIR}/shadelabConfigVersion.cmake
        DESTINATION ${config_dir})

# pkg-config: the layers in link order, then what they link privately (they
# are static libraries, so a plain `pkg-config --libs` lists everything).
set(pc_libs "")
foreach(layer measure passes vulkan shaders trace metrics scene base)
  string(APPEND pc_libs " -lshadelab_${layer}")
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/cmake/shadelab.pc.in ${PROJECT_BINARY_DIR}/shadelab.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/shadelab.pc DESTINATION ${CMAKE_INSTALL_DATADIR}/pkgconfig)
