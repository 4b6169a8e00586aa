# facet_add_plugin(<name> SOURCES <file>... [LIBRARIES <target>...])
#
# Builds a stage plugin as a MODULE library named libfacet_<name>.so, the file name the host
# looks for. Symbols are hidden by default, so the only exported symbol is the entry point that
# FACET_PLUGIN defines; undefined symbols fail the link rather than the load.
function(facet_add_plugin name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "facet_add_plugin(${name}): SOURCES is required")
  endif()
  set(target facet_plugin_${name})
  add_library(${target} MODULE ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE facet::sdk ${ARG_LIBRARIES})
  set_target_properties(${target} PROPERTIES
    PREFIX "lib"
    OUTPUT_NAME "facet_${name}"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  target_link_options(${target} PRIVATE "LINKER:--no-undefined")
  if(DEFINED FACET_PLUGIN_OUTPUT_DIRECTORY)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${FACET_PLUGIN_OUTPUT_DIRECTORY})
  endif()
  if(COMMAND facet_set_warnings)
    facet_set_warnings(${target})
  endif()
  if(NOT DEFINED FACET_INSTALL_PLUGINDIR)
    include(GNUInstallDirs)
    set(FACET_INSTALL_PLUGINDIR ${CMAKE_INSTALL_LIBDIR}/facet/plugins)
  endif()
  # Installed plugins find libfacet_sdk.so two levels up: <prefix>/lib/facet/plugins -> <prefix>/lib.
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/../..")
  install(TARGETS ${target} LIBRARY DESTINATION ${FACET_INSTALL_PLUGINDIR})
endfunction()
