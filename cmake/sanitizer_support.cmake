# The `asan` preset: every executable gets tests/sanitizers/keep_modules.cpp
# (a dlclose that unloads nothing), so LeakSanitizer can name, and
# tests/sanitizers/lsan.supp suppress, the leaks of the validation layer and
# lavapipe, which the Vulkan loader has unloaded by the time it reports.
# Call once every target exists.
function(_shadelab_executables directory out)
  get_property(targets DIRECTORY "${directory}" PROPERTY BUILDSYSTEM_TARGETS)
  set(found "")
  foreach(target IN LISTS targets)
    get_target_property(type "${target}" TYPE)
    if(type STREQUAL "EXECUTABLE")
      list(APPEND found "${target}")
    endif()
  endforeach()
  get_property(subdirectories DIRECTORY "${directory}" PROPERTY SUBDIRECTORIES)
  foreach(subdirectory IN LISTS subdirectories)
    _shadelab_executables("${subdirectory}" more)
    list(APPEND found ${more})
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

function(shadelab_keep_modules_for_lsan)
  _shadelab_executables("${PROJECT_SOURCE_DIR}" executables)
  foreach(target IN LISTS executables)
    target_sources("${target}" PRIVATE "${PROJECT_SOURCE_DIR}/tests/sanitizers/keep_modules.cpp")
  endforeach()
endfunction()
