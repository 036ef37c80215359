# Blood flow (issue 18) as a user runs it: a small analytic stenosis phantom (a 6 mm artery with a 50 % diameter
# stenosis) through segment, skeleton and centerline, then `simulate sph` at a coarse spacing for 20 ms after a 5 ms
# ramp (the plumbing: the inlet and the outlet at the vessel's ends, the outlet's gauge pressure as the reference,
# the particle frames written to --out and kept as a Run in the study, the mass ledger balanced, the wall loads
# averaged over 12.5-20 ms on the lumen surface's vertices and kept as a "Wall loads (SPH)" surface, and in the
# report; the stenosis numerics chosen); the wall's lumen loaded by that wall pressure (one-way coupling). Bad input: an unknown unit, a profile, the CUDA backend without a device, a folder that is not VascuSim's.
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

set(study ${WORK}/flow.vsim)
run_cli(0 ignored phantom stenosis --style analytic --out ${WORK}/ph --size 96x96x64 --spacing 0.8,0.8,1.0)
run_cli(0 ignored import ${WORK}/ph/dicom --study ${study})
run_cli(0 ignored segment --study ${study})
run_cli(0 ignored skeleton --study ${study})
run_cli(0 ignored centerline --study ${study})

run_cli(0 flow simulate sph --study ${study} --inlet 0.03m/s --outlet 50mmHg --spacing 1.0mm --ramp 0.005s --until 0.02s
        --frames 4 --out ${WORK}/run)
string(JSON stopped GET "${flow}" run_status stopped_by)
string(JSON boundaries LENGTH "${flow}" boundaries)
string(JSON inlet GET "${flow}" boundaries 0 prescribed)
string(JSON frames GET "${flow}" frames)
string(JSON run_id GET "${flow}" run_artifact)
string(JSON inflow GET "${flow}" metrics inflow_kg)
string(JSON warnings GET "${flow}" warnings)
string(JSON wall_id GET "${flow}" wall_loads_artifact)
string(JSON wall_sampled GET "${flow}" wall_loads sampled_vertices)
string(JSON wall_vertices GET "${flow}" wall_loads vertices)
string(JSON wall_tawss GET "${flow}" wall_loads largest_tawss_pa value)
string(JSON backend GET "${flow}" backend)
if(NOT stopped STREQUAL "end" OR NOT boundaries EQUAL 2 OR NOT inlet STREQUAL "flow rate" OR frames LESS 4
   OR NOT run_id MATCHES "^run-" OR NOT EXISTS ${WORK}/run/series.pvd OR NOT EXISTS ${WORK}/run/metrics.json
   OR NOT wall_id MATCHES "^surface-" OR wall_sampled LESS 100 OR NOT wall_tawss GREATER 0
   OR NOT backend MATCHES "^(cpu \\(double|cuda \\(single)")
    message(FATAL_ERROR "simulate sph: stopped by '${stopped}', ${boundaries} boundaries, ${frames} frames, run '${run_id}'\n${flow}")
endif()
# The largest TAWSS lies in the stenosis (the phantom's narrowing: 20 mm long), not at an open end, where the kernels
# reach the buffers' prescribed particles (before 2026-11-28: 5.8 Pa at the inlet, 29 mm from the throat).
file(READ ${WORK}/ph/truth.json truth)
foreach(axis x y z)
    string(JSON throat_${axis} GET "${truth}" measures stenosis_centre_${axis}_mm)
endforeach()
string(JSON peak_at GET "${flow}" wall_loads largest_tawss_pa at_mm)
string(JSON peak_x GET "${peak_at}" 0)
string(JSON peak_y GET "${peak_at}" 1)
string(JSON peak_z GET "${peak_at}" 2)
execute_process(COMMAND ${PYTHON} -c "import sys, math; a = list(map(float, sys.argv[1:])); sys.exit(0 if math.dist(a[:3], a[3:]) <= 10.0 else 1)"
                ${peak_x} ${peak_y} ${peak_z} ${throat_x} ${throat_y} ${throat_z} RESULT_VARIABLE in_throat)
if(NOT in_throat EQUAL 0)
    message(FATAL_ERROR "the largest TAWSS (${wall_tawss} Pa) lies at ${peak_at} mm, over 10 mm from the stenosis's "
            "centre (${throat_x}, ${throat_y}, ${throat_z} mm)")
