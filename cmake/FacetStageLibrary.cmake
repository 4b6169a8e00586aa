# facet_add_stage_library(<target> SOURCES <file>... [PUBLIC <lib>...] [PRIVATE <lib>...])
#
# A bundled plugin's stage code as a static library: linked by the plugin module (made with
# facet_add_plugin in the same folder), by the unit tests and by the benchmarks, which thus test
# the very code the plugin runs. Built position-independent and with hidden symbols, as the
# module is. No other plugin links it (facet_check_plugin_dependencies).
#
# facet_add_support_library(<target> SOURCES <file>... [PUBLIC <lib>...] [PRIVATE <lib>...])
#
# Code that several plugins share (io's frame listing and overlay picture, eval's segment
# matching), declared as such: any plugin may link a support library, built like a stage library
# but holding no stage.
function(_facet_add_plugin_code_library target role)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(${target} STATIC ${ARG_SOURCES})
  # Stage headers are included as "<family>/<file>.hpp".
  target_include_directories(${target} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/..)
  target_link_libraries(${target} PUBLIC facet::sdk opencv_core ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON FACET_LIBRARY_ROLE ${role})
  facet_set_warnings(${target})
endfunction()

function(facet_add_stage_library target)
  _facet_add_plugin_code_library(${target} stage ${ARGN})
endfunction()

function(facet_add_support_library target)
  _facet_add_plugin_code_library(${target} support ${ARGN})
endfunction()

# The targets defined in `dir` and every folder below it.
function(_facet_targets_below dir out_var)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdir IN LISTS subdirs)
    _facet_targets_below(${subdir} below)
    list(APPEND targets ${below})
  endforeach()
  set(${out_var} ${targets} PARENT_SCOPE)
endfunction()

# The targets `target` links, directly or through other targets (aliases resolved).
function(_facet_link_closure target out_var)
  set(seen)
  set(pending ${target})
  while(pending)
    list(POP_FRONT pending current)
    foreach(property IN ITEMS LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
      get_target_property(links ${current} ${property})
      if(NOT links)
        continue()
      endif()
      foreach(link IN LISTS links)
        string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" link "${link}")
        if(NOT TARGET "${link}")
          continue()
        endif()
        get_target_property(aliased ${link} ALIASED_TARGET)
        if(aliased)
          set(link ${aliased})
        endif()
        if(NOT link IN_LIST seen)
          list(APPEND seen ${link})
          list(APPEND pending ${link})
        endif()
      endforeach()
    endforeach()
  endwhile()
  set(${out_var} ${seen} PARENT_SCOPE)
endfunction()

# facet_check_plugin_dependencies(<dir>)
#
# The dependency rule of docs/architecture.md, checked when the build is configured: a plugin
# module under <dir> links the SDK, facet::algo, support libraries and the stage libraries of its
# own folder, never another plugin's stage library. A plugin that needs another's code names
# what it needs in a support library instead.
function(facet_check_plugin_dependencies dir)
  _facet_targets_below(${dir} targets)
  set(violations)
  foreach(module IN LISTS targets)
    get_target_property(type ${module} TYPE)
    if(NOT type STREQUAL "MODULE_LIBRARY")
      continue()
    endif()
    get_target_property(module_dir ${module} SOURCE_DIR)
    _facet_link_closure(${module} linked)
    foreach(library IN LISTS linked)
      get_target_property(role ${library} FACET_LIBRARY_ROLE)
      get_target_property(library_dir ${library} SOURCE_DIR)
      if(role STREQUAL "stage" AND NOT library_dir STREQUAL module_dir)
        file(RELATIVE_PATH module_where ${PROJECT_SOURCE_DIR} ${module_dir})
        file(RELATIVE_PATH library_where ${PROJECT_SOURCE_DIR} ${library_dir})
        list(APPEND violations
          "  ${module} (${module_where}) links ${library}, the stage library of ${library_where}")
      endif()
    endforeach()
  endforeach()
  if(violations)
    list(JOIN violations "\n" text)
    message(FATAL_ERROR "A plugin links another plugin's stages:\n${text}\nMove the code they "
      "share into a support library (facet_add_support_library) and link that instead.")
  endif()
endfunction()
