# `vascusim-cli validate sph-dambreak` (SPHERIC benchmark 2 against MARIN's probes) as a user runs it.

# Without a GPU the default backend refuses it, saying how to run it on the CPU; with one it runs (a GPU machine).
execute_process(COMMAND ${CLI} validate sph-dambreak --until 0.02 RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT (code EQUAL 1 AND err MATCHES "needs a GPU.*--backend cpu") AND NOT out MATCHES "\"sph-dambreak\"")
    message(FATAL_ERROR "validate sph-dambreak without a GPU: exit ${code}\n${out}\n${err}")
endif()

# Its options belong to it alone; an end past the record is refused before anything runs.
execute_process(COMMAND ${CLI} validate sph-kernel --particles 5000 RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 2 OR NOT err MATCHES "--particles applies to sph-dambreak only")
    message(FATAL_ERROR "--particles with another case: exit ${code}\n${err}")
endif()
execute_process(COMMAND ${CLI} validate sph-dambreak --backend cpu --until 2 RESULT_VARIABLE code ERROR_VARIABLE err)
if(NOT code EQUAL 1 OR NOT err MATCHES "within the experiment's record \\(0 to 1.02 s\\)")
    message(FATAL_ERROR "--until past the record: exit ${code}\n${err}")
endif()

# A coarse run (about 25,000 particles, 54 mm) over the record's first 0.3 s on the CPU: the column's fall at H4 and
# the front's arrival at H3 (0.211 s measured) within the tolerance, the dry probes dry; the run does not cover the
# record, so it fails on that figure alone and exits 1.
execute_process(COMMAND ${CLI} validate sph-dambreak --backend cpu --particles 20000 --until 0.3
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 1 OR NOT err MATCHES "out of tolerance: sph-dambreak: simulated time \\(the whole record\\)\n?$")
    message(FATAL_ERROR "the short CPU run must fail on the record alone: exit ${code}\n${out}\n${err}")
endif()
string(JSON count LENGTH "${out}" figures)
math(EXPR last "${count} - 1")
set(found 0)
foreach(k RANGE ${last})
    string(JSON name GET "${out}" figures ${k} name)
    string(JSON measured GET "${out}" figures ${k} measured)
    string(JSON passed GET "${out}" figures ${k} passed)
    message(STATUS "${name}: ${measured} (passed ${passed})")
    if(name MATCHES "^(H4 .*RMS|H3 front arrival)")
        math(EXPR found "${found} + 1")
    endif()
    if(NOT name MATCHES "^simulated time" AND NOT passed)
        message(FATAL_ERROR "${name} out of tolerance:\n${out}")
    endif()
endforeach()
if(NOT found EQUAL 2 OR NOT out MATCHES "on the CPU \\(double precision\\)")
    message(FATAL_ERROR "the H4 RMS and H3 arrival figures, and the backend, must be printed:\n${out}")
endif()