endif()
# The stenosis numerics the pipeline chose (SphSolver.h: kStenosisShifting, stenosisCfl): particle shifting A 2 with
# its floor at the throat's mean speed (the inlet's 0.03 m/s times the truth's area ratio; the label's voxels and the
# inlet's centerline radius move it: within a factor 0.6-1.6), the continuity density relaxed over 20 h / c0, and the
# Courant number 0.1 x 48.457 / the throat's Re (rho U d / mu of its mean flow; the truth's about 110 here), within
# the same factor. (At 0.1 m/s, throat Re about 390, that Courant number takes 8x the steps: 8,796 in 348 s.)
string(JSON shifting GET "${flow}" parameters particle_shifting)
string(JSON shift_floor GET "${flow}" parameters shifting_speed_m_s)
string(JSON relaxation GET "${flow}" parameters density_relaxation_s)
string(JSON sound_speed GET "${flow}" parameters sound_speed_m_s)
string(JSON courant GET "${flow}" parameters cfl)
string(JSON reference_d GET "${truth}" measures reference_diameter_mm)
string(JSON minimal_d GET "${truth}" measures minimal_diameter_mm)
execute_process(COMMAND ${PYTHON} -c "import sys; a, f, t, c, n, D, d = map(float, sys.argv[1:]); throat = 0.03 * (D / d) ** 2; re = 1060 * throat * 1e-3 * d / 3.5e-3; sys.exit(0 if a == 2 and 0.6 <= f / throat <= 1.6 and abs(t - 20 * 2e-3 / c) <= 1e-9 * t and 0.6 <= n / (0.1 * 48.457 / re) <= 1.6 else 1)"
                ${shifting} ${shift_floor} ${relaxation} ${sound_speed} ${courant} ${reference_d} ${minimal_d} RESULT_VARIABLE chosen)
if(NOT chosen EQUAL 0)
    message(FATAL_ERROR "simulate sph's stenosis numerics: shifting ${shifting}, its floor ${shift_floor} m/s (truth "
            "diameters ${reference_d} / ${minimal_d} mm at 0.03 m/s), relaxation ${relaxation} s at c0 ${sound_speed} m/s, "
            "Courant number ${courant}")
endif()
# The outlets' 50 mmHg (6,666 Pa) is the reference pressure: reported on the pressures, left out of the equation of
# state (as an absolute level in it the buffers compressed the fluid: the run stopped at the density guard at 0.13 ms).
string(JSON outlet_pa GET "${flow}" metrics outlet_0_pressure_pa)
string(JSON density_variation GET "${flow}" metrics largest_density_variation)
string(JSON downstream_pa GET "${flow}" stenosis downstream_pressure_pa value)
string(JSON settling GET "${flow}" settling_s) # the vessel's resistance x compliance, s
if(outlet_pa LESS 6665 OR outlet_pa GREATER 6667 OR density_variation GREATER 0.01 OR downstream_pa LESS 6666
   OR NOT settling GREATER 0)
    message(FATAL_ERROR "simulate sph --outlet 50mmHg: outlet ${outlet_pa} Pa, density variation ${density_variation}, "
            "downstream section ${downstream_pa} Pa\n${flow}")
endif()
# The ledger: inflow - outflow - absorbed = the fluid's mass change, to rounding.
string(JSON outflow GET "${flow}" metrics outflow_kg)
string(JSON absorbed GET "${flow}" metrics absorbed_kg)
string(JSON change GET "${flow}" metrics fluid_mass_change_kg)
execute_process(COMMAND ${PYTHON} -c "import sys; i,o,a,c = map(float, sys.argv[1:]); sys.exit(0 if abs(i - o - a - c) <= 1e-9 * max(i, 1e-30) + 1e-18 else 1)"
                ${inflow} ${outflow} ${absorbed} ${change} RESULT_VARIABLE balanced)
if(NOT balanced EQUAL 0)
    message(FATAL_ERROR "simulate sph: the ledger does not balance: in ${inflow}, out ${outflow}, absorbed ${absorbed}, change ${change} kg")
endif()
run_cli(0 info info ${study})
if(NOT info MATCHES "Blood flow \\(SPH\\)" OR NOT info MATCHES "Wall loads \\(SPH\\)"
   OR NOT info MATCHES "sections_along_centerline")
    message(FATAL_ERROR "the study does not list the blood-flow run:\n${info}")
endif()

