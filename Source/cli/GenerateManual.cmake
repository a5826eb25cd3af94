# Writes the man page and the bash completion with the rosin just built (cmake -P, from Source/cli/CMakeLists.txt):
# both come from the option tables its commands parse with. -DROSIN=... -DMAN_PAGE=....1.gz -DCOMPLETION=...
foreach(output MAN_PAGE COMPLETION)
    get_filename_component(folder ${${output}} DIRECTORY)
    file(MAKE_DIRECTORY ${folder})
endforeach()
execute_process(COMMAND ${ROSIN} --man OUTPUT_FILE ${MAN_PAGE}.tmp RESULT_VARIABLE man_status)
execute_process(COMMAND ${ROSIN} --completion bash OUTPUT_FILE ${COMPLETION} RESULT_VARIABLE completion_status)
if(NOT man_status EQUAL 0 OR NOT completion_status EQUAL 0)
    message(FATAL_ERROR "rosin --man / --completion bash failed (${man_status}, ${completion_status})")
endif()
# -n: no name or time stamp in the archive, so the same page gives the same bytes.
execute_process(COMMAND gzip -9n -c ${MAN_PAGE}.tmp OUTPUT_FILE ${MAN_PAGE} RESULT_VARIABLE gzip_status)
file(REMOVE ${MAN_PAGE}.tmp)
if(NOT gzip_status EQUAL 0)
    message(FATAL_ERROR "gzip of the man page failed (${gzip_status})")
endif()
