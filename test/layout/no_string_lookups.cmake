# Fails when a bundled stage or the plugin template declares or reads a port or parameter by a
# string instead of through a typed descriptor (facet/contract.hpp, docs/architecture.md).
# Usage: cmake -DROOT=<source dir> -P no_string_lookups.cmake
set(patterns
  "\\.get_(int|double|bool|string)\\("
  "\\.param\\("
  "\\.(optional_)?input<"
  "\\.output<"
  "ctx\\.(input|input_shared|has_input|input_packet|output|output_packet)[<(]")
file(GLOB_RECURSE sources ${ROOT}/plugins/*.cpp ${ROOT}/plugins/*.hpp ${ROOT}/sdk/template/src/*.cpp
     ${ROOT}/sdk/template/src/*.hpp)
set(found "")
foreach(source IN LISTS sources)
  file(STRINGS ${source} lines)
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    foreach(pattern IN LISTS patterns)
      if(line MATCHES "${pattern}")
        file(RELATIVE_PATH relative ${ROOT} ${source})
        string(STRIP "${line}" stripped)
        string(APPEND found "  ${relative}:${number}: ${stripped}\n")
        break()
      endif()
    endforeach()
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "ports or parameters used by name instead of through a descriptor "
                      "(facet/contract.hpp):\n${found}")
endif()
message(STATUS "every bundled stage uses typed descriptors")