# The report's stenosis section carries the wall loads beside the velocity figures, and the pressures' level; the
# velocity and pressure along the centerline as plots, the TAWSS on the surface as a picture (rendered: under xvfb).
run_cli(0 ignored report --study ${study} --out ${WORK}/report.pdf)
execute_process(COMMAND pdftotext ${WORK}/report.pdf - OUTPUT_VARIABLE report_text RESULT_VARIABLE code)
string(REPLACE "\n" " " report_text "${report_text}")
if(NOT code EQUAL 0 OR NOT report_text MATCHES "Wall loads on the lumen surface" OR NOT report_text MATCHES "TAWSS"
   OR NOT report_text MATCHES "pressures gauge, the outlets at 50 mmHg"
   OR NOT report_text MATCHES "Velocity along the centerline" OR NOT report_text MATCHES "Mean pressure along the centerline"
   OR NOT report_text MATCHES "Time-averaged wall shear stress \\(TAWSS, Pa\\) on the lumen surface"
   OR report_text MATCHES "not rendered")
    message(FATAL_ERROR "the report does not give the wall loads:\n${report_text}")
endif()

# One-way coupling: the wall's lumen carries 120 mmHg plus the flow's time-averaged wall pressure (relative to its
# outlets). The run names the wall loads among its inputs and says how much of the lumen they reached and what they
# added; every added pressure is >= 0 here (the outlets are the flow's lowest pressure), so the peak von Mises stress
# rises from the uniform run's, and by no more than the largest added share of the pressure (2 % for the mesh).
run_cli(0 ignored mesh wall --study ${study} --target-vertices 800)
set(patient --param female=0 --param family_history=0)
run_cli(0 uniform simulate fem --study ${study} --protocol physiological ${patient})
run_cli(0 coupled simulate fem --study ${study} --protocol physiological ${patient} --param flow_wall_pressure=1)
string(JSON uniform_peak GET "${uniform}" metrics peak_von_mises_kpa)
string(JSON coupled_peak GET "${coupled}" metrics peak_von_mises_kpa)
string(JSON covered GET "${coupled}" metrics flow_pressure_covered_share)
string(JSON added_min GET "${coupled}" metrics flow_pressure_min_pa)
string(JSON added_max GET "${coupled}" metrics flow_pressure_max_pa)
string(JSON coupled_status GET "${coupled}" run_status converged)
string(JSON coupled_run GET "${coupled}" run_artifact)
file(READ ${study}/runs/${coupled_run}/run.json coupled_record)
execute_process(COMMAND ${PYTHON} -c "import sys; u, c, lo, hi, cov = map(float, sys.argv[1:]); p = 120 * 133.322; sys.exit(0 if cov >= 0.9 and lo >= -1 and hi > lo and u < c <= 1.02 * u * (1 + hi / p) else 1)"
                ${uniform_peak} ${coupled_peak} ${added_min} ${added_max} ${covered} RESULT_VARIABLE plausible)
if(NOT plausible EQUAL 0 OR NOT coupled_status OR NOT coupled_record MATCHES "\"flow_wall_loads\": \"${wall_id}\"")
    message(FATAL_ERROR "simulate fem with the flow's wall pressure: peak ${coupled_peak} kPa against ${uniform_peak} "
                        "uniform, ${covered} of the lumen reached, ${added_min}..${added_max} Pa added, converged "
                        "${coupled_status}\n${coupled}")
endif()

# Refusals: exit 2 for usage, 1 for what cannot be done; nothing is added.
run_cli(2 unit simulate sph --study ${study} --inlet 5furlongs)
run_cli(2 profile simulate sph --study ${study} --profile square)
# The GPU backend: refused with the reason where there is no device (this suite's machines); where there is one it
# runs the same case (tests/gpu/tst_gpu_sph checks it against the CPU).
execute_process(COMMAND ${CLI} simulate sph --study ${study} --backend cuda --spacing 1.0mm --until 0.001s --frames 1
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT ((code EQUAL 1 AND err MATCHES "no CUDA device: use --backend cpu or auto|no CUDA backend")
        OR (code EQUAL 0 AND out MATCHES "\"backend\": \"cuda")))
    message(FATAL_ERROR "simulate sph --backend cuda: exit ${code}\n${out}\n${err}")
endif()
file(MAKE_DIRECTORY ${WORK}/stranger)
file(WRITE ${WORK}/stranger/notes.txt "a user's notes")
run_cli(1 refused simulate sph --study ${study} --spacing 1.0mm --until 0.001s --out ${WORK}/stranger)
file(READ ${WORK}/stranger/notes.txt notes)
if(NOT notes STREQUAL "a user's notes")
    message(FATAL_ERROR "simulate sph touched a folder it did not create")
endif()
