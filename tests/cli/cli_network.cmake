# The drug-delivery steps as a user runs them on the full-size hepatic-tree phantom (512 x 512 x 400 at 0.7 mm):
# segment, skeleton, centerline, then `simulate network` from the root with the phantom's tumour (Kirchhoff
# balanced, 16 outlets, the control points' two-phase drop near the void fraction, the run files written), the
# tumour as a label (the same share as the sphere), a hand-written network file, `validate network`, and bad input refused with a message (a tip off the tree, a void
# fraction of 1, a network with a cycle, outlets without a condition).
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

set(study ${WORK}/hepatic.vsim)
run_cli(0 ignored phantom hepatic-tree --out ${WORK}/ph)
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
foreach(file network.json segments.csv outlets.csv metrics.json)
    if(NOT EXISTS ${WORK}/run/${file})
        message(FATAL_ERROR "simulate network did not write ${file}")
    endif()
endforeach()
if(balance GREATER 1e-12 OR NOT outlets EQUAL 16 OR fed LESS 1 OR drop LESS 9 OR drop GREATER 11 OR best LESS 0.2)
    message(FATAL_ERROR "simulate network: balance ${balance}, ${outlets} outlets, ${fed} tumour outlets, drop ${drop} %, "
                        "best tip ${best}\n${run}")
endif()

# The tumour as a label: the phantom's truth label (value 2) imported as a volume.
run_cli(0 imported import ${WORK}/ph/truth-label.nrrd --study ${study})
string(REGEX MATCH "as (image-[0-9]+)" ignored "${imported}")
set(label_id ${CMAKE_MATCH_1})
run_cli(0 bylabel simulate network --study ${study} --tip 20,-25,-305 --tumour-label ${label_id} --tumour-value 2)
string(JSON fed_label GET "${bylabel}" metrics tumour_outlets)
string(JSON share_label GET "${bylabel}" metrics tumour_fraction)
string(JSON share_sphere GET "${run}" metrics tumour_fraction)
if(fed_label LESS 1 OR NOT share_label EQUAL share_sphere)
    message(FATAL_ERROR "the tumour as a label: ${fed_label} outlets, share ${share_label} (sphere ${share_sphere})")
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
run_cli(1 far simulate network --study ${study} --tip 200,200,0)
run_cli(1 void simulate network --study ${study} --tip 20,-25,-305 --void-fraction 1)
run_cli(1 cycle simulate network --study ${study} --network ${WORK}/cycle.json --tip 0)
run_cli(1 open simulate network --study ${study} --network ${WORK}/open.json --tip 0)
if(NOT far MATCHES "from the vessel tree" OR NOT void MATCHES "void_fraction" OR NOT cycle MATCHES "segment 3 .*closes a cycle"
   OR NOT open MATCHES "outlet node 2 has no boundary condition")
    message(FATAL_ERROR "bad input must be refused with a message:\n${far}\n${void}\n${cycle}\n${open}")
endif()
run_cli(0 validation validate network)
