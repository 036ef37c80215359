# Thesis scenario (a), the needle injection (issue 18; app/InjectionPipeline.h), as a user runs it: a short patient-like
# stenosis phantom (an 8 mm artery with a 30 % stenosis, 24 mm long) through segment, skeleton and centerline, then
# `simulate injection` at a coarse spacing (a 2 mm bore, 0.8 mm particles, the thesis's 300 particles a second) on
# the CPU for the stream's first 40 ms. Checked against the free fall the set-up implies (gravity along the vessel;
# the solver knows nothing of it): the stream's head at 40 ms lies between 0.8 of 1/2 g t^2 and 1/2 g t^2 + the
# needle's peak speed x t + two spacings below the needle, and nothing has reached the box yet (its top lies farther
# than a free fall reaches by then). Also: the vessel empty at the start, the mass ledger balanced to rounding, the
# Run kept and its frames written. Bad input: a bore under two spacings, a rate in another unit.
# The full scenario (the blood landing in the box) runs on the GPU: tests/bench/RESULTS.md.
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

set(study ${WORK}/injection.vsim)
run_cli(0 ignored phantom stenosis --out ${WORK}/ph --size 64x64x24 --spacing 0.8,0.8,1.0 --vessel-diameter 8
        --stenosis 30 --seed 1)
run_cli(0 ignored import ${WORK}/ph/dicom --study ${study})
run_cli(0 ignored segment --study ${study})
run_cli(0 ignored skeleton --study ${study})
run_cli(0 ignored centerline --study ${study})

# Refusals first: they cost no run and leave the study as it was.
run_cli(1 refused simulate injection --study ${study} --needle-bore 1mm --spacing 0.8mm --backend cpu)
if(NOT refused MATCHES "at least two particles")
    message(FATAL_ERROR "a bore under two spacings was not refused with its reason:\n${refused}")
endif()
run_cli(2 refused simulate injection --study ${study} --rate 300ml/min --backend cpu)

run_cli(0 run simulate injection --study ${study} --needle-bore 2mm --spacing 0.8mm --box-depth 5mm --box-margin 4mm
        --param cfl=0.2 --until 0.04s --frames 4 --backend cpu --out ${WORK}/run)
string(JSON stopped GET "${run}" run_status stopped_by)
string(JSON run_id GET "${run}" run_artifact)
string(JSON rows LENGTH "${run}" fill rows)
string(JSON first_in_vessel GET "${run}" fill rows 0 in_vessel_ml)
math(EXPR last "${rows} - 1")
string(JSON time GET "${run}" fill rows ${last} time_s)
string(JSON front GET "${run}" fill rows ${last} front_mm)
string(JSON collected GET "${run}" fill rows ${last} collected_ml)
string(JSON in_vessel GET "${run}" fill rows ${last} in_vessel_ml)
string(JSON residual GET "${run}" mass_balance residual_kg)
string(JSON injected GET "${run}" mass_balance injected_kg)
string(JSON length GET "${run}" vessel_length_mm)
string(JSON spacing GET "${run}" parameters spacing_mm)
string(JSON flow_ml_s GET "${run}" needle flow_rate_ml_s)
if(NOT stopped STREQUAL "end" OR NOT run_id MATCHES "^run-" OR NOT EXISTS ${WORK}/run/series.pvd
   OR NOT first_in_vessel EQUAL 0 OR NOT in_vessel GREATER 0)
    message(FATAL_ERROR "simulate injection: stopped by '${stopped}', run '${run_id}', ${first_in_vessel} ml in the "
            "vessel at the start, ${in_vessel} ml at the end\n${run}")
endif()
execute_process(COMMAND ${PYTHON} -c "
import math, sys
residual, injected, t, front, collected, length, spacing, flow = map(float, sys.argv[1:])
g = 9.81
peak = 2.0 * 1e-6 * flow / (math.pi * 1e-6)  # m/s: parabolic through the 2 mm bore (radius 1 mm)
fall = 0.5 * g * t * t * 1e3                  # mm
low, high = 0.8 * fall, fall + 1e3 * peak * t + 2.0 * spacing
box_reachable = 0.5 * g * t * t * 1e3 + 1e3 * peak * t >= length + 2.0 * spacing
print('at t = %.4f s the head is %.2f mm below the needle (free fall %.2f mm: %.2f-%.2f); %.4g ml collected; '
      'ledger residual %.3g of %.3g kg' % (t, front, fall, low, high, collected, residual, injected))
ok = abs(residual) <= 1e-12 * injected and low <= front <= high and (collected == 0.0 or box_reachable)
sys.exit(0 if ok else 1)"
    ${residual} ${injected} ${time} ${front} ${collected} ${length} ${spacing} ${flow_ml_s}
    RESULT_VARIABLE physical OUTPUT_VARIABLE figures)
message(STATUS "${figures}")
if(NOT physical EQUAL 0)
    message(FATAL_ERROR "simulate injection: ${figures}\n${run}")
endif()
