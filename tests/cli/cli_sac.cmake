# The AAA sac from the command line (issue 15 item 3) on a patient-like AAA phantom (256 x 256 x 200, 0.7 x 0.7 x 1
# mm, seed 2; its anatomy and scanner are not the estimator's model): import, the aorta from the automatic point,
# the sac (outer contour, thrombus, wall), then the report's AAA section gives the SVS outer diameter (within 2 mm
# of the phantom's truth, computed from its geometry by the same definition) with its definition, against the
# repair thresholds. Without a wall run the section says so. The sac label goes out as a DICOM SEG and comes
# back with the same voxels.
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)
file(REMOVE_RECURSE ${WORK})

run_cli(0 ignored phantom aaa --out ${WORK}/phantom --size 256x256x200 --spacing 0.7,0.7,1.0 --seed 2)
run_cli(0 ignored import ${WORK}/phantom/dicom --study ${WORK}/aaa.vsim)
run_cli(0 segmented segment --study ${WORK}/aaa.vsim --target aorta)
run_cli(0 sac sac --study ${WORK}/aaa.vsim)
message(STATUS "${sac}")
if(NOT sac MATCHES "max_outer_diameter_mm [0-9.]+  \\(largest outer-wall to outer-wall caliper")
    message(FATAL_ERROR "sac output:\n${sac}")
endif()
run_cli(0 ignored report --study ${WORK}/aaa.vsim --out ${WORK}/report.pdf --metrics-json ${WORK}/metrics.json
        --sections aaa)
file(READ ${WORK}/metrics.json metrics)
file(READ ${WORK}/phantom/truth.json truth)
string(JSON truth_outer GET "${truth}" measures max_outer_diameter_mm)
string(REGEX MATCH "\"key\": \"max_outer_diameter_mm\"[^}]*\"value\": ([0-9.]+)" found "${metrics}")
set(reported ${CMAKE_MATCH_1})
if(NOT found)
    message(FATAL_ERROR "the report's metrics hold no max_outer_diameter_mm:\n${metrics}")
endif()
execute_process(COMMAND ${PYTHON} -c "import sys; sys.exit(0 if abs(${reported} - ${truth_outer}) <= 2.0 else 1)"
                RESULT_VARIABLE off)
message(STATUS "report: maximum outer diameter ${reported} mm, truth ${truth_outer} mm")
if(NOT off EQUAL 0)
    message(FATAL_ERROR "the report's outer diameter ${reported} mm is over 2 mm from the truth ${truth_outer} mm")
endif()
execute_process(COMMAND pdftotext -layout ${WORK}/report.pdf - OUTPUT_VARIABLE text)
string(REGEX REPLACE "[ \n]+" " " text "${text}")
if(NOT text MATCHES "Maximum diameter, outer wall to outer wall \\(SVS\\)" OR NOT text MATCHES "Definitions\\."
   OR NOT text MATCHES "repair thresholds" OR NOT text MATCHES "wall-stress run was not made")
    message(FATAL_ERROR "the report's AAA section:\n${text}")
endif()

# The sac label as a DICOM SEG (lumen, thrombus and wall as three segments), imported back: the same voxels as the
# label's own NRRD file gives; an existing output file is not overwritten without --overwrite.
run_cli(0 exported export-label --study ${WORK}/aaa.vsim --out ${WORK}/sac-seg.dcm)
run_cli(1 again export-label --study ${WORK}/aaa.vsim --out ${WORK}/sac-seg.dcm)
# It names the CT it was made on: the Referenced Series Sequence holds the imported series' UID (dcmdump, where found).
if(DCMDUMP)
    execute_process(COMMAND ${DCMDUMP} +P 0008,1115 +P 0020,000e ${WORK}/sac-seg.dcm OUTPUT_VARIABLE dumped)
    run_cli(0 info info ${WORK}/aaa.vsim)
    string(JSON ct_series GET "${info}" artifacts 0 attributes series_instance_uid)
    if(NOT dumped MATCHES "ReferencedSeriesSequence" OR NOT dumped MATCHES "\\[${ct_series}\\] #[^\n]*SeriesInstanceUID")
        message(FATAL_ERROR "the SEG does not reference the CT series ${ct_series}:\n${dumped}")
    endif()
