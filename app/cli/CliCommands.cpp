#include "CliCommands.h"
#include "CliSupport.h"
#include "CommandLine.h"

#include "vsim/app/DemoStudy.h"
#include "vsim/app/DicomStudyImport.h"
#include "vsim/app/GuidedSegmentationRecord.h"
#include "vsim/app/NetworkPipeline.h"
#include "vsim/app/SacRecord.h"
#include "vsim/app/SegmentNames.h"
#include "vsim/app/StudySummary.h"
#include "vsim/app/VersionInfo.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/core/StoredText.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/dicom/PhantomWriter.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/imaging/VesselNames.h"
#include "vsim/imaging/GuidedSegmentation.h"
#include "vsim/imaging/VesselSegmentation.h"
#include "vsim/mesh/VesselSurface.h"
#include "vsim/study/Study.h"
#include "vsim/study/VolumeFileImport.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <fstream>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

namespace vsim::cli {
namespace fs = std::filesystem;

std::string Arguments::option(const std::string& name, const std::string& fallback) const
{
    for (const auto& [key, value] : options)
        if (key == name)
            return value;
    return fallback;
}

bool Arguments::hasOption(const std::string& name) const
{
    for (const auto& option : options)
        if (option.first == name)
            return true;
    return false;
}

int printVersion()
{
    for (const auto& [component, version] : app::libraryVersions())
        std::cout << component << " " << version << "\n";
    return 0;
}

int printStudyInfo(const Arguments& arguments)
{
    const study::Study study = openStudyForReading(arguments.positional[0]);
    std::cout << app::studySummaryJson(study) << std::endl;
    return 0;
}

namespace {

/// The study to import into: opened for writing, or created in a new or empty folder.
study::Study openOrCreateStudy(const Arguments& arguments)
{
    const fs::path bundle = arguments.option("study");
    return fs::exists(bundle / "study.json") ? openStudyForWriting(arguments)
                                             : study::Study::create(bundle, bundle.stem().string(), waitSeconds(arguments));
}

int listDicom(const dicom::DicomScanResult& scan)
{
    std::cout << app::dicomScanJson(scan) << std::endl;
    return 0;
}

} // namespace

int importIntoStudy(const Arguments& arguments, const Progress& progress)
{
    const std::string bundle = arguments.option("study");
    const bool list = arguments.hasOption("list");
    if (bundle.empty() && !list)
        throw UsageError("vascusim-cli import: --study is required (or --list)");
    if (arguments.hasOption("as-label"))
        return importLabelIntoStudy(arguments, progress);
    const fs::path input = arguments.positional[0];
    std::optional<HounsfieldRescale> rescale;
    if (arguments.hasOption("rescale"))
    {
        const std::vector<double> values = parseNumbers(arguments.option("rescale"), ',', 2, "rescale");
        rescale = HounsfieldRescale{values[0], values[1]};
    }
    if (isVolumeFile(input))
    {
        study::Study study = openOrCreateStudy(arguments);
        const std::string id = study::importVolumeFile(study, input, rescale, progress);
        study.save();
        std::cout << "imported " << input.filename().string() << " as " << id << "\n";
        for (const std::string& warning : study.artifact(id).warnings)
            std::cout << "warning: " << warning << "\n";
        return 0;
    }
    const dicom::DicomScanResult scan = dicom::scanDicom(input, progress.subRange(0.0, 0.1));
    if (list)
        return listDicom(scan);
    const dicom::DicomSeries& series = app::chooseSeries(scan, arguments.option("series"));
    dicom::DicomImportOptions options;
    options.memoryLimitBytes = std::uint64_t(quantityOption(arguments, "memory-limit-mb", "", 0.0) * 1024.0 * 1024.0);
    study::Study study = openOrCreateStudy(arguments);
    const std::string id =
        app::importDicomSeriesIntoStudy(study, series, input, options, progress.subRange(0.1, 0.9), rescale);
    study.save();
    progress.report(1.0, "saved");
    const auto& artifact = study.artifact(id);
    const VolumeGeometry geometry = study.volumeGeometry(id);
    std::cout << "imported series " << series.key << " (" << series.slices.size() << " slices) as " << id << ": "
              << geometry.dims[0] << " x " << geometry.dims[1] << " x " << geometry.dims[2] << " voxels\n";
    for (const std::string& warning : scan.warnings)
        std::cout << "warning: " << warning << "\n";
    for (const std::string& warning : artifact.warnings)
        std::cout << "warning: " << warning << "\n";
    return 0;
}

int writePhantomSeries(const Arguments& arguments, const Progress& progress)
{
    const std::string out = arguments.option("out");
    const dicom::PhantomKind kind = dicom::phantomKindFromName(arguments.positional[0]);
    dicom::PhantomOptions options;
    // Patient-like unless asked otherwise; the bifurcation exists in the analytic style only.
    options.style = dicom::phantomStyleFromName(
        arguments.option("style", kind == dicom::PhantomKind::Bifurcation ? "analytic" : "patient"));
    if (arguments.hasOption("blur") && options.style == dicom::PhantomStyle::Patient)
        throw UsageError("--blur (a Gaussian sigma) belongs to --style analytic; a patient-style phantom takes --psf-fwhm");
    if (arguments.hasOption("psf-fwhm") && options.style == dicom::PhantomStyle::Analytic)
        throw UsageError("--psf-fwhm belongs to --style patient; an analytic phantom takes --blur (sigma, mm)");
    if (arguments.hasOption("psf-fwhm"))
        options.psfFwhmMm = quantityOption(arguments, "psf-fwhm", "mm", 0.8);
    if (arguments.hasOption("noise") && options.style == dicom::PhantomStyle::Patient)
        options.scannerNoiseHu = quantityOption(arguments, "noise", "HU", 20.0);
    if (arguments.hasOption("size"))
        options.size = parseTriple<int>(arguments.option("size"), 'x', "size");
    if (arguments.hasOption("spacing"))
    {
        const auto spacing = parseTriple<double>(arguments.option("spacing"), ',', "spacing");
        options.spacing = {spacing[0], spacing[1], spacing[2]};
    }
    options.noiseHu = quantityOption(arguments, "noise", "HU", options.noiseHu);
    options.seed = std::uint64_t(quantityOption(arguments, "seed", "", double(options.seed)));
    options.blurMm = quantityOption(arguments, "blur", "mm", options.blurMm);
    options.aneurysmDiameterMm = quantityOption(arguments, "max-diameter", "mm", options.aneurysmDiameterMm);
    if (arguments.hasOption("stenosis")) // A[,B]: the second a milder blockage downstream (patient style)
    {
        const std::string text = arguments.option("stenosis");
        const std::size_t comma = text.find(',');
        options.stenosisPercent = quantityText(text.substr(0, comma), "stenosis", "%");
        if (comma != std::string::npos)
            options.secondStenosisPercent = quantityText(text.substr(comma + 1), "stenosis", "%");
    }
    options.vesselDiameterMm = quantityOption(arguments, "vessel-diameter", "mm", options.vesselDiameterMm);
    options.stenosisLengthMm = quantityOption(arguments, "stenosis-length", "mm", options.stenosisLengthMm);
    if ((options.secondStenosisPercent > 0.0 || arguments.hasOption("vessel-diameter") ||
         arguments.hasOption("stenosis-length")) &&
        (kind != dicom::PhantomKind::Stenosis || options.style != dicom::PhantomStyle::Patient))
        throw UsageError("a second stenosis, --vessel-diameter and --stenosis-length belong to the patient-style "
                         "stenosis phantom");
    dicom::CtSeriesDescription description = dicom::phantomSeriesDescription(kind);
    description.transferSyntax = dicom::transferSyntaxFromName(arguments.option("transfer-syntax", "explicit-le"));
    description.enhancedMultiFrame = arguments.hasOption("enhanced");
    if (options.style == dicom::PhantomStyle::Patient)
        description.seriesDescription = "CTA late arterial phase, " + dicom::phantomKindName(kind) + " patient-like phantom";
    const dicom::PhantomFiles files = dicom::writePhantom(kind, options, description, out, progress);
    std::cout << "wrote " << files.series.files.size() << " DICOM files to " << files.dicomFolder.string() << "\n"
              << "truth: " << files.truthJson.string() << ", " << files.truthLabels.string() << "\n";
    return 0;
}


namespace {

/// Every value of a repeatable point option (x,y,z mm).
std::vector<Eigen::Vector3d> pointOptions(const Arguments& arguments, const std::string& name)
{
    std::vector<Eigen::Vector3d> points;
    for (const auto& [option, value] : arguments.options)
        if (option == name)
        {
            const auto xyz = parseTriple<double>(value, ',', name);
            points.emplace_back(xyz[0], xyz[1], xyz[2]);
        }
    return points;
}

/// segment --target: the guided segmentation from points; the label is recorded with its request.
std::string segmentFromPoints(const Arguments& arguments, study::Study& study, const std::string& imageId,
                              const CtVolume& ct, imaging::SegmentationResult& result,
                              imaging::SegmentationRequest& request, const Progress& progress)
{
    ParameterSet parameters(imaging::guidedSegmentationParameters());
    applyParameters(arguments, parameters);
    request.target = imaging::segmentationTargetFromName(arguments.option("target"));
    request.includeMm = pointOptions(arguments, "seed");
    request.excludeMm = pointOptions(arguments, "exclude");
    if (request.includeMm.empty() && request.target != imaging::SegmentationTarget::Aorta)
        throw UsageError("vascusim-cli segment --target hepatic|all needs at least one --seed x,y,z (mm) inside the "
                         "vessel (--target aorta finds the abdominal aorta itself)");
    for (const auto& [option, value] : arguments.options)
        if (option == "stop")
        {
            const std::vector<double> v = parseNumbers(value, ',', 6, "stop");
            request.stops.push_back({Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector3d(v[3], v[4], v[5])});
            if (request.stops.back().normal.norm() < 1e-9)
                throw UsageError("--stop x,y,z,nx,ny,nz: the normal must not be zero");
        }
    if (arguments.hasOption("max-length"))
        request.maxLengthMm = quantityOption(arguments, "max-length", "mm", 0.0);
    result = imaging::segmentFromPoints(ct, parameters, request, progress);
    return app::recordGuidedSegmentation(study, result, request, parameters, imageId);
}

/// segment without --target: the layered segmentation from one seed (automatic unless given).
imaging::SegmentationResult segmentFromSeed(const Arguments& arguments, const CtVolume& ct,
                                            study::Provenance& provenance, const Progress& progress)
{
    for (const char* guidedOnly : {"exclude", "stop", "max-length"})
        if (arguments.hasOption(guidedOnly))
            throw UsageError(std::string("vascusim-cli segment: --") + guidedOnly + " needs --target aorta|hepatic|all");
    const std::vector<Eigen::Vector3d> seeds = pointOptions(arguments, "seed");
    if (seeds.size() > 1)
        throw UsageError("vascusim-cli segment: several --seed points need --target aorta|hepatic|all");
    ParameterSet parameters(imaging::segmentationParameters());
    applyParameters(arguments, parameters);
    std::optional<Eigen::Vector3d> seed;
    if (!seeds.empty())
        seed = seeds.front();
    imaging::SegmentationResult result = imaging::segmentVessels(ct, parameters, seed, progress);
    provenance.parameters = parameters.valuesAsText();
    provenance.parameters["seed_mm"] = app::pointsText({result.seedMm});
    provenance.parameters["seed_found_automatically"] = result.seedFound ? "yes" : "no";
    return result;
}

} // namespace

int segmentStudy(const Arguments& arguments, const Progress& progress)
{
    study::Study study = openStudyForWriting(arguments);
    const std::string imageId = chooseArtifact(study, arguments.option("image"), study::ArtifactKind::Image,
                                               "the study has no CT image: import one first (vascusim-cli import "
                                               "<dicom folder> --study S)");
    const CtVolume ct = study.loadImage(imageId);
    const bool guided = arguments.hasOption("target");
    imaging::SegmentationResult result;
    imaging::SegmentationRequest request;
    std::string id;
    if (guided)
        id = segmentFromPoints(arguments, study, imageId, ct, result, request, progress.subRange(0.0, 0.9));
    else
    {
        study::Provenance provenance;
        provenance.command = "segment";
        provenance.inputs = {imageId};
        result = segmentFromSeed(arguments, ct, provenance, progress.subRange(0.0, 0.9));
        id = study.addLabel(result.label, storedText("Vessel lumen"), provenance, result.warnings);
    }
    study.save();
    progress.report(1.0, "saved");
    std::cout << "segmented " << imageId << " as " << id << ": " << numberText(result.figures.at("volume_ml")) << " ml";
    if (guided)
        std::cout << " (" << imaging::segmentationTargetName(request.target) << "), window "
                  << numberText(result.figures.at("lower_hu")) << ".." << numberText(result.figures.at("upper_hu"))
                  << " HU, " << numberText(result.figures.at("leaks_cut")) << " leak(s) cut, points "
                  << app::pointsText(request.includeMm.empty() ? std::vector<Eigen::Vector3d>{result.seedMm}
                                                               : request.includeMm)
                  << " mm"
                  << (result.seedFound ? " (the aorta found automatically)" : "") << "\n";
    else
        std::cout << ", boundary " << numberText(result.figures.at("threshold_hu")) << " HU (blood "
                  << numberText(result.figures.at("blood_hu")) << " HU, tissue "
                  << numberText(result.figures.at("tissue_hu")) << " HU), seed " << app::pointsText({result.seedMm})
                  << " mm" << (result.seedFound ? " (found automatically)" : "") << "\n";
    for (const auto& [key, value] : result.figures) // each point's window (HU) and lumen radius (mm)
        if (key.rfind("include_", 0) == 0 || key.rfind("exclude_", 0) == 0)
            std::cout << "  " << key << " " << numberText(value) << "\n";
    if (const auto joined = result.figures.find("points_joined_by_paths"); joined != result.figures.end() && joined->second > 0)
        std::cout << "  minimal paths on vesselness: " << numberText(joined->second) << " point(s) joined to the aorta's "
                  << "label, " << numberText(result.figures.at("path_length_mm")) << " mm of path ("
                  << numberText(result.figures.at("path_dim_mm")) << " mm below its half level), "
                  << numberText(result.figures.at("path_voxels_added")) << " voxels added\n";
    for (const std::string& warning : result.warnings)
        std::cout << "warning: " << warning << "\n";
    return 0;
}

int surfaceStudy(const Arguments& arguments, const Progress& progress)
{
    study::Study study = openStudyForWriting(arguments);
    const std::string labelId = chooseArtifact(study, arguments.option("label"), study::ArtifactKind::Label,
                                               "the study has no vessel label: run vascusim-cli segment first");
    if (arguments.hasOption("stl"))
        checkOutputFile(arguments.option("stl"), arguments.hasOption("overwrite"));
    ParameterSet parameters(mesh::surfaceParameters());
    applyParameters(arguments, parameters);
    if (arguments.hasOption("target-vertices"))
        parameters.set("target_vertices", quantityOption(arguments, "target-vertices", "", 0.0));
    const mesh::VesselSurface result =
        mesh::extractVesselSurface(study.loadLabel(labelId), 1, parameters, progress.subRange(0.0, 0.9));
    study::Provenance provenance;
    provenance.command = "surface";
    provenance.inputs = {labelId};
    provenance.parameters = parameters.valuesAsText();
    std::vector<std::string> notes;
    if (result.surface.points.size() < result.fullVertices)
        notes.push_back("decimated from " + std::to_string(result.fullVertices) + " vertices: shape error mean " +
                        numberText(result.meanErrorMm) + " mm, Hausdorff " + numberText(result.hausdorffMm) + " mm");
    const std::string id = study.addSurface(result.surface, storedText("Lumen surface"), provenance, notes);
    study.save();
    if (arguments.hasOption("stl"))
        mesh::writeStl(result.surface, arguments.option("stl"));
    progress.report(1.0, "saved");
    std::cout << "surface of " << labelId << " as " << id << ": " << result.surface.points.size() << " vertices, "
              << result.surface.triangles.size() << " triangles, " << numberText(result.surface.area()) << " mm^2\n";
    for (const std::string& note : notes)
        std::cout << note << "\n";
    return 0;
}

int skeletonStudy(const Arguments& arguments, const Progress& progress)
{
    study::Study study = openStudyForWriting(arguments);
    // Without --label, the newest lumen label: not a sac's labels nor an organ grown from points.
    const std::string labelId = arguments.hasOption("label") ? arguments.option("label") : app::newestLumenLabel(study);
    if (labelId.empty())
        throw Error("the study has no vessel label: run vascusim-cli segment first");
    if (!study.hasArtifact(labelId) || study.artifact(labelId).kind != study::ArtifactKind::Label)
        throw Error("'" + labelId + "' is not a label artifact of the study");
    ParameterSet parameters(imaging::skeletonParameters());
    applyParameters(arguments, parameters);
    const imaging::SkeletonResult result =
        imaging::extractSkeleton(study.loadLabel(labelId), 1, parameters, progress.subRange(0.0, 0.9));
    study::Provenance provenance;
    provenance.command = "skeleton";
    provenance.inputs = {labelId};
    provenance.parameters = parameters.valuesAsText();
    std::vector<std::string> notes;
    if (result.crowdedAfterVdsm > 0)
        notes.push_back(std::to_string(result.crowdedAfterVdsm) + " crowded voxels remain after VDSM");
    const std::string id = study.addSkeleton(result.graph, storedText("Vessel skeleton"), provenance, notes);
    study.save();
    progress.report(1.0, "saved");
    std::cout << "skeleton of " << labelId << " as " << id << ": " << result.graph.endpoints().size() << " endpoints, "
              << result.graph.junctions().size() << " junctions, " << result.graph.edges.size() << " edges; "
              << result.crowdedAfterThinning << " crowded voxels after thinning, " << result.crowdedAfterVdsm
              << " after VDSM, " << result.prunedBranches << " spurs pruned\n";
    for (const std::string& note : notes)
        std::cout << "warning: " << note << "\n";
    return 0;
}

int centerlineStudy(const Arguments& arguments, const Progress& progress)
{
    if (arguments.hasOption("from") != arguments.hasOption("to"))
        throw UsageError("vascusim-cli centerline: give --from and --to together");
    study::Study study = openStudyForWriting(arguments);
    const std::string skeletonId =
        chooseArtifact(study, arguments.option("skeleton"), study::ArtifactKind::Skeleton,
                       "the study has no skeleton: run vascusim-cli skeleton first");
    const std::string labelId =
        arguments.hasOption("label") ? arguments.option("label")
                                     : study.artifact(skeletonId).provenance.inputs.empty()
                                           ? chooseArtifact(study, {}, study::ArtifactKind::Label, "no vessel label")
                                           : study.artifact(skeletonId).provenance.inputs.front();
    ParameterSet parameters(imaging::centerlineParameters());
    applyParameters(arguments, parameters);
    const SkeletonGraph skeleton = study.loadSkeleton(skeletonId);
    std::optional<std::pair<int, int>> fromTo;
    if (arguments.hasOption("from"))
    {
        fromTo = std::pair<int, int>{int(quantityOption(arguments, "from", "", 0)), int(quantityOption(arguments, "to", "", 0))};
        for (int node : {fromTo->first, fromTo->second})
            if (node < 0 || node >= int(skeleton.nodes.size()))
                throw Error("no skeleton node " + std::to_string(node) + " (the skeleton has " +
                            std::to_string(skeleton.nodes.size()) + " nodes)");
    }
    const SkeletonGraph centerlines =
        imaging::extractCenterlines(study.loadLabel(labelId), 1, skeleton, parameters, fromTo, progress.subRange(0, 0.9));
    study::Provenance provenance;
    provenance.command = "centerline";
    provenance.inputs = {skeletonId, labelId};
    provenance.parameters = parameters.valuesAsText();
    if (fromTo)
        provenance.parameters["from_node"] = std::to_string(fromTo->first),
        provenance.parameters["to_node"] = std::to_string(fromTo->second);
    const std::string id = study.addSkeleton(centerlines, storedText("Centerlines"), provenance);
    study.save();
    progress.report(1.0, "saved");
    double length = 0;
    for (const auto& edge : centerlines.edges)
        length += edge.length();
    std::cout << "centerlines of " << skeletonId << " as " << id << ": " << centerlines.edges.size()
              << " paths, " << numberText(length) << " mm in all\n";
    std::string named;
    std::size_t unnamed = 0;
    for (const std::string& name : app::segmentNames(study, id, centerlines))
        if (name == imaging::kUnnamedSegment)
            ++unnamed;
        else if (named.find(name) == std::string::npos)
            named += (named.empty() ? "" : ", ") + name;
    std::cout << "anatomical names: " << (named.empty() ? "none" : named) << "; " << unnamed
              << " segment(s) unnamed (vascusim-cli rename-segment names them)\n";
    return 0;
}

int measureStudy(const Arguments& arguments, const Progress& progress)
{
    const std::string bundle = arguments.option("study");
    const study::Study study = openStudyForReading(bundle);
    const std::string centerlinesId = chooseCenterlines(study, arguments.option("centerlines"));
    const std::string labelId = arguments.hasOption("label") ? arguments.option("label")
                                                             : app::labelOfCenterlines(study, centerlinesId);
    if (labelId.empty())
        throw Error("the study has no vessel label to measure in: run vascusim-cli segment first");
    ParameterSet parameters(imaging::measurementParameters());
    applyParameters(arguments, parameters);
    const imaging::VesselMeasurements result = imaging::measureVessels(
        study.loadLabel(labelId), study.loadSkeleton(centerlinesId), parameters, progress.subRange(0.0, 0.95));

    const std::vector<std::string> names =
        app::segmentNames(study, centerlinesId, study.loadSkeleton(centerlinesId));
    const auto titleOf = [&](std::size_t index) {
        const auto& s = result.segments[index];
        return app::segmentTitle(index < names.size() ? names[index] : imaging::kUnnamedSegment, s.from, s.to);
    };
    nlohmann::json segments = nlohmann::json::array();
    for (std::size_t index = 0; index < result.segments.size(); ++index)
    {
        const imaging::SegmentMeasurements& s = result.segments[index];
        nlohmann::json sections = nlohmann::json::array();
        for (const imaging::CrossSection& c : s.sections)
            sections.push_back({{"arc_mm", c.arcLengthMm},
                                {"centre_mm", {c.centre.x(), c.centre.y(), c.centre.z()}},
                                {"area_mm2", c.areaMm2},
                                {"equivalent_diameter_mm", c.equivalentDiameterMm},
                                {"min_diameter_mm", c.minDiameterMm},
                                {"max_diameter_mm", c.maxDiameterMm},
                                {"near_junction", c.nearJunction}});
        segments.push_back({{"segment", index},
                            {"name", index < names.size() ? names[index] : std::string(imaging::kUnnamedSegment)},
                            {"from_node", s.from},
                            {"to_node", s.to},
                            {"length_mm", s.lengthMm},
                            {"start_radius_mm", s.startRadiusMm},
                            {"end_radius_mm", s.endRadiusMm},
                            {"reference_diameter_mm", s.referenceDiameterMm},
                            {"minimal_diameter_mm", s.minimalDiameterMm},
                            {"diameter_stenosis_percent", s.diameterStenosisPercent},
                            {"area_stenosis_percent", s.areaStenosisPercent},
                            {"max_diameter_mm", s.maxDiameterMm},
                            {"max_caliper_mm", s.maxCaliperMm},
                            {"sections", sections}});
    }
    const nlohmann::json document = {{"centerlines", centerlinesId},
                                     {"label", labelId},
                                     {"parameters", parameters.valuesAsText()},
                                     {"max_diameter_mm", result.maxDiameterMm},
                                     {"max_caliper_mm", result.maxCaliperMm},
                                     {"worst_stenosis_segment", result.worstStenosisSegment},
                                     {"segments", segments}};
    if (arguments.hasOption("json"))
    {
        checkOutputFile(arguments.option("json"), arguments.hasOption("overwrite"));
        std::ofstream file(arguments.option("json"), std::ios::trunc);
        file << document.dump(2) << "\n";
        if (!file.flush())
            throw Error("cannot write the measurements", {{"file", arguments.option("json")}});
    }
    progress.report(1.0, "measured");
    std::cout << "maximum lumen diameter " << numberText(result.maxDiameterMm)
              << " mm (equivalent diameter of the lumen, perpendicular to the centerline; largest caliper "
              << numberText(result.maxCaliperMm) << " mm; the AAA outer diameter: vascusim-cli sac)\n";
    if (result.worstStenosisSegment >= 0)
    {
        const auto& worst = result.segments[std::size_t(result.worstStenosisSegment)];
        std::cout << "worst narrowing " << numberText(worst.diameterStenosisPercent) << " % diameter, "
                  << numberText(worst.areaStenosisPercent) << " % area (" << titleOf(std::size_t(result.worstStenosisSegment))
                  << ", minimal " << numberText(worst.minimalDiameterMm) << " mm of reference "
                  << numberText(worst.referenceDiameterMm) << " mm, lumen equivalent diameters)\n";
    }
    for (std::size_t index = 0; index < result.segments.size(); ++index)
    {
        const imaging::SegmentMeasurements& s = result.segments[index];
        std::cout << "segment " << index << " " << titleOf(index) << ": " << numberText(s.lengthMm) << " mm, radii "
                  << numberText(s.startRadiusMm) << " -> " << numberText(s.endRadiusMm) << " mm\n";
    }
    return 0;
}

int renameSegmentInStudy(const Arguments& arguments, const Progress& progress)
{
    study::Study study = openStudyForWriting(arguments);
    const std::string centerlinesId = chooseCenterlines(study, arguments.option("centerlines"));
    const std::string text = arguments.option("segment");
    std::size_t consumed = 0;
    long index = -1;
    try
    {
        index = std::stol(text, &consumed);
    }
    catch (const std::exception&)
    {
    }
    if (consumed != text.size() || index < 0)
        throw Error("--segment takes a segment number as measure lists it (0, 1, ...)", {{"segment", text}});
    app::renameSegment(study, centerlinesId, std::size_t(index), arguments.option("name"));
    study.save();
    progress.report(1.0, "saved");
    std::cout << "segment " << index << " of " << centerlinesId << " is now named \"" << arguments.option("name")
              << "\"\n";
    return 0;
}

int writeDemoStudy(const Arguments& arguments, const Progress& progress)
{
    const fs::path bundle = arguments.option("out", app::defaultDemoStudyPath().string());
    std::cout << app::ensureDemoStudy(bundle, progress).string() << "\n";
    return 0;
}

} // namespace vsim::cli
