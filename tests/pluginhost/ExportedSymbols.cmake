# cmake -DNM=... -DMODULE=path -DMAX=n -P ExportedSymbols.cmake
# Fails when the plugin module exports more than MAX dynamic symbols: only the format's entry points (and a
# few weak template instances from the C++ runtime) should be visible to the host.
execute_process(COMMAND ${NM} -D --defined-only ${MODULE} OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "${NM} failed on ${MODULE}")
endif()
string(REGEX MATCHALL "\n" lines "\n${symbols}")
list(LENGTH lines count)
math(EXPR count "${count} - 1")
message(STATUS "[figure] ${MODULE}: ${count} exported symbols (limit ${MAX})")
if(count GREATER MAX)
    message(FATAL_ERROR "${MODULE} exports ${count} symbols; expected at most ${MAX}")
endif()
foreach(entry ${ENTRY})
    if(NOT symbols MATCHES " T ${entry}\n")
        message(FATAL_ERROR "${MODULE} does not export its entry point ${entry}")
    endif()
endforeach()
