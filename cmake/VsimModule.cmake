# vsim_add_module(): one library target per module, with the layering of shared/design/ARCHITECTURE.md enforced.
#
#   vsim_add_module(NAME <name> SOURCES <files...>
#                   [DEPENDS <vsim modules...>] [PUBLIC_LIBS <targets...>] [PRIVATE_LIBS <targets...>]
#                   [PRECOMPILED_HEADERS <headers...>])
#
# Creates target vsim_<name> with alias vsim::<name>; public headers live in include/vsim/<header dir>/.
# A dependency that points up or sideways in the picture below stops the configure step:
#
#   core <- interop (ITK/VTK adapters) <- dicom | imaging | mesh          (compute, no Qt)
#   core <- sim_common <- sim_<solver> <- cuda_<solver>                   (solvers: core only, no Qt/VTK/ITK)
#   core <- interop <- study (persists core types) <- report | viz <- app
include_guard(GLOBAL)

# Modules each module may depend on. sim_<x> and cuda_<x> are matched by family below.
set(VSIM_ALLOWED_DEPS_core "")
set(VSIM_ALLOWED_DEPS_interop core)
set(VSIM_ALLOWED_DEPS_dicom core interop)
set(VSIM_ALLOWED_DEPS_imaging core interop)
set(VSIM_ALLOWED_DEPS_mesh core interop)
set(VSIM_ALLOWED_DEPS_sim_common core)
set(VSIM_ALLOWED_DEPS_cuda_common core)
set(VSIM_ALLOWED_DEPS_study core interop)
set(VSIM_ALLOWED_DEPS_report core study)
set(VSIM_ALLOWED_DEPS_viz core study interop mesh)
# Modules that may link Qt, and the Qt modules they may use (compute and solver modules link no Qt).
set(VSIM_QT_ALLOWED_report Qt6::Core Qt6::Gui)
set(VSIM_QT_ALLOWED_viz Qt6::Core Qt6::Gui Qt6::OpenGL Qt6::OpenGLWidgets)

function(_vsim_allowed_dependencies name out_var)
    if(DEFINED VSIM_ALLOWED_DEPS_${name})
        set(${out_var} "${VSIM_ALLOWED_DEPS_${name}}" PARENT_SCOPE)
    elseif(name MATCHES "^sim_(.+)$")
        set(${out_var} core sim_common PARENT_SCOPE)
    elseif(name MATCHES "^cuda_(.+)$")
        set(${out_var} core sim_common cuda_common sim_${CMAKE_MATCH_1} PARENT_SCOPE)
    else()
        message(FATAL_ERROR "vsim_add_module: '${name}' is not a module of ARCHITECTURE.md; add it to cmake/VsimModule.cmake")
    endif()
endfunction()

function(_vsim_check_libraries name)
    set(solver_like OFF)
    if(name STREQUAL "core" OR name MATCHES "^(sim|cuda)_")
        set(solver_like ON)
    endif()
    foreach(library IN LISTS ARGN)
        if(library MATCHES "^Qt6::")
            if(NOT library IN_LIST VSIM_QT_ALLOWED_${name})
                message(FATAL_ERROR "vsim_add_module: forbidden dependency ${name} -> ${library} (only report and viz link Qt, app links QtWidgets)")
            endif()
        elseif(solver_like AND library MATCHES "^(VTK::|ITK|vsim::itk|DCMTK)")
            message(FATAL_ERROR "vsim_add_module: forbidden dependency ${name} -> ${library} (core and solvers depend on core alone)")
        endif()
    endforeach()
endfunction()

function(vsim_add_module)
    cmake_parse_arguments(PARSE_ARGV 0 ARG "" "NAME;HEADER_DIR" "SOURCES;DEPENDS;PUBLIC_LIBS;PRIVATE_LIBS;PRECOMPILED_HEADERS")
    if(NOT ARG_NAME)
        message(FATAL_ERROR "vsim_add_module: NAME is required")
    endif()
    _vsim_allowed_dependencies(${ARG_NAME} allowed)
    foreach(dependency IN LISTS ARG_DEPENDS)
        if(NOT dependency IN_LIST allowed)
            message(FATAL_ERROR "vsim_add_module: forbidden dependency ${ARG_NAME} -> ${dependency} "
                                "(allowed: ${allowed}; see shared/design/ARCHITECTURE.md)")
        endif()
    endforeach()
    _vsim_check_libraries(${ARG_NAME} ${ARG_PUBLIC_LIBS} ${ARG_PRIVATE_LIBS})

    set(target vsim_${ARG_NAME})
    # Public headers are listed as sources so that AUTOMOC sees the Q_OBJECT classes among them.
    file(GLOB_RECURSE public_headers CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/include/*.h)
    add_library(${target} STATIC ${ARG_SOURCES} ${public_headers})
    add_library(vsim::${ARG_NAME} ALIAS ${target})
    target_include_directories(${target} PUBLIC
        $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
        PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
    list(TRANSFORM ARG_DEPENDS PREPEND "vsim::" OUTPUT_VARIABLE module_targets)
    target_link_libraries(${target} PUBLIC ${module_targets} ${ARG_PUBLIC_LIBS} PRIVATE ${ARG_PRIVATE_LIBS})
    target_compile_options(${target} PRIVATE
        $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wno-unused-parameter>)
    if(ARG_PRECOMPILED_HEADERS)
        target_precompile_headers(${target} PRIVATE ${ARG_PRECOMPILED_HEADERS})
    endif()
    set_target_properties(${target} PROPERTIES VSIM_MODULE ${ARG_NAME})
endfunction()
