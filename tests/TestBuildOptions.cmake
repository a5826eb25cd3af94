# How test executables are compiled: for build speed, since CI builds them twice (Release and the sanitizers).
# The code under test lives in the libraries, compiled at the build's optimisation; the test code itself at -O1.
# One precompiled header per executable holds GoogleTest and, where asked, nlohmann-json: these headers were
# most of each test file's compile time (json 3.6 s and gtest 1.9 s to parse, against 4-7 s per file).
#
# With ROSIN_UNITY_BUILD (the default) an executable's files are compiled together, a few per unit. Test files
# give their helpers short common names (kFs, pi, Rig), so each keeps them in `namespace ROSIN_FILE_LOCAL`:
# a name unique to the file in a unity build (CMake's UNITY_BUILD_UNIQUE_ID), an anonymous namespace otherwise.
function(rosin_test_build_options target)
    target_compile_options(${target} PRIVATE -O1)
    target_precompile_headers(${target} PRIVATE <gtest/gtest.h> <cmath> <string> <vector> ${ARGN})
    if(ROSIN_UNITY_BUILD)
        set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_UNIQUE_ID ROSIN_FILE_LOCAL)
    else()
        target_compile_definitions(${target} PRIVATE ROSIN_FILE_LOCAL=)
    endif()
endfunction()

# Registers a test executable's GoogleTest tests with `label`. The tests a gtest filter names in SLOW (the
# discover runs, the grid sweeps, whole-plugin renders) get the label `<label>-slow` instead: the edit loop
# (`ctest --preset dev`, which leaves out -L slow) then runs in about a minute, while `-L <label>`, a regular
# expression, still selects them (a list of labels does not survive gtest_discover_tests's PROPERTIES).
# They also start first (COST): on two cores the long ones then run side by side from the start instead of
# trailing one after the other at the end. Further arguments are test properties for all of them.
function(rosin_discover_tests target label)
    cmake_parse_arguments(ARG "" "SLOW" "" ${ARGN})
    if(ARG_SLOW)
        gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "-${ARG_SLOW}"
                             PROPERTIES LABELS ${label} ${ARG_UNPARSED_ARGUMENTS})
        gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 TEST_FILTER "${ARG_SLOW}"
                             PROPERTIES LABELS ${label}-slow COST 1000 ${ARG_UNPARSED_ARGUMENTS})
    else()
        gtest_discover_tests(${target} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS ${label} ${ARG_UNPARSED_ARGUMENTS})
    endif()
endfunction()
