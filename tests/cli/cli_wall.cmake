# The wall steps as a user runs them: a small aaa phantom through segment, skeleton and centerline, then
# `mesh wall` (no inverted element, over 1,000 tets), `simulate fem --protocol
# physiological` (a positive peak stress and rupture index below 1, the frame series written), a cloth sheet, a
# .vtu imported as a wall, and bad input (a file that is not .vtu, an unknown protocol, --backend cuda without a GPU,
# an unknown backend) refused.
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

set(study ${WORK}/wall.vsim)
run_cli(0 ignored phantom aaa --out ${WORK}/ph --size 192x192x160 --spacing 1.8,1.8,2.5)
run_cli(0 ignored import ${WORK}/ph/dicom --study ${study})
run_cli(0 ignored segment --study ${study})
run_cli(0 ignored skeleton --study ${study})
run_cli(0 ignored centerline --study ${study})
run_cli(0 wall mesh wall --study ${study} --target-vertices 1500)
string(JSON inverted GET "${wall}" inverted_elements)
string(JSON tets GET "${wall}" tets)
string(JSON wall_id GET "${wall}" artifact)
if(NOT inverted EQUAL 0 OR tets LESS 1000)
    message(FATAL_ERROR "mesh wall: ${inverted} inverted elements, ${tets} tets\n${wall}")
endif()
run_cli(0 run simulate fem --study ${study} --protocol physiological --param settle_time_s=0.3 --out ${WORK}/run)
string(JSON peak GET "${run}" metrics peak_von_mises_kpa)
string(JSON index GET "${run}" metrics peak_rupture_index)
string(JSON stop GET "${run}" stop_reason)
string(JSON backend GET "${run}" backend)
if(NOT peak GREATER 0 OR NOT index LESS 1 OR NOT stop STREQUAL "" OR NOT backend STREQUAL "cpu" OR NOT EXISTS ${WORK}/run/series.pvd
   OR NOT EXISTS ${WORK}/run/frames/frame_0000.vtu OR NOT EXISTS ${WORK}/run/metrics.json)
    message(FATAL_ERROR "simulate fem physiological: peak ${peak} kPa, index ${index}, stop '${stop}'\n${run}")
endif()
run_cli(0 sheet mesh sheet --study ${study} --width 10 --length 20 --cell 1)
run_cli(0 imported mesh import ${study}/meshes/${wall_id}.vtu --study ${study})
run_cli(1 junk mesh import ${WORK}/ph/truth.json --study ${study})
run_cli(1 unknown simulate fem --study ${study} --protocol nothing)
# This test runs where there is no GPU (auto then means the CPU, above); the device tool runs tst_gpu_fem.
run_cli(1 cuda simulate fem --study ${study} --protocol physiological --backend cuda)
run_cli(1 backend simulate fem --study ${study} --protocol physiological --backend quantum)
if(NOT junk MATCHES "error: not a VTK XML" OR NOT unknown MATCHES "unknown protocol"
   OR NOT cuda MATCHES "error: .*CUDA.*use --backend cpu or auto" OR NOT backend MATCHES "unknown backend 'quantum'")
    message(FATAL_ERROR "bad input must be refused with a message:\n${junk}\n${unknown}\n${cuda}\n${backend}")
endif()
