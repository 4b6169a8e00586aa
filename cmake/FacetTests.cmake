# facet_discover_tests(<program> [WORKING_DIRECTORY dir] [DISCOVERY_TIMEOUT s] [PROPERTIES ...])
#
# Registers a GoogleTest program with CTest. By default every test case is its own CTest test
# (gtest_discover_tests), so that `ctest -R` picks single cases and a crash names its case. With
# FACET_TEST_PER_PROGRAM (the sanitizer presets) the program is one CTest test instead: a
# sanitizer build starts a process in seconds rather than milliseconds, and over a thousand
# processes would cost more than the tests themselves.
option(FACET_TEST_PER_PROGRAM "Register each GoogleTest program as one CTest test" OFF)

function(facet_discover_tests program)
  cmake_parse_arguments(ARG "" "WORKING_DIRECTORY;DISCOVERY_TIMEOUT" "PROPERTIES" ${ARGN})
  if(NOT ARG_WORKING_DIRECTORY)
    set(ARG_WORKING_DIRECTORY ${PROJECT_BINARY_DIR})
  endif()
  if(FACET_TEST_PER_PROGRAM)
    add_test(NAME ${program} COMMAND ${program} --gtest_brief=1
             WORKING_DIRECTORY ${ARG_WORKING_DIRECTORY})
    set_tests_properties(${program} PROPERTIES TIMEOUT 2400 ${ARG_PROPERTIES})
  else()
    if(NOT ARG_DISCOVERY_TIMEOUT)
      set(ARG_DISCOVERY_TIMEOUT 60)
    endif()
    if(ARG_PROPERTIES)
      gtest_discover_tests(${program} WORKING_DIRECTORY ${ARG_WORKING_DIRECTORY}
                           DISCOVERY_TIMEOUT ${ARG_DISCOVERY_TIMEOUT} PROPERTIES ${ARG_PROPERTIES})
    else()
      gtest_discover_tests(${program} WORKING_DIRECTORY ${ARG_WORKING_DIRECTORY}
                           DISCOVERY_TIMEOUT ${ARG_DISCOVERY_TIMEOUT})
    endif()
  endif()
endfunction()
