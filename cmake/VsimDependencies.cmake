# Third-party packages, found once for the whole tree. Versions are those of Debian 12 (scripts/install-deps.sh).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(ZLIB REQUIRED)
find_package(Threads REQUIRED)
find_package(Qt6 6.4 REQUIRED COMPONENTS Core Gui Widgets OpenGL OpenGLWidgets Concurrent Test LinguistTools)
# fontconfig: the system font that draws a view's text beyond Latin-1 (viz TextFonts.h)
find_package(Fontconfig REQUIRED)
qt_standard_project_setup()
set(CMAKE_AUTOMOC ON)

# VTK: never VTK::GUISupportQt (built against Qt 5 in Debian); the Qt 6 bridge lives in modules/viz.
find_package(VTK 9.1 REQUIRED COMPONENTS
    CommonCore CommonDataModel CommonExecutionModel CommonMath CommonTransforms
    IOXML IOImage ImagingCore ImagingGeneral
    RenderingCore RenderingOpenGL2 RenderingVolume RenderingVolumeOpenGL2 RenderingAnnotation
    RenderingFreeType RenderingImage InteractionStyle InteractionWidgets FiltersCore FiltersGeneral FiltersSources
    FiltersModeling IOGeometry)

find_package(ITK 5.2 REQUIRED COMPONENTS
    ITKCommon ITKIOImageBase ITKIONRRD ITKIONIFTI ITKIOMeta ITKImageGrid
    ITKSmoothing ITKThresholding ITKConnectedComponents ITKRegionGrowing ITKImageFeature ITKImageIntensity
    ITKBinaryMathematicalMorphology ITKMathematicalMorphology ITKDistanceMap ITKLabelMap ITKImageLabel
    ITKImageStatistics ITKFastMarching ITKLevelSets)
# ITK 5.2 in Debian bundles Eigen 3.3.9 under the same include guards as Eigen 3.4: one translation unit
# cannot hold both. ITK_USE_SYSTEM_EIGEN makes ITK's (template-only) Eigen use compile against Eigen 3.4.
add_library(vsim_itk INTERFACE)
target_link_libraries(vsim_itk INTERFACE ${ITK_LIBRARIES} Eigen3::Eigen)
target_compile_definitions(vsim_itk INTERFACE ITK_USE_SYSTEM_EIGEN)
add_library(vsim::itk ALIAS vsim_itk)
# No include(${ITK_USE_FILE}): it puts ITK's bundled Eigen on every target's include path, shadowing Eigen 3.4.
# ITK image IOs are chosen explicitly in code (NrrdImageIO, NiftiImageIO, ...), so no factory registration is needed.

find_package(DCMTK REQUIRED)

# SuiteSparse (Debian libsuitesparse-dev): CHOLMOD's supernodal Cholesky and UMFPACK's multifrontal LU for the
# converged wall solves (modules/sim/fem SparseDirect), on OpenBLAS where installed (libopenblas0-pthread).
find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
foreach(component cholmod umfpack amd colamd camd ccolamd suitesparseconfig)
    find_library(SUITESPARSE_${component}_LIBRARY ${component} REQUIRED)
    list(APPEND SUITESPARSE_LIBRARIES ${SUITESPARSE_${component}_LIBRARY})
endforeach()
add_library(vsim_suitesparse INTERFACE)
target_include_directories(vsim_suitesparse SYSTEM INTERFACE ${SUITESPARSE_INCLUDE_DIR})
target_link_libraries(vsim_suitesparse INTERFACE ${SUITESPARSE_LIBRARIES})
add_library(vsim::suitesparse ALIAS vsim_suitesparse)
