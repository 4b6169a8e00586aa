# facet_add_stage_library(<target> SOURCES <file>... [PUBLIC <lib>...] [PRIVATE <lib>...])
#
# A bundled plugin's stage code as a static library: linked by the plugin module (made with
# facet_add_plugin), by the unit tests and by the benchmarks, which thus test the very code the
# plugin runs. Built position-independent and with hidden symbols, as the module is.
function(facet_add_stage_library target)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(${target} STATIC ${ARG_SOURCES})
  # Stage headers are included as "<family>/<file>.hpp".
  target_include_directories(${target} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/..)
  target_link_libraries(${target} PUBLIC facet::sdk opencv_core ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  facet_set_warnings(${target})
endfunction()
