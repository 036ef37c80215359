# Real CT (label realdata; ../shared/data, see its README): the portal-venous liver CT (3D-IRCADb 1.17, DICOM) and
# the CT pulmonary angiogram crop (TotalSegmentator, NIfTI) import as CT in HU with the grids their publishers give
# (512 x 512 x 119, 0.743 x 0.743 mm, 1.6 mm apart; 122 x 102 x 112 at 1.5 mm, axes towards L, P, S), and the
# vessel segmentation runs on both without a refusal; their reference masks import onto the CT's grid as labels
# (`import --as-label`; the heart mask from the uncropped scan's grid, cut by its whole-voxel offset) with every
# labelled voxel kept (truth: the masks' own counts, read by nifti_count.py) and where the publisher says they lie
# (the heart mask holds most of the pulmonary trunk). The segmentation's overlap with the masks is printed (issue 15
# sets its targets). Skipped, with the reason, when the data folder is absent.
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

if(NOT EXISTS ${DATA}/ircad-liver-17/PATIENT_DICOM OR NOT EXISTS ${DATA}/ctpa-totalsegmentator/ct_cropped.nii.gz)
    message("SKIP: the real CT data is not at ${DATA} (../shared/data beside the project)")
    return()
endif()

function(expect_grid info dims spacing)
    string(JSON got_dims GET "${info}" artifacts 0 geometry dims)
    string(JSON got_spacing GET "${info}" artifacts 0 geometry spacing_mm)
    string(REGEX REPLACE "[ \n]" "" got_dims "${got_dims}")
    string(REGEX REPLACE "[ \n]" "" got_spacing "${got_spacing}")
    if(NOT got_dims STREQUAL dims OR NOT got_spacing MATCHES "${spacing}")
        message(FATAL_ERROR "grid ${got_dims} at ${got_spacing}, expected ${dims} at ${spacing}")
    endif()
endfunction()

run_cli(0 ignored import ${DATA}/ircad-liver-17/PATIENT_DICOM --study ${WORK}/liver.vsim)
run_cli(0 info info ${WORK}/liver.vsim)
expect_grid("${info}" "[512,512,119]" "^\\[0\\.74[0-9]*,0\\.74[0-9]*,1\\.6[0-9]*\\]$")
run_cli(0 segmented segment --study ${WORK}/liver.vsim)
message(STATUS "liver CT: ${segmented}")
file(MAKE_DIRECTORY ${WORK}/masks)
execute_process(COMMAND ${CMAKE_COMMAND} -E tar xf ${DATA}/ircad-liver-17/MASKS_DICOM.zip WORKING_DIRECTORY ${WORK}/masks
                RESULT_VARIABLE code)
foreach(mask artery portalvein venoussystem bone)
    run_cli(0 imported import ${WORK}/masks/MASKS_DICOM/${mask} --study ${WORK}/liver.vsim --as-label)
    if(NOT imported MATCHES "on the grid of image-1: [1-9][0-9]* labelled voxels")
        message(FATAL_ERROR "the ${mask} mask must import on the CT's grid:\n${imported}")
    endif()
endforeach()
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/label_overlap.py ${WORK}/liver.vsim label-2 label-3 label-4 label-5
                label-6 OUTPUT_VARIABLE overlap RESULT_VARIABLE code)
message(STATUS "liver CT, the automatic segmentation against artery (label-3), portal vein, hepatic veins, bone:\n${overlap}")

