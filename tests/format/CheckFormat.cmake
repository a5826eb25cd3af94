# Fails, naming the files, when a C++ file of the project is not formatted as .clang-format says (issue 21: CI
# fails on unformatted code). Run by CTest as format.clang-format:
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
set(unformatted "")
foreach(file IN LISTS files)
    execute_process(COMMAND ${CLANG_FORMAT} --dry-run --Werror --style=file ${file}
                    WORKING_DIRECTORY ${ROOT} RESULT_VARIABLE result OUTPUT_QUIET ERROR_QUIET)
    if(NOT result EQUAL 0)
        file(RELATIVE_PATH relative ${ROOT} ${file})
        list(APPEND unformatted ${relative})
    endif()
endforeach()
if(unformatted)
    list(JOIN unformatted "\n  " listing)
    message(FATAL_ERROR "not formatted as .clang-format says (clang-format -i FILE):\n  ${listing}")
endif()
message(STATUS "all ${count} C++ files formatted as .clang-format says")
