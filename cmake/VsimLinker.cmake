# The linker: LLVM's lld when the compiler can use it, else GNU gold, else the default (GNU ld). About 180 programs
# and libraries link against VTK, ITK and Qt; lld links one of the GUI tests in 0.6 s against GNU ld's 4.0 s
# (2026-12-02, 2 cores), a sixth of the suite's build time. VSIM_LINKER=default keeps the toolchain's own.
include(CheckLinkerFlag)

set(VSIM_LINKER "AUTO" CACHE STRING "The linker for C and C++ targets: AUTO (lld, then gold), lld, gold, default")
set_property(CACHE VSIM_LINKER PROPERTY STRINGS AUTO lld gold default)

set(vsim_linker_candidates ${VSIM_LINKER})
if(VSIM_LINKER STREQUAL "AUTO")
    set(vsim_linker_candidates lld gold)
endif()
set(VSIM_LINKER_USED default)
if(NOT VSIM_LINKER STREQUAL "default")
    foreach(candidate IN LISTS vsim_linker_candidates)
        check_linker_flag(CXX "-fuse-ld=${candidate}" VSIM_LINKER_${candidate}_WORKS)
        if(VSIM_LINKER_${candidate}_WORKS)
            set(VSIM_LINKER_USED ${candidate})
            break()
        endif()
    endforeach()
    if(VSIM_LINKER_USED STREQUAL "default" AND NOT VSIM_LINKER STREQUAL "AUTO")
        message(FATAL_ERROR "VSIM_LINKER=${VSIM_LINKER}, but the compiler cannot link with it")
    endif()
endif()
if(NOT VSIM_LINKER_USED STREQUAL "default")
    # Only where C or C++ links the target: nvcc links nothing here, but it would not take the flag.
    add_link_options("$<$<LINK_LANGUAGE:C,CXX>:-fuse-ld=${VSIM_LINKER_USED}>")
endif()
message(STATUS "Linker: ${VSIM_LINKER_USED}")