# The guided segmentation, target hepatic, from a point in the aorta (the artery mask's largest cross-section at
# z = 96 mm), one in the right hepatic artery beside the hilum and one on the left hepatic artery where it runs
# against the left portal vein (the centring pulls that point into the vein: it grows no front and is joined by its
# minimal path only). Asserted (must-show 3): the three points in one piece of the label (the path common -> proper
# -> right and left hepatic reached; points_joined.py), at most 10 % of the label in the portal and hepatic-vein
# masks. Reported, with a floor against regressions: the recall of the artery mask's voxels farther than 10 mm from
# the aorta (the must-show asks 0.6). In this portal-venous phase the far arteries are barely brighter than the
# liver: far_recall.py prints their median HU (107) beside the mask's aorta (158) and the liver mask's median (101)
# and robust SD (22 HU): a contrast-to-noise ratio of 0.27 per voxel. It also splits the far voxels into their
# connected pieces: on this scan only 46 % of them lie in the piece that reaches into the liver (the celiac trunk's
# tree: common, proper, right and left hepatic, splenic, gastroduodenal); the rest are the superior mesenteric and
# renal arteries, which a hepatic target does not follow, so 0.6 of the whole is out of a hepatic label's reach.
# far_recall.py also prints the ceiling: the far voxels at or above their own vessel's half level (the edge of the
# lumen as CT shows it; the mask is drawn wider): 0.69 of all far voxels, 0.65 of the celiac tree's, and 0.30 of all
# far voxels for a perfect label of the celiac tree alone.
# 2026-11-27: far recall 0.26 (0.20 before the minimal paths), 0.17 in the celiac tree (0.03), 0.34 elsewhere.
set(hepatic_points 202.6,195.4,96 124.1,146.4,91.2 156.8,112.2,115.2)
set(seed_args)
foreach(point ${hepatic_points})
    list(APPEND seed_args --seed ${point})
endforeach()
run_cli(0 guided segment --study ${WORK}/liver.vsim --target hepatic ${seed_args})
message(STATUS "liver CT, guided (hepatic):\n${guided}")
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/label_overlap.py ${WORK}/liver.vsim label-7 label-3 label-4
                label-5 label-6 OUTPUT_VARIABLE overlap)
string(JSON portal GET "${overlap}" references label-4 share_of_label)
string(JSON venous GET "${overlap}" references label-5 share_of_label)
if(portal GREATER 0.05 OR venous GREATER 0.05) # each at most half the must-show's 10 %: 10 % together
    message(FATAL_ERROR "the hepatic label runs into the veins (portal ${portal}, hepatic veins ${venous}):\n${overlap}")
endif()
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/points_joined.py ${WORK}/liver.vsim label-7 label-3
                ${hepatic_points} OUTPUT_VARIABLE joined RESULT_VARIABLE code)
string(JSON right GET "${joined}" joined_to_first 1)
string(JSON left GET "${joined}" joined_to_first 2)
if(NOT code EQUAL 0 OR NOT right OR NOT left)
    message(FATAL_ERROR "the hepatic label does not join the aorta to the right and left hepatic arteries:\n${joined}")
endif()
message(STATUS "liver CT, guided (hepatic): the points joined by the label:\n${joined}")
run_cli(0 imported import ${WORK}/masks/MASKS_DICOM/liver --study ${WORK}/liver.vsim --as-label) # label-8
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/far_recall.py ${WORK}/liver.vsim label-7 label-3 10 label-8
                OUTPUT_VARIABLE far RESULT_VARIABLE code)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "far_recall.py failed:\n${far}")
endif()
message(STATUS "liver CT, guided (hepatic): artery-mask voxels over 10 mm from the aorta found:\n${far}")
message(STATUS "liver CT, guided (hepatic) against artery (label-3), portal vein, hepatic veins, bone:\n${overlap}")
string(JSON tree_recall GET "${far}" far_recall_liver_reaching_tree)
if(tree_recall LESS 0.15)
    message(FATAL_ERROR "the hepatic label lost the celiac tree (recall ${tree_recall}, 0.17 on 2026-11-27)")
endif()

# The liver grown from three points (issue 19's semi-automatic liver tool; the points 30-36 mm deep in the mask)
# against the liver mask: Dice 0.905, 97.6 % of the label inside the mask (2026-11-28; the mask holds the tumours and
# the larger vessels, which the window leaves out).
run_cli(0 grown segment-organ --study ${WORK}/liver.vsim --seed 114.4,127.1,136.0 --seed 108.5,171.6,128.0
        --seed 182.0,81.0,139.2)
string(REGEX MATCH "as (label-[0-9]+)" ignored "${grown}")
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/label_overlap.py ${WORK}/liver.vsim ${CMAKE_MATCH_1} label-8
                OUTPUT_VARIABLE liver_overlap)