endif()
run_cli(0 fromseg import ${WORK}/sac-seg.dcm --study ${WORK}/aaa.vsim --as-label)
run_cli(0 fromnrrd import ${WORK}/aaa.vsim/labels/label-3.nrrd --study ${WORK}/aaa.vsim --as-label)
string(REGEX MATCH "([0-9]+) labelled voxels" ignored "${fromseg}")
set(seg_voxels ${CMAKE_MATCH_1})
string(REGEX MATCH "([0-9]+) labelled voxels" ignored "${fromnrrd}")
set(nrrd_voxels ${CMAKE_MATCH_1})
message(STATUS "DICOM SEG round trip: ${seg_voxels} voxels (the label's NRRD: ${nrrd_voxels})")
if(NOT seg_voxels OR NOT seg_voxels EQUAL nrrd_voxels OR NOT again MATCHES "overwrite")
    message(FATAL_ERROR "DICOM SEG round trip:\n${exported}\n${fromseg}\n${fromnrrd}\n${again}")
endif()
# Value for value (lumen 1, thrombus 4, wall 5), not only the same voxels: the two imported labels' files.
string(REGEX MATCH "as (label-[0-9]+)" ignored "${fromseg}")
set(seg_id ${CMAKE_MATCH_1})
string(REGEX MATCH "as (label-[0-9]+)" ignored "${fromnrrd}")
set(nrrd_id ${CMAKE_MATCH_1})
execute_process(COMMAND ${PYTHON} -c "
import gzip, sys
def body(path):
    data = open(path, 'rb').read()
    header, payload = data.split(b'\\n\\n', 1)
    return gzip.decompress(payload) if b'gzip' in header else payload
a, b = body(sys.argv[1]), body(sys.argv[2])
print(sorted(set(a)), sorted(set(b)))
sys.exit(0 if a == b else 1)" ${WORK}/aaa.vsim/labels/${seg_id}.nrrd ${WORK}/aaa.vsim/labels/${nrrd_id}.nrrd
    RESULT_VARIABLE differ OUTPUT_VARIABLE values)
message(STATUS "label values, SEG and NRRD imports: ${values}")
if(NOT differ EQUAL 0)
    message(FATAL_ERROR "the SEG round trip changed label values: ${values}")
endif()

# Issue 16: the wall-stress figures inside the sac. The wall from the aorta's lumen with the sac's thrombus as its
# own layer (mesh wall --thrombus), the quadratic hyperelastic physiological run (wall_model 1: Raghavan-Vorp wall,
# Wang thrombus, Newton equilibrium): the sac's 99th percentile and nodal maximum of the wall's von Mises stress
# with their place (along the centerline below the lowest renal artery, clock position) lie in the sac's z range
# (give or take an element edge, 3 mm: the nodal maximum sits on a node of a sac element) and do not exceed the whole wall's element maximum; the strength in the sac comes from its own thrombus and outer
# diameter; the report prints them, and the whole-wall maximum as stress only. The linear model refuses the wall
# with a thrombus layer.
string(REGEX MATCH "as (label-[0-9]+)" ignored "${segmented}")
set(lumen_id ${CMAKE_MATCH_1})
string(REGEX MATCH "sac_top_z_mm ([-0-9.]+)" ignored "${sac}")
set(sac_top ${CMAKE_MATCH_1})
string(REGEX MATCH "sac_bottom_z_mm ([-0-9.]+)" ignored "${sac}")
set(sac_bottom ${CMAKE_MATCH_1})
run_cli(0 ignored skeleton --study ${WORK}/aaa.vsim --label ${lumen_id})
run_cli(0 ignored centerline --study ${WORK}/aaa.vsim)
run_cli(0 wall mesh wall --study ${WORK}/aaa.vsim --target-vertices 3000 --thrombus)
string(JSON wall_label GET "${wall}" lumen_label)
if(NOT wall_label STREQUAL lumen_id) # not the newest label (an imported copy of the sac label above)
    message(FATAL_ERROR "mesh wall without --label must take the lumen the centerlines came from (${lumen_id}), took ${wall_label}")
