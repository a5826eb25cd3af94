# How test executables are compiled: for build speed, since CI builds them twice (Release and the sanitizers).
# The code under test lives in the libraries, compiled at the build's optimisation; the test code itself at -O1.
# One precompiled header per executable holds GoogleTest and, where asked, nlohmann-json: these headers were
# most of each test file's compile time (json 3.6 s and gtest 1.9 s to parse, against 4-7 s per file).
function(rosin_test_build_options target)
    target_compile_options(${target} PRIVATE -O1)
    target_precompile_headers(${target} PRIVATE <gtest/gtest.h> <cmath> <string> <vector> ${ARGN})
endfunction()
