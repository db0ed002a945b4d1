# Debian's OpenImageIO config lists /usr/include/opencv4, which does not exist
# without OpenCV installed; CMake refuses missing include directories. Used
# after find_package(OpenImageIO) by the build and by the installed
# shadelabConfig.cmake.
foreach(target IN ITEMS OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  if(TARGET ${target})
    get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
    if(dirs)
      list(FILTER dirs EXCLUDE REGEX "opencv4")
      set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${dirs}")
    endif()
  endif()
endforeach()
