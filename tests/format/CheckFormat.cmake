# Fails, naming the files, when a C++ file of the project is not formatted as .clang-format says, so CI
# fails on unformatted code. Run by CTest as format.clang-format:
#   cmake -DCLANG_FORMAT=... -DROOT=... -P CheckFormat.cmake
# Fix with: clang-format -i FILE (Debian's clang-format 14, installed by .ci/install-deps).
if(NOT CLANG_FORMAT)
    message(FATAL_ERROR "clang-format not found: `bash .ci/install-deps` installs it (Debian package clang-format)")
endif()
file(GLOB_RECURSE files LIST_DIRECTORIES false
     ${ROOT}/Source/*.cpp ${ROOT}/Source/*.h ${ROOT}/tests/*.cpp ${ROOT}/tests/*.h
     ${ROOT}/benchmarks/*.cpp ${ROOT}/benchmarks/*.h ${ROOT}/Resources/*.cpp ${ROOT}/Resources/*.h)
list(FILTER files EXCLUDE REGEX "/tests/fuzz/corpus/")
list(LENGTH files count)
# One clang-format process for all files (one per file took 66-95 s of CI's two cores, this takes ~3 s); its
# diagnostics ("FILE:LINE:COL: error: code should be clang-formatted") name the files.
execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror --style=file ${files}
                WORKING_DIRECTORY ${ROOT} RESULT_VARIABLE result OUTPUT_QUIET ERROR_VARIABLE diagnostics)
set(unformatted "")
if(NOT result EQUAL 0)
    string(REGEX MATCHALL "[^\n]+:[0-9]+:[0-9]+: (error|warning): code should be clang-formatted" violations
                 "${diagnostics}")
    foreach(violation IN LISTS violations)
        string(REGEX REPLACE ":[0-9]+:[0-9]+: (error|warning): code should be clang-formatted$" "" path
                             "${violation}")
        file(RELATIVE_PATH relative ${ROOT} ${path})
        list(APPEND unformatted ${relative})
    endforeach()
    list(REMOVE_DUPLICATES unformatted)
    if(NOT unformatted) # it failed for another reason: say what it said
        message(FATAL_ERROR "clang-format failed (exit ${result}):\n${diagnostics}")
    endif()
endif()
if(unformatted)
    list(JOIN unformatted "\n  " listing)
    message(FATAL_ERROR "not formatted as .clang-format says (clang-format -i FILE):\n  ${listing}")
endif()
message(STATUS "all ${count} C++ files formatted as .clang-format says")
