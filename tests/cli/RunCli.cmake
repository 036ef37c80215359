# Shared by the CLI scripts: a fresh work folder, and run_cli(<expected exit code> <output variable> <arguments...>),
# which runs vascusim-cli, fails the test on another exit code and returns stdout and stderr together.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(run_cli expected_code output_var)
    execute_process(COMMAND ${CLI} ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL expected_code)
        message(FATAL_ERROR "vascusim-cli ${ARGN}: exit ${code}, expected ${expected_code}\n${out}\n${err}")
    endif()
    set(${output_var} "${out}${err}" PARENT_SCOPE)
endfunction()