string(JSON liver_dice GET "${liver_overlap}" references label-8 dice)
message(STATUS "liver CT, the liver grown from points: ${grown}Dice ${liver_dice} against the liver mask")
if(liver_dice LESS 0.85)
    message(FATAL_ERROR "the liver grown from points: Dice ${liver_dice} against the mask (0.905 on 2026-11-28)")
endif()

# Chemoembolization planning on the patient (issue 19): the guided hepatic label's skeleton and centerlines, the
# catheter at the network's root, the liver and the first tumour masks as labels: territories, the lesion's coverage
# grade and feeders, tips ranked by coverage, within the issue's 2 s for one tip and 10 s for the ranking.
run_cli(0 imported import ${WORK}/masks/MASKS_DICOM/livertumor1 --study ${WORK}/liver.vsim --as-label)
string(REGEX MATCH "as (label-[0-9]+)" ignored "${imported}")
set(tumour_id ${CMAKE_MATCH_1})
run_cli(0 ignored skeleton --study ${WORK}/liver.vsim --label label-7)
run_cli(0 centerlined centerline --study ${WORK}/liver.vsim)
string(REGEX MATCH "as (skeleton-[0-9]+)" ignored "${centerlined}")
set(centerlines_id ${CMAKE_MATCH_1})
run_cli(0 planned simulate network --study ${WORK}/liver.vsim --tip root --liver-label label-8 --tumour-label ${tumour_id}
        --centerlines ${centerlines_id}
        --out ${WORK}/tace)
foreach(key liver_volume_ml hepatic_outlets lesions lesion_1_diameter_mm lesion_1_margin_mm coverage_grade feeders
        best_tip_grade best_tip_non_target_ml territory_seconds ranked_tips ranking_seconds)
    string(JSON value GET "${planned}" metrics ${key})
    set(${key} ${value})
    string(APPEND tace_figures " ${key} ${value};")
endforeach()
message(STATUS "liver CT, chemoembolization from the root:${tace_figures}")
if(NOT lesions EQUAL 1 OR hepatic_outlets LESS 1 OR feeders LESS 1 OR territory_seconds GREATER 2
   OR ranking_seconds GREATER 10 OR NOT EXISTS ${WORK}/tace/territory.nrrd OR NOT EXISTS ${WORK}/tace/feeders.csv)
    message(FATAL_ERROR "chemoembolization planning on the liver CT:${tace_figures}")
endif()

# The tumours from one point each near their centres, grown within the liver mask (segment-organ --within: the
# lesion's boundary against the parenchyma), against the reference tumour masks (0.743 and 0.830 on 2026-11-29;
# the organ window held 0.13 and 0.24 of them).
run_cli(0 imported2 import ${WORK}/masks/MASKS_DICOM/livertumor2 --study ${WORK}/liver.vsim --as-label)
string(REGEX MATCH "as (label-[0-9]+)" ignored "${imported2}")
set(tumour2_id ${CMAKE_MATCH_1})
foreach(pair "101.8,138.2,156.8;${tumour_id}" "205.8,126.3,147.2;${tumour2_id}")
    list(GET pair 0 point)
    list(GET pair 1 reference)
    run_cli(0 lesion segment-organ --study ${WORK}/liver.vsim --seed ${point} --organ tumour --within label-8)
    string(REGEX MATCH "as (label-[0-9]+)" ignored "${lesion}")
    execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/label_overlap.py ${WORK}/liver.vsim ${CMAKE_MATCH_1} ${reference}
                    OUTPUT_VARIABLE lesion_overlap)
    string(JSON lesion_dice GET "${lesion_overlap}" references ${reference} dice)
    message(STATUS "liver CT, a tumour from one point: ${lesion}Dice ${lesion_dice} against ${reference}")
    if(lesion_dice LESS 0.7)
        message(FATAL_ERROR "a tumour grown within the liver from ${point}: Dice ${lesion_dice} against ${reference}")
    endif()
endforeach()

# The same with blood entering at the common hepatic artery, given as a point on it (the segment after the celiac
# trunk's division, towards the hilum; by inspection of this network: its one other outlet is the gastroduodenal),
# and the report's chemoembolization section with its pictures (the territory over the CT, the DSA-like view).
run_cli(0 hepatic simulate network --study ${WORK}/liver.vsim --tip root --liver-label label-8 --tumour-label ${tumour_id}
        --centerlines ${centerlines_id} --inlet 189.0,164.1,98.1 --out ${WORK}/tace-hepatic)
