# The clinical report on the demo studies (issue 7): `vascusim-cli demo` runs the aaa, hepatic-tree and stenosis
# phantoms through the pipeline at full size and writes each study's report; check_report.py reads them as a user
# would (pdftotext, pdftoppm, dcmdump). Then an anonymized report, Letter paper, and bad input refused.
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

run_cli(0 demo demo --out ${WORK}/demo)
foreach(case aaa hepatic-tree stenosis)
    set(folder ${WORK}/demo/${case})
    set(extra --figures 0)
    if(case STREQUAL "aaa")
        set(extra --figures 1 --run-metrics ${folder}/wall-run/metrics.json)
    endif()
    if(case STREQUAL "hepatic-tree")
        set(extra --figures 1 --run-metrics ${folder}/network-run/metrics.json)
        run_cli(0 anonymous report --study ${folder}/${case}.vsim --out ${WORK}/anonymous.pdf --dicom-pdf ${WORK}/anonymous.dcm
                --anonymize --page letter --no-validation)
        list(APPEND extra --anonymized ${WORK}/anonymous.pdf ${WORK}/anonymous.dcm)
    endif()
    execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_report.py ${folder} ${folder}/${case}.vsim ${extra}
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    message(STATUS "${out}")
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "report of ${case}: ${err}")
    endif()
endforeach()

# Issue 14: the parameter table lists what the physiological run used (no ramp or tearing settings of the thesis
# protocol, no time_step_ms, no raw keys), blood pressure in mmHg with kPa beside it, and an unconverged run is
# marked next to its figures and in the run's summary.
execute_process(COMMAND pdftotext ${WORK}/demo/aaa/report.pdf - OUTPUT_VARIABLE aaa_text RESULT_VARIABLE code)
string(REGEX REPLACE "[ \n]+" " " aaa_text "${aaa_text}")
foreach(unused "Ramp start" "Ramp end" "Ramp steps" "Tear strength" "Fracture entropy end" "Loaded length" "Time step "
        "Settling time step" "Load path time" "pressure_mmhg" "settle_time_s" "young_modulus_mpa" "cg_max_iterations")
    string(FIND "${aaa_text}" "${unused}" at)
    if(NOT at EQUAL -1)
        message(FATAL_ERROR "the physiological run's parameter table shows '${unused}', which it did not use or is a raw key")
    endif()
endforeach()
# The demo runs the default, quadratic wall (wall_model 1): its own settings, not the linear path's.
if(NOT aaa_text MATCHES "Blood pressure 120 mmHg \\(16\\.0 kPa\\)" OR NOT aaa_text MATCHES "Wall Poisson's ratio 0\\.49")
    message(FATAL_ERROR "the parameter table must give the blood pressure in mmHg with kPa and the quadratic wall's settings:\n${aaa_text}")
endif()
file(READ ${WORK}/demo/aaa/wall-run/metrics.json wall_run)
string(JSON converged GET "${wall_run}" run_status converged)
if(NOT converged AND NOT aaa_text MATCHES "Wall stress at blood pressure \\(physiological protocol\\) - NOT CONVERGED")
    message(FATAL_ERROR "the demo wall run did not converge and the AAA table does not say so")
endif()
if(NOT aaa_text MATCHES "Convergence converged, force residual [0-9.]+e-[0-9]+ \\(tolerance 1\\.0e-06\\)")
    message(FATAL_ERROR "the run summary must state the convergence and the equilibrium's force residual (issue 16)")
endif()
# The validation cases ran with other solver settings than the run: the report says which (the quadratic wall's
# GMRES solves at most 200 iterations each, the cases' PCG 20000).
if(NOT aaa_text MATCHES "What differs from the reported run: the run's solves stopped at 200 iterations, the cases' at 20000")
    message(FATAL_ERROR "the AAA report must say how its validation differs from the wall run")
endif()
execute_process(COMMAND pdftotext ${WORK}/demo/hepatic-tree/report.pdf - OUTPUT_VARIABLE hepatic_text)
string(REGEX REPLACE "[ \n]+" " " hepatic_text "${hepatic_text}")
if(NOT hepatic_text MATCHES "That is the configuration of the reported run")
    message(FATAL_ERROR "the drug report must say that its validation ran in the run's configuration")
