# The drug-delivery steps as a user runs them on the full-size hepatic-tree phantom (512 x 512 x 400 at 0.7 mm):
# segment, skeleton, centerline, then `simulate network` from the root with the phantom's tumour (Kirchhoff
# balanced, 16 outlets, the control points' two-phase drop near the void fraction, the run files written), the
# tumour as a label (the same share as the sphere), injection by tip pressure and by mass rate, a hand-written
# network file, `validate network`, and bad input refused with a message (a tip off the tree, a void fraction of 1,
# a network with a cycle, outlets without a condition, a rate and a tip pressure together, an unknown rate unit, a
# tip pressure below the outlets'); chemoembolization planning from a named inlet with feeders corrected by hand.
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

set(study ${WORK}/hepatic.vsim)
run_cli(0 ignored phantom hepatic-tree --style analytic --out ${WORK}/ph)
run_cli(0 ignored import ${WORK}/ph/dicom --study ${study})
run_cli(0 ignored segment --study ${study})
run_cli(0 ignored skeleton --study ${study})
run_cli(0 ignored centerline --study ${study})
set(tumour -84.73,-47.75,-261.32,15)
run_cli(0 run simulate network --study ${study} --tip 20,-25,-305 --tumour ${tumour} --out ${WORK}/run)
string(JSON balance GET "${run}" metrics conservation_error)
string(JSON outlets GET "${run}" metrics outlets)
string(JSON fed GET "${run}" metrics tumour_outlets)
string(JSON drop GET "${run}" metrics control_A_drop_percent)
string(JSON best GET "${run}" metrics best_tip_fraction)
foreach(file network.json segments.csv outlets.csv filling.csv metrics.json)
    if(NOT EXISTS ${WORK}/run/${file})
        message(FATAL_ERROR "simulate network did not write ${file}")
    endif()
endforeach()
# Issue 17: the filling over time is in the study as a Run of 101 frames that ParaView opens.
string(JSON run_id GET "${run}" run_artifact)
file(GLOB filling_frames ${study}/runs/${run_id}/frames/frame_*.vtp)
list(LENGTH filling_frames filling_frame_count)
if(NOT EXISTS ${study}/runs/${run_id}/series.pvd OR NOT filling_frame_count EQUAL 101)
    message(FATAL_ERROR "simulate network must keep its filling run (${run_id}: ${filling_frame_count} frames)")
endif()
if(balance GREATER 1e-12 OR NOT outlets EQUAL 16 OR fed LESS 1 OR drop LESS 9 OR drop GREATER 11 OR best LESS 0.2)
    message(FATAL_ERROR "simulate network: balance ${balance}, ${outlets} outlets, ${fed} tumour outlets, drop ${drop} %, "
                        "best tip ${best}\n${run}")
endif()

# An organ grown from a point is no vessel label: the skeleton step without --label keeps to the lumen label.
run_cli(0 organ segment-organ --study ${study} --seed -84.73,-47.75,-261.32 --organ tumour)
run_cli(0 reskeleton skeleton --study ${study})
if(NOT organ MATCHES "grown from 1 point" OR NOT reskeleton MATCHES "^skeleton of label-2 ")
    message(FATAL_ERROR "segment-organ, then skeleton without --label must read the lumen label:\n${organ}\n${reskeleton}")
endif()

# The tumour as a label: the phantom's truth label (its own values, the tumour 2) imported as a label.
run_cli(0 imported import ${WORK}/ph/truth-label.nrrd --study ${study} --as-label)
string(REGEX MATCH "as (label-[0-9]+)" ignored "${imported}")
set(label_id ${CMAKE_MATCH_1})
run_cli(0 bylabel simulate network --study ${study} --tip 20,-25,-305 --tumour-label ${label_id} --tumour-value 2)
string(JSON fed_label GET "${bylabel}" metrics tumour_outlets)
string(JSON share_label GET "${bylabel}" metrics tumour_fraction)
string(JSON share_sphere GET "${run}" metrics tumour_fraction)
if(fed_label LESS 1 OR NOT share_label EQUAL share_sphere)
    message(FATAL_ERROR "the tumour as a label: ${fed_label} outlets, share ${share_label} (sphere ${share_sphere})")
