# Real CT (label realdata; ../shared/data, see its README): the portal-venous liver CT (3D-IRCADb 1.17, DICOM) and
# the CT pulmonary angiogram crop (TotalSegmentator, NIfTI) import as CT in HU with the grids their publishers give
# (512 x 512 x 119, 0.743 x 0.743 mm, 1.6 mm apart; 122 x 102 x 112 at 1.5 mm, axes towards L, P, S), and the
# vessel segmentation runs on both without a refusal. Skipped, with the reason, when the data folder is absent.
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
