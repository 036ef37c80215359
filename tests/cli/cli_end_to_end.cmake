# Runs vascusim-cli as a user would and checks its output against what the inputs must give.
include(${CMAKE_CURRENT_LIST_DIR}/RunCli.cmake)

run_cli(0 version --version)
foreach(component VascuSim Qt VTK ITK DCMTK Eigen "GPU plugin" "CUDA runtime" GPU)
    if(NOT version MATCHES "${component} [^\n]+")
        message(FATAL_ERROR "--version does not name ${component}:\n${version}")
    endif()
endforeach()
# The GPU plugin (app/common/src/GpuPlugin.h): a file that is not one is refused, an absent one is 'not installed';
# either way the CLI runs, on the CPU.
foreach(plugin ${CLI} ${WORK}/no-such-plugin.so)
    execute_process(COMMAND ${CMAKE_COMMAND} -E env VASCUSIM_GPU_PLUGIN=${plugin} ${CLI} --version
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL 0 OR NOT out MATCHES "GPU plugin (refused: [^\n]*does not load|not installed)"
       OR NOT out MATCHES "GPU not used: every solver runs on the CPU")
        message(FATAL_ERROR "--version with VASCUSIM_GPU_PLUGIN=${plugin}: exit ${code}\n${out}\n${err}")
    endif()
endforeach()

# demo study (the full-size aaa phantom) -> its CT as NRRD imported into a new study -> info shows its geometry
run_cli(0 demo demo-study --out ${WORK}/demo.vsim)
file(GLOB ct ${WORK}/demo.vsim/images/*.nrrd)
run_cli(0 imported import ${ct} --study ${WORK}/imported.vsim)
run_cli(0 info info ${WORK}/imported.vsim)
string(JSON dims GET "${info}" artifacts 0 geometry dims)
string(JSON spacing_z GET "${info}" artifacts 0 geometry spacing_mm 2)
string(JSON origin_x GET "${info}" artifacts 0 geometry origin_mm 0)
string(JSON command GET "${info}" artifacts 0 provenance command)
string(REGEX REPLACE "[ \n]" "" dims "${dims}")
if(NOT dims STREQUAL "[512,512,400]" OR NOT spacing_z EQUAL 1 OR NOT origin_x MATCHES "^-178\\.8(5|4999)"
   OR NOT command STREQUAL "import volume")
    message(FATAL_ERROR "info does not show the demo CT's geometry: dims ${dims}, spacing z ${spacing_z}, origin x ${origin_x}, command ${command}")
endif()

# bad input: a missing study, a junk volume, an unknown command
run_cli(1 missing info ${WORK}/no-such.vsim)
file(WRITE ${WORK}/junk.nii "junk")
run_cli(1 junk import ${WORK}/junk.nii --study ${WORK}/imported.vsim)
if(NOT junk MATCHES "error: ")
    message(FATAL_ERROR "a junk volume must give an error line:\n${junk}")
endif()
run_cli(2 unknown frobnicate)
run_cli(0 info_after info ${WORK}/imported.vsim)
string(JSON count LENGTH "${info_after}" artifacts)
if(NOT count EQUAL 1)
    message(FATAL_ERROR "a failed import must leave the study as it was (1 artifact), found ${count}")
endif()
message(STATUS "vascusim-cli end to end: all checks passed")
