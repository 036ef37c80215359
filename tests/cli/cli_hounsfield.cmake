# No false refusals (issue 15 item 5): a CT crop without air is CT in HU and segments; a volume of stored values
# without their rescale (HU + 1024) is refused at the import with the option to use, and with --rescale 1,-1024 it
# imports and segments to the same volume as the original (truth: the original crop's own segmentation).
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

run_cli(0 ignored phantom bifurcation --out ${WORK}/crop --size 160x160x120)
run_cli(0 ignored import ${WORK}/crop/dicom --study ${WORK}/crop.vsim)
run_cli(0 original segment --study ${WORK}/crop.vsim)
string(REGEX MATCH "as label-[0-9]+: ([0-9.]+) ml" ignored "${original}")
set(original_ml ${CMAKE_MATCH_1})

execute_process(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/stored_values_nrrd.py ${WORK}/crop.vsim/images/image-1.nrrd
                ${WORK}/stored.nrrd RESULT_VARIABLE code)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "could not write the stored-values volume")
endif()
run_cli(1 refused import ${WORK}/stored.nrrd --study ${WORK}/stored.vsim)
if(NOT refused MATCHES "not CT Hounsfield units: no voxel is below 0" OR NOT refused MATCHES "--rescale 1,-1024")
    message(FATAL_ERROR "a stored-values volume must be refused naming --rescale:\n${refused}")
endif()
run_cli(0 accepted import ${WORK}/stored.nrrd --study ${WORK}/stored.vsim --rescale 1,-1024)
if(NOT accepted MATCHES "warning: values rescaled to HU by the user's rescale")
    message(FATAL_ERROR "the rescale must be stated:\n${accepted}")
endif()
run_cli(0 rescaled segment --study ${WORK}/stored.vsim)
string(REGEX MATCH "as label-[0-9]+: ([0-9.]+) ml" ignored "${rescaled}")
if(NOT CMAKE_MATCH_1 STREQUAL original_ml)
    message(FATAL_ERROR "the rescaled volume must segment as the original: ${CMAKE_MATCH_1} ml vs ${original_ml} ml")
endif()
run_cli(2 unit import ${WORK}/stored.nrrd --study ${WORK}/x.vsim --rescale)