set(hepatic_figures)
foreach(key hepatic_outlets extrahepatic_outlets root_pressure_mmhg coverage_grade feeders drug_extrahepatic_percent
        best_tip_node best_tip_grade best_tip_non_target_ml)
    string(JSON value GET "${hepatic}" metrics ${key})
    set(hepatic_${key} ${value})
    string(APPEND hepatic_figures " ${key} ${value};")
endforeach()
message(STATUS "liver CT, blood entering at the common hepatic artery:${hepatic_figures}")
string(REGEX REPLACE "\\..*" "" best_node "${hepatic_best_tip_node}")
run_cli(0 selective simulate network --study ${WORK}/liver.vsim --tip ${best_node} --liver-label label-8
        --tumour-label ${tumour_id} --centerlines ${centerlines_id} --inlet 189.0,164.1,98.1)
run_cli(0 ignored report --study ${WORK}/liver.vsim --out ${WORK}/tace.pdf --sections chemoembolization)
execute_process(COMMAND pdftotext -raw ${WORK}/tace.pdf - OUTPUT_VARIABLE tace_text)
execute_process(COMMAND pdfimages -list ${WORK}/tace.pdf OUTPUT_VARIABLE tace_images)
string(REGEX MATCHALL "\n +[0-9]+ +[0-9]+ image" pictures "${tace_images}")
list(LENGTH pictures picture_count)
if(hepatic_extrahepatic_outlets GREATER 2 OR NOT hepatic_root_pressure_mmhg EQUAL 90 OR hepatic_feeders LESS 1
   OR NOT tace_text MATCHES "Perfused territory from the tip on the axial CT slice"
   OR NOT tace_text MATCHES "Blood enters at: 189.0,164.1,98.1" OR picture_count LESS 2)
    message(FATAL_ERROR "chemoembolization from the common hepatic artery:${hepatic_figures} ${picture_count} pictures")
endif()

# The feeders found against the reference artery mask's branches entering each tumour + margin (issue 19; see
# feeder_sensitivity.py: the mask's pieces in the region that come from outside it, matched within 5 mm of a found
# feeder's entry), blood entering at the common hepatic artery. The IRCAD artery mask holds the aorta, the celiac trunk
# and the hepatic arteries to their first divisions: none of it enters the first tumour's 10 mm margin, and one branch
# enters the second's (checked: the reference count is the data's, not the estimator's).
run_cli(0 hepatic2 simulate network --study ${WORK}/liver.vsim --tip root --liver-label label-8
        --tumour-label ${tumour2_id} --centerlines ${centerlines_id} --inlet 189.0,164.1,98.1 --out ${WORK}/tace2-hepatic)
string(JSON margin1 GET "${hepatic}" metrics lesion_1_margin_mm)
string(JSON margin2 GET "${hepatic2}" metrics lesion_1_margin_mm)
foreach(case "${tumour_id};${margin1};tace-hepatic;0" "${tumour2_id};${margin2};tace2-hepatic;1")
    list(GET case 0 reference)
    list(GET case 1 margin)
    list(GET case 2 folder)
    list(GET case 3 expected)
    execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/feeder_sensitivity.py ${WORK}/liver.vsim label-3 ${reference}
                    ${WORK}/${folder}/feeders.csv ${margin} OUTPUT_VARIABLE judged RESULT_VARIABLE judged_status)
    if(NOT judged_status EQUAL 0)
        message(FATAL_ERROR "feeder_sensitivity.py on ${reference} failed:\n${judged}")
    endif()
    foreach(key reference_feeders found feeders feeders_on_artery_mask)
        string(JSON ${key} GET "${judged}" ${key})
    endforeach()
    message(STATUS "liver CT, feeders of ${reference} (margin ${margin} mm) against the artery mask: ${found} of "
            "${reference_feeders} branches entering found; ${feeders_on_artery_mask} of ${feeders} feeders on the mask")
    if(NOT reference_feeders EQUAL expected OR feeders LESS 1)
        message(FATAL_ERROR "feeders against the artery mask (${expected} reference branches expected):\n${judged}")
    endif()
