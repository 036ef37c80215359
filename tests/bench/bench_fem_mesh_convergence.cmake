# Mesh convergence of the wall stress in the sac (issue 16 item 5), label bench: the patient-like AAA phantom of
# cli_sac (256 x 256 x 200, 0.7 x 0.7 x 1 mm, seed 2) through the command line (import, aorta, sac, skeleton,
# centerlines), its wall meshed at three refinements (lumen surface target vertices VERTICES, default
# 1500;3000;6000; the wall one prism layer of 1.5 mm throughout, no thrombus layer), the quadratic physiological
# analysis (wall_model 1: quadratic tets, Raghavan-Vorp 2000, 120 mmHg, force residual 1e-6) on each: the sac's 99th-percentile and nodal-maximum von
# Mises stress, their change between refinements (the issue asks <= 5 % between the two finest), elements, smallest
# dihedral angle, Newton updates and time. Prints one JSON object; exit 1 when a run does not converge.
#   cmake -DCLI=<vascusim-cli> -DWORK=<folder> [-DVERTICES="1500;3000;6000"] -P bench_fem_mesh_convergence.cmake
include(${CMAKE_CURRENT_LIST_DIR}/../cli/RunCli.cmake)
if(NOT VERTICES)
    set(VERTICES 1500 3000 6000)
endif()
run_cli(0 ignored phantom aaa --out ${WORK}/phantom --size 256x256x200 --spacing 0.7,0.7,1.0 --seed 2)
run_cli(0 ignored import ${WORK}/phantom/dicom --study ${WORK}/aaa.vsim)
run_cli(0 segmented segment --study ${WORK}/aaa.vsim --target aorta)
string(REGEX MATCH "as (label-[0-9]+)" ignored "${segmented}")
set(lumen_id ${CMAKE_MATCH_1})
run_cli(0 ignored sac --study ${WORK}/aaa.vsim)
run_cli(0 ignored skeleton --study ${WORK}/aaa.vsim --label ${lumen_id})
run_cli(0 ignored centerline --study ${WORK}/aaa.vsim)
set(rows "")
set(previous_p99 "")
foreach(vertices ${VERTICES})
    run_cli(0 wall mesh wall --study ${WORK}/aaa.vsim --target-vertices ${vertices})
    string(JSON mesh_id GET "${wall}" artifact)
    string(JSON tets GET "${wall}" tets)
    string(JSON dihedral GET "${wall}" min_dihedral_deg)
    string(TIMESTAMP start "%s")
    run_cli(0 run simulate fem --study ${WORK}/aaa.vsim --protocol physiological --mesh ${mesh_id} --param wall_model=1)
    string(TIMESTAMP stop "%s")
    math(EXPR seconds "${stop} - ${start}")
    foreach(key sac_pws_p99_kpa sac_pws_nodal_max_kpa run_force_residual equilibrium_updates quadratic_nodes sac_elements
            run_converged)
        string(JSON ${key} GET "${run}" metrics ${key})
    endforeach()
    if(NOT run_converged EQUAL 1)
        message(FATAL_ERROR "the run at ${vertices} vertices did not converge:\n${run}")
    endif()
    if(rows)
        string(APPEND rows ", ")
    endif()
    string(APPEND rows "{\"target_vertices\": ${vertices}, \"tets\": ${tets}, \"quadratic_nodes\": ${quadratic_nodes}, "
                       "\"min_dihedral_deg\": ${dihedral}, \"sac_elements\": ${sac_elements}, "
                       "\"sac_pws_p99_kpa\": ${sac_pws_p99_kpa}, \"sac_pws_nodal_max_kpa\": ${sac_pws_nodal_max_kpa}, "
                       "\"newton_updates\": ${equilibrium_updates}, \"force_residual\": ${run_force_residual}, "
                       "\"seconds\": ${seconds}}")
    message(STATUS "${vertices} vertices: ${tets} tets, P99 ${sac_pws_p99_kpa} kPa, nodal max ${sac_pws_nodal_max_kpa} kPa, ${seconds} s")
endforeach()
message("{\"bench\": \"fem_mesh_convergence\", \"refinements\": [${rows}]}")
