# facet_add_plugin(<name> SOURCES <file>... [LIBRARIES <target>...])
#
# Builds a stage plugin as a MODULE library named libfacet_<name>.so, the file name the host
# looks for, in the current binary directory (or FACET_PLUGIN_OUTPUT_DIRECTORY when set).
# Symbols are hidden by default, so the only exported symbol is the entry point that
# FACET_PLUGIN defines; undefined symbols fail the link rather than the load.
# `cmake --install` puts the plugin into <prefix>/lib/facet/plugins, where facet finds it.
include_guard(GLOBAL)
include(GNUInstallDirs)

# Warns when this project's C++ compiler differs from the SDK's in family or major version: the
# host would refuse the plugin with "toolchain mismatch" when loading it.
function(_facet_check_plugin_compiler target)
  if(NOT DEFINED FACET_SDK_CXX_COMPILER_ID OR FACET_SDK_CXX_COMPILER_ID STREQUAL "")
    return()  # building inside the facet tree: same compiler by construction
  endif()
  string(REGEX MATCH "^[0-9]+" sdk_major "${FACET_SDK_CXX_COMPILER_VERSION}")
  string(REGEX MATCH "^[0-9]+" own_major "${CMAKE_CXX_COMPILER_VERSION}")
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL FACET_SDK_CXX_COMPILER_ID OR
     NOT own_major STREQUAL sdk_major)
    message(WARNING
      "facet_add_plugin(${target}): the facet SDK was built with ${FACET_SDK_CXX_COMPILER_ID} "
      "${FACET_SDK_CXX_COMPILER_VERSION}, this project uses ${CMAKE_CXX_COMPILER_ID} "
      "${CMAKE_CXX_COMPILER_VERSION}. facet will refuse to load the plugin (toolchain "
      "mismatch); configure with -DCMAKE_CXX_COMPILER=<the SDK's compiler>.")
  endif()
endfunction()

function(facet_add_plugin name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBRARIES" ${ARGN})
  if(NOT ARG_SOURCES)
    message(FATAL_ERROR "facet_add_plugin(${name}): SOURCES is required")
  endif()
  if(NOT name MATCHES "^[A-Za-z0-9_]+$")
    message(FATAL_ERROR "facet_add_plugin(${name}): use letters, digits and '_' in plugin names")
  endif()
  _facet_check_plugin_compiler(${name})
  set(target facet_plugin_${name})
  add_library(${target} MODULE ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE facet::sdk ${ARG_LIBRARIES})
  set_target_properties(${target} PROPERTIES
    PREFIX "lib"
    OUTPUT_NAME "facet_${name}"
    SUFFIX ".so"
    CXX_VISIBILITY_PRESET hidden
    VISIBILITY_INLINES_HIDDEN ON)
  target_link_options(${target} PRIVATE "LINKER:--no-undefined")
  if(DEFINED FACET_PLUGIN_OUTPUT_DIRECTORY)
    set_target_properties(${target} PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${FACET_PLUGIN_OUTPUT_DIRECTORY})
  endif()
  if(COMMAND facet_set_warnings)
    facet_set_warnings(${target})
  endif()
  if(DEFINED FACET_INSTALL_PLUGINDIR)
    set(plugin_dir ${FACET_INSTALL_PLUGINDIR})
  else()
    set(plugin_dir ${CMAKE_INSTALL_LIBDIR}/facet/plugins)
  endif()
  # Installed plugins find libfacet_sdk.so two levels up: <prefix>/lib/facet/plugins -> <prefix>/lib.
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "$ORIGIN/../..")
  install(TARGETS ${target} LIBRARY DESTINATION ${plugin_dir})
endfunction()