endif()
# Chemoembolization planning with the blood entering at a named vessel and the feeders corrected by hand: the liver
# grown from a point in the tissue, the first branch named the common hepatic artery, a run from there, then the
# same with one feeder found removed and one segment added; the edits need a liver, and an unknown name is refused
# with the names the tree has.
run_cli(0 liver segment-organ --study ${study} --seed 0,0,-300 --organ liver)
string(REGEX MATCH "as (label-[0-9]+)" ignored "${liver}")
set(liver_id ${CMAKE_MATCH_1})
run_cli(0 ignored rename-segment --study ${study} --segment 15 --name "common hepatic artery")
set(tace --study ${study} --tip root --liver-label ${liver_id} --tumour-label ${label_id} --tumour-value 2
    --inlet "Common Hepatic Artery")
run_cli(0 planned simulate network ${tace} --out ${WORK}/tace)
file(STRINGS ${WORK}/tace/feeders.csv found_feeders)
list(GET found_feeders 1 first_feeder)
string(REGEX MATCH "^[0-9]+" removed_feeder "${first_feeder}")
run_cli(0 edited simulate network ${tace} --remove-feeder ${removed_feeder} --add-feeder 0 --out ${WORK}/tace-edited)
foreach(key feeders root_pressure_mmhg)
    string(JSON planned_${key} GET "${planned}" metrics ${key})
endforeach()
string(JSON added GET "${edited}" metrics feeders_added_by_hand)
string(JSON removed GET "${edited}" metrics feeders_removed_by_hand)
string(JSON edited_feeders GET "${edited}" metrics feeders)
string(JSON edited_inlet GET "${edited}" source inlet)
file(READ ${WORK}/tace-edited/feeders.csv edited_csv)
if(planned_feeders LESS 2 OR NOT planned_root_pressure_mmhg EQUAL 90 OR NOT added EQUAL 1 OR NOT removed EQUAL 1
   OR NOT edited_feeders EQUAL planned_feeders OR NOT edited_inlet STREQUAL "Common Hepatic Artery"
   OR NOT edited_csv MATCHES "\n0,\"[^\"]+\",[0-9]+,[0-9]+,1,0,1,1," OR edited_csv MATCHES "\n${removed_feeder},")
    message(FATAL_ERROR "the inlet and the feeders corrected by hand:\n${planned}\n${edited}\n${edited_csv}")
endif()
# The report's chemoembolization section from the best tip by coverage: the perfused territory over the CT and the
# DSA-like view at the working angle are pictures in it (drawn without a display).
set(labels --liver-label ${liver_id} --tumour-label ${label_id} --tumour-value 2)
run_cli(0 rooted simulate network --study ${study} --tip root ${labels})
string(JSON best_node GET "${rooted}" metrics best_tip_node)
string(REGEX REPLACE "\\..*" "" best_node "${best_node}")
run_cli(0 selective simulate network --study ${study} --tip ${best_node} ${labels})
run_cli(0 ignored report --study ${study} --out ${WORK}/tace.pdf --sections chemoembolization)
execute_process(COMMAND pdftotext -raw ${WORK}/tace.pdf - OUTPUT_VARIABLE tace_text RESULT_VARIABLE pdf_status)
execute_process(COMMAND pdfimages -list ${WORK}/tace.pdf OUTPUT_VARIABLE tace_images)
string(REGEX MATCHALL "\n +[0-9]+ +[0-9]+ image" pictures "${tace_images}")
list(LENGTH pictures picture_count)
if(NOT pdf_status EQUAL 0 OR NOT tace_text MATCHES "Perfused territory from the tip on the axial CT slice"
   OR NOT tace_text MATCHES "DSA-like view at the working angle \\((LAO|RAO) [0-9.]+, (cranial|caudal) [0-9.]+ deg"
   OR picture_count LESS 2)
    message(FATAL_ERROR "the chemoembolization report must show the territory and the working view (tip ${best_node}, "
                        "${picture_count} pictures):\n${tace_images}")
endif()

run_cli(1 noliver simulate network --study ${study} --tip root --remove-feeder 1)
run_cli(1 noname simulate network --study ${study} --tip root --inlet "celiac trunk")
if(NOT noliver MATCHES "with a liver label" OR NOT noname MATCHES "its named segments: common hepatic artery")
    message(FATAL_ERROR "feeder edits without a liver and an unknown inlet must be refused:\n${noliver}\n${noname}")
endif()

run_cli(1 notlabel simulate network --study ${study} --tip 20,-25,-305 --tumour-label skeleton-3)
if(NOT notlabel MATCHES "must be a label or image")
    message(FATAL_ERROR "a skeleton as the tumour must be refused:\n${notlabel}")
