# The report in German, Simplified Chinese and a pseudo-locale (issue 20, item 7), on the demo studies cli_report
# made (its fixture): check_report_language.py finds no English outside the catalogues (pseudo-locale) and every
# catalogue translation applied (German, Chinese). Then a language the build has no catalogue for is refused.
#   cmake -DCLI=... -DWORK=... -DDEMO=<cli_report's demo folder> -DPYTHON=... -DLRELEASE=... -DTS_DIR=... -P this
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/pseudo_catalogue.py ${TS_DIR}/vascusim_de.ts ${WORK}/pseudo.ts
                RESULT_VARIABLE code)
execute_process(COMMAND ${LRELEASE} ${WORK}/pseudo.ts -qm ${WORK}/pseudo.qm RESULT_VARIABLE released OUTPUT_QUIET)
if(NOT code EQUAL 0 OR NOT released EQUAL 0)
    message(FATAL_ERROR "the pseudo-locale catalogue could not be made (${code}, ${released})")
endif()

foreach(case aaa hepatic-tree stenosis)
    set(study ${DEMO}/${case}/${case}.vsim)
    if(NOT EXISTS ${study})
        message(FATAL_ERROR "no demo study ${study}: cli_report makes it (run the two together)")
    endif()
    foreach(language pseudo de zh_CN)
        set(chosen ${language})
        if(language STREQUAL "pseudo")
            set(chosen ${WORK}/pseudo.qm)
        endif()
        run_cli(0 ignored report --study ${study} --out ${WORK}/${case}-${language}.pdf --language ${chosen} --no-validation)
    endforeach()
    execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_report_language.py ${study}
                            ${WORK}/${case}-pseudo.pdf ${WORK}/${case}-de.pdf ${TS_DIR}/vascusim_de.ts
                            ${WORK}/${case}-zh_CN.pdf ${TS_DIR}/vascusim_zh_CN.ts
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "${out}")
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "report languages of ${case}: ${err}")
    endif()
endforeach()

run_cli(1 unknown report --study ${DEMO}/aaa/aaa.vsim --out ${WORK}/x.pdf --language fr)
if(NOT unknown MATCHES "unknown language 'fr'" OR EXISTS ${WORK}/x.pdf)
    message(FATAL_ERROR "an unknown report language must be refused before anything is written:\n${unknown}")
endif()