endforeach()

run_cli(0 ignored import ${DATA}/ctpa-totalsegmentator/ct_cropped.nii.gz --study ${WORK}/ctpa.vsim)
run_cli(0 info info ${WORK}/ctpa.vsim)
expect_grid("${info}" "[122,102,112]" "^\\[1\\.5,1\\.5,1\\.5\\]$")
string(JSON direction GET "${info}" artifacts 0 geometry direction)
string(REGEX REPLACE "[ \n]" "" direction "${direction}")
if(NOT direction STREQUAL "[[1.0,0.0,0.0],[0.0,1.0,0.0],[0.0,0.0,1.0]]")
    message(FATAL_ERROR "the crop's voxel axes must run towards L, P, S (LPS identity): ${direction}")
endif()
run_cli(0 segmented segment --study ${WORK}/ctpa.vsim)
message(STATUS "CT pulmonary angiogram: ${segmented}")
foreach(mask heart pulmonary_artery)
    execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/nifti_count.py ${DATA}/ctpa-totalsegmentator/${mask}.nii.gz
                    OUTPUT_VARIABLE truth OUTPUT_STRIP_TRAILING_WHITESPACE)
    run_cli(0 imported import ${DATA}/ctpa-totalsegmentator/${mask}.nii.gz --study ${WORK}/ctpa.vsim --as-label)
    if(NOT imported MATCHES ": ${truth} labelled voxels")
        message(FATAL_ERROR "the ${mask} mask must keep its ${truth} voxels on the crop's grid:\n${imported}")
    endif()
endforeach()
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/label_overlap.py ${WORK}/ctpa.vsim label-4 label-3
                OUTPUT_VARIABLE trunk)
string(JSON in_heart GET "${trunk}" references label-3 share_of_label)
if(in_heart LESS 0.5)
    message(FATAL_ERROR "the heart mask must hold most of the pulmonary artery mask (publisher), got ${in_heart}")
endif()
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/label_overlap.py ${WORK}/ctpa.vsim label-2 label-3 label-4
                OUTPUT_VARIABLE overlap)
message(STATUS "CT pulmonary angiogram, the automatic segmentation against heart (label-3), pulmonary artery:\n${overlap}")

# The guided segmentation (issue 15, must-show 3), as a reader would place it: a point in the middle of the pulmonary
# trunk (30 mm above the valve, the proximal end of the pulmonary-artery mask), an exclude point in the right
# ventricular outflow tract 15 mm below the valve (on the trunk's axis extended), and a stop plane at each hilum (where
# the mask's left and right pulmonary arteries end, normal pointing lateral; the path limit then only a backstop).
# Fronts that compete meet half-way along the blood between their points (the valve is no narrowing here), so an
# exclude point deep in the ventricle (60 mm below the trunk point) let the label grow 6 mm of the outflow tract:
# 6.1 % of it in the heart outside the pulmonary artery. The issue asks recall >= 0.8 and <= 5 %.
run_cli(0 guided segment --study ${WORK}/ctpa.vsim --target all --seed 24,-172,698 --exclude 38.6,-208.5,675.4
        --stop -49.1,-146.5,691.4,-1,0,0 --stop 49.6,-129.3,694.2,1,0,0 --max-length 150)
message(STATUS "CT pulmonary angiogram, guided: ${guided}")
execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/label_overlap.py ${WORK}/ctpa.vsim label-5 label-3 label-4
                --except label-4 OUTPUT_VARIABLE overlap)
message(STATUS "CT pulmonary angiogram, the guided segmentation against heart (label-3), pulmonary artery:\n${overlap}")
string(JSON recall GET "${overlap}" references label-4 recall)
string(JSON heart_outside GET "${overlap}" references label-3 share_of_label_outside_except)
if(recall LESS 0.8 OR heart_outside GREATER 0.05)
    message(FATAL_ERROR "guided CTPA: pulmonary-artery recall ${recall} (>= 0.8), heart outside it ${heart_outside} (<= 0.05)")
endif()