endif()
string(JSON thrombus_elements GET "${wall}" thrombus_elements)
string(JSON max_thrombus GET "${wall}" max_thrombus_mm)
# Issue 16: no element under 10 degrees, the iliac crotch and the thick thrombus's tall prisms included.
string(JSON min_dihedral GET "${wall}" min_dihedral_deg)
if(min_dihedral LESS 10)
    message(FATAL_ERROR "the wall's smallest dihedral angle is ${min_dihedral} deg (10 at least):\n${wall}")
endif()
run_cli(1 linear simulate fem --study ${WORK}/aaa.vsim --protocol physiological --param wall_model=0 --param female=0
        --param family_history=0)
if(NOT linear MATCHES "thrombus layer" OR thrombus_elements LESS 1000)
    message(FATAL_ERROR "the thrombus layer (${thrombus_elements} elements, thickest ${max_thrombus} mm) and the linear "
                        "model's refusal:
${wall}
${linear}")
endif()
run_cli(0 run simulate fem --study ${WORK}/aaa.vsim --protocol physiological --param female=0 --param family_history=0)
foreach(key sac_pws_p99_kpa sac_pws_nodal_max_kpa sac_pws_z_mm sac_pws_along_centerline_mm sac_pws_clock_h
        sac_pwri_p99 peak_von_mises_kpa run_force_residual sac_elements strength_from_sac_elements element_order
        equilibrium_updates thrombus_elements wall_clock_s)
    string(JSON ${key} GET "${run}" metrics ${key})
endforeach()
message(STATUS "sac (z ${sac_bottom}..${sac_top} mm): PWS P99 ${sac_pws_p99_kpa} kPa, nodal max ${sac_pws_nodal_max_kpa} kPa "
               "at z ${sac_pws_z_mm} mm, ${sac_pws_along_centerline_mm} mm along the centerline, ${sac_pws_clock_h} h; "
               "PWRI P99 ${sac_pwri_p99} (strength from the sac's own thrombus and outer diameter in ${strength_from_sac_elements} "
               "of ${sac_elements} sac elements); whole-wall element max ${peak_von_mises_kpa} kPa; force residual "
               "${run_force_residual} after ${equilibrium_updates} Newton updates; ${thrombus_elements} thrombus elements "
               "(thickest ${max_thrombus} mm), element order ${element_order}, ${wall_clock_s} s")
execute_process(COMMAND ${PYTHON} -c "import sys; sys.exit(0 if (${sac_bottom} - 3 <= ${sac_pws_z_mm} <= ${sac_top} + 3
    and 0 < ${sac_pws_p99_kpa} <= ${sac_pws_nodal_max_kpa} * 1.5 and ${sac_pws_p99_kpa} <= ${peak_von_mises_kpa}
    and 0 < ${sac_pws_clock_h} <= 12 and ${sac_pws_along_centerline_mm} > 0 and ${run_force_residual} <= 1e-6
    and ${strength_from_sac_elements} >= 0.9 * ${sac_elements} and ${element_order} == 2
    and ${thrombus_elements} > 1000) else 1)"
    RESULT_VARIABLE wrong)
if(NOT wrong EQUAL 0)
    message(FATAL_ERROR "the sac's wall-stress figures:\n${run}")
endif()
run_cli(0 ignored report --study ${WORK}/aaa.vsim --out ${WORK}/stress.pdf --sections aaa --no-validation)
execute_process(COMMAND pdftotext ${WORK}/stress.pdf - OUTPUT_VARIABLE text)
string(REGEX REPLACE "[ \n]+" " " text "${text}")
if(NOT text MATCHES "Peak wall stress in the sac \\(von Mises, 99th percentile of its elements\\)"
   OR NOT text MATCHES "Highest element stress on the whole wall" OR NOT text MATCHES "inside the aneurysm sac only")
    message(FATAL_ERROR "the report's sac wall-stress rows:\n${text}")
endif()