endif()

# A hand-written network: a Y with its outlets at pressures, then the same with a cycle and without conditions.
set(nodes "[{\"position_mm\": [0, 0, 0]}, {\"position_mm\": [0, 0, 20]}, {\"position_mm\": [-5, 0, 30]}, {\"position_mm\": [5, 0, 30]}]")
set(y "{\"from\": 0, \"to\": 1, \"start_radius_mm\": 2, \"end_radius_mm\": 1.8, \"length_mm\": 20}, {\"from\": 1, \"to\": 2, \"start_radius_mm\": 1.2, \"end_radius_mm\": 1, \"length_mm\": 11}, {\"from\": 1, \"to\": 3, \"start_radius_mm\": 1.2, \"end_radius_mm\": 1, \"length_mm\": 11}")
set(outlet_conditions "[{\"node\": 2, \"pressure_mmhg\": 10}, {\"node\": 3, \"pressure_mmhg\": 20}]")
file(WRITE ${WORK}/y.json "{\"format\": \"vascusim-network\", \"version\": 1, \"root\": 0, \"nodes\": ${nodes}, \"segments\": [${y}], \"outlets\": ${outlet_conditions}}")
file(WRITE ${WORK}/cycle.json "{\"format\": \"vascusim-network\", \"version\": 1, \"root\": 0, \"nodes\": ${nodes}, \"segments\": [${y}, {\"from\": 2, \"to\": 3, \"start_radius_mm\": 1, \"end_radius_mm\": 1, \"length_mm\": 10}]}")
file(WRITE ${WORK}/open.json "{\"format\": \"vascusim-network\", \"version\": 1, \"root\": 0, \"nodes\": ${nodes}, \"segments\": [${y}]}")
run_cli(0 file simulate network --study ${study} --network ${WORK}/y.json --tip 0)
run_cli(0 murray simulate network --study ${study} --network ${WORK}/open.json --default-outlets murray --tip 0)
run_cli(0 pressure simulate network --study ${study} --tip 20,-25,-305 --tip-pressure 30 --param blood_flow=0)
run_cli(0 mass simulate network --study ${study} --tip 20,-25,-305 --rate 1.9g/min)
string(JSON pressure_tip GET "${pressure}" metrics tip_pressure_mmhg)
string(JSON mass_rate GET "${mass}" metrics injection_mass_rate_g_min)
if(pressure_tip LESS 29.999 OR pressure_tip GREATER 30.001 OR mass_rate LESS 1.8999 OR mass_rate GREATER 1.9001)
    message(FATAL_ERROR "injection by pressure (${pressure_tip} mmHg) or by mass rate (${mass_rate} g/min) not kept")
endif()
run_cli(1 both simulate network --study ${study} --tip 20,-25,-305 --rate 2 --tip-pressure 30)
run_cli(2 unit simulate network --study ${study} --tip 20,-25,-305 --rate 2l/h)
run_cli(1 low simulate network --study ${study} --tip 20,-25,-305 --tip-pressure 5 --param blood_flow=0)
run_cli(1 blood_pressure simulate network --study ${study} --tip 20,-25,-305 --tip-pressure 30)
if(NOT both MATCHES "not both" OR NOT unit MATCHES "unknown unit 'l/h'" OR NOT low MATCHES "does not drive any flow"
   OR NOT blood_pressure MATCHES "with blood flow the injection is a rate")
    message(FATAL_ERROR "a conflicting, malformed or too low injection must be refused:\n${both}\n${unit}\n${low}\n${blood_pressure}")
endif()
run_cli(1 far simulate network --study ${study} --tip 200,200,0)
run_cli(1 void simulate network --study ${study} --tip 20,-25,-305 --void-fraction 1)
run_cli(1 cycle simulate network --study ${study} --network ${WORK}/cycle.json --tip 0)
run_cli(1 open simulate network --study ${study} --network ${WORK}/open.json --tip 0)
if(NOT far MATCHES "from the vessel tree" OR NOT void MATCHES "void_fraction" OR NOT cycle MATCHES "segment 3 .*closes a cycle"
   OR NOT open MATCHES "outlet node 2 has no boundary condition")
    message(FATAL_ERROR "bad input must be refused with a message:\n${far}\n${void}\n${cycle}\n${open}")
endif()
run_cli(0 validation validate network)