endif()

# The thesis tearing protocol on the demo AAA, then its report again: the tearing figures equal the run's.
set(tear ${WORK}/aaa-tear)
run_cli(0 ignored simulate fem --study ${WORK}/demo/aaa/aaa.vsim --protocol thesis-rupture --param ramp_steps=40
        --param tear_strength_mpa=5 --out ${tear}/run)
run_cli(0 ignored report --study ${WORK}/demo/aaa/aaa.vsim --out ${tear}/report.pdf --dicom-pdf ${tear}/report.dcm
        --metrics-json ${tear}/metrics.json --metrics-csv ${tear}/metrics.csv --sections aaa)
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_report.py ${tear} ${WORK}/demo/aaa/aaa.vsim --figures 1
                --run-metrics ${tear}/run/metrics.json --keys tear_onset_pressure_mpa,torn_elements,fracture_entropy,final_pressure_kpa
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "report with the tearing protocol: ${err}")
endif()

# The sac needs the aorta's outer edge against fat: the analytic demo AAA (uniform tissue) has none and is refused
# with the reason; its AAA report then gives lumen diameters and says so.
run_cli(1 refused sac --study ${WORK}/demo/aaa/aaa.vsim)
if(NOT refused MATCHES "outer wall could not be traced")
    message(FATAL_ERROR "sac on the analytic demo: ${refused}")
endif()
file(READ ${tear}/metrics.json tear_metrics)
if(NOT tear_metrics MATCHES "measured_max_diameter_mm" OR tear_metrics MATCHES "max_outer_diameter_mm")
    message(FATAL_ERROR "the AAA report without a sac must give the lumen diameter only:\n${tear_metrics}")
endif()

# Each report is kept in its study too (reports/<id>.pdf).
foreach(case aaa hepatic-tree stenosis)
    file(GLOB kept ${WORK}/demo/${case}/${case}.vsim/reports/*.pdf)
    if(NOT kept)
        message(FATAL_ERROR "the ${case} study does not keep its report")
    endif()
endforeach()

# Which sections each study got, and what it says was not run.
file(READ ${WORK}/demo/aaa/metrics.json aaa)
file(READ ${WORK}/demo/stenosis/metrics.json stenosis)
# Issue 16: the analytic demo AAA has no sac (no fat around the aorta), so its report gives stress only (no rupture
# index, whose regression holds for the sac).
if(NOT aaa MATCHES "\"section\": \"aaa\"" OR NOT aaa MATCHES "peak_von_mises_kpa" OR aaa MATCHES "rupture_index"
   OR NOT aaa_text MATCHES "No sac was measured \\(vascusim-cli sac\\), so no rupture index is given"
   OR NOT stenosis MATCHES "diameter_stenosis_percent"
   OR NOT stenosis MATCHES "no wall-mechanics run")
    message(FATAL_ERROR "demo reports: the AAA or stenosis section is missing\n${aaa}\n${stenosis}")
endif()
execute_process(COMMAND pdfinfo ${WORK}/anonymous.pdf OUTPUT_VARIABLE info)
if(NOT info MATCHES "612 x 792")
    message(FATAL_ERROR "--page letter did not give Letter pages:\n${info}")
endif()

run_cli(1 section report --study ${WORK}/demo/aaa/aaa.vsim --out ${WORK}/x.pdf --sections aaa,bogus)
run_cli(1 page report --study ${WORK}/demo/aaa/aaa.vsim --out ${WORK}/x.pdf --page a5)
run_cli(1 nostudy report --study ${WORK}/missing.vsim --out ${WORK}/x.pdf)
if(NOT section MATCHES "unknown report section 'bogus'" OR NOT page MATCHES "unknown page size 'a5'" OR NOT nostudy MATCHES "study")
    message(FATAL_ERROR "bad report input must be refused with a message:\n${section}\n${page}\n${nostudy}")
endif()
