# Which libraries a target may reach at link time, checked when CMake
# configures (docs/ARCHITECTURE.md, "Layer rules"):
#
#   shadelab_forbid_links(TARGETS target... FORBIDDEN library...)
#
# walks each target's link closure (LINK_LIBRARIES and INTERFACE_LINK_LIBRARIES,
# recursively; a static library's private dependencies appear there as
# $<LINK_ONLY:...>) and stops the configure step naming the chain that reaches
# a forbidden library. Conditional generator expressions count as if true; an
# expression it cannot read stops the configure step too, rather than letting
# a dependency through unchecked. Targets that do not exist (the fuzz build
# has no Vulkan layer) are skipped.

# The target or library a link item names, "" for none.
function(_shadelab_link_item_name item owner out)
  set(name "${item}")
  while(name MATCHES "^\\$<")
    if(name MATCHES "^\\$<(LINK_ONLY|BUILD_INTERFACE|TARGET_NAME_IF_EXISTS):(.*)>$")
      set(name "${CMAKE_MATCH_2}")
    elseif(name MATCHES "^\\$<INSTALL_INTERFACE:")
      set(name "")
    elseif(name MATCHES "^\\$<\\$<[^<>]*>:(.*)>$")
      set(name "${CMAKE_MATCH_1}")
    else()
      message(FATAL_ERROR "shadelab_forbid_links: cannot read the link item '${item}' of "
                          "${owner}; teach cmake/link_rules.cmake its generator expression")
    endif()
  endwhile()
  # target_link_libraries from another directory brackets items with ::@(id) markers.
  if(name MATCHES "^::@")
    set(name "")
  endif()
  if(TARGET "${name}")
    get_target_property(aliased "${name}" ALIASED_TARGET)
    if(aliased)
      set(name "${aliased}")
    endif()
  endif()
  set(${out} "${name}" PARENT_SCOPE)
endfunction()

function(shadelab_forbid_links)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "" "TARGETS;FORBIDDEN")
  set(forbidden "")
  foreach(library IN LISTS arg_FORBIDDEN)
    _shadelab_link_item_name("${library}" "FORBIDDEN" name)
    list(APPEND forbidden "${name}")
  endforeach()
  foreach(root IN LISTS arg_TARGETS)
    if(NOT TARGET "${root}")
      continue()
    endif()
    # Breadth first; each queue entry is the chain "root -> a -> b", b to expand.
    set(queue "${root}")
    set(seen "${root}")
    while(queue)
      list(POP_FRONT queue chain)
      string(REGEX REPLACE "^.* -> " "" target "${chain}")
      set(items "")
      foreach(property IN ITEMS LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
        get_target_property(values "${target}" ${property})
        if(values)
          list(APPEND items ${values})
        endif()
      endforeach()
      foreach(item IN LISTS items)
        _shadelab_link_item_name("${item}" "${target}" name)
        if(name STREQUAL "")
          continue()
        endif()
        if(name IN_LIST forbidden)
          message(FATAL_ERROR "${root} must not link ${name}, but reaches it: ${chain} -> ${name} "
                              "(docs/ARCHITECTURE.md, Layer rules)")
        endif()
        if(TARGET "${name}" AND NOT name IN_LIST seen)
          list(APPEND seen "${name}")
          list(APPEND queue "${chain} -> ${name}")
        endif()
      endforeach()
    endwhile()
  endforeach()
endfunction()
