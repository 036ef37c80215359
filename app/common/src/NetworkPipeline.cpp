#include "vsim/app/NetworkPipeline.h"

#include "vsim/app/RunRecord.h"
#include "vsim/app/SegmentNames.h"
#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/imaging/PartialVolumeRadii.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/imaging/VesselNames.h"
#include "vsim/interop/NrrdFile.h"
#include "vsim/sim/network/FillingSolver.h"
#include "vsim/sim/network/Inlet.h"
#include "vsim/sim/network/NetworkBuild.h"
#include "vsim/study/NetworkFile.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace vsim::app {
namespace {

std::ofstream openForWriting(const std::filesystem::path& file)
{
    std::ofstream stream(file, std::ios::trunc);
    if (!stream)
        throw Error("cannot write the run file", {{"file", file.string()}});
    return stream;
}

/// The conical segment's end radii (mm): a straight line fitted (least squares) to the equivalent radii of the
/// cross-sections away from junctions, evaluated at both ends. Single sections near the ends are too noisy for
/// the model (a section at a junction takes in the branch, one at a cut vessel end loses area, and a flow split
/// goes with the radius cubed); with fewer than three good sections, the median equivalent radius at both ends,
/// else the centerline's distance radii.
std::array<double, 2> fittedEndRadii(const imaging::SegmentMeasurements& segment, const SkeletonGraph::Edge& edge)
{
    std::vector<std::pair<double, double>> samples; // arc length (mm), equivalent radius (mm)
    for (const imaging::CrossSection& section : segment.sections)
        if (!section.nearJunction && section.equivalentDiameterMm > 0.0)
            samples.emplace_back(section.arcLengthMm, 0.5 * section.equivalentDiameterMm);
    if (samples.size() < 3)
    {
        if (segment.referenceDiameterMm > 0.0)
            return {0.5 * segment.referenceDiameterMm, 0.5 * segment.referenceDiameterMm};
        return {edge.radii.front(), edge.radii.back()};
    }
    double sx = 0, sy = 0, sxx = 0, sxy = 0, smallest = 1e300;
    for (const auto& [x, y] : samples)
        sx += x, sy += y, sxx += x * x, sxy += x * y, smallest = std::min(smallest, y);
    const double n = double(samples.size()), denominator = n * sxx - sx * sx;
    const double slope = denominator > 0.0 ? (n * sxy - sx * sy) / denominator : 0.0, intercept = (sy - slope * sx) / n;
    const double floor = 0.5 * smallest; // a steep fit must not reach zero at an end
    return {std::max(floor, intercept), std::max(floor, intercept + slope * segment.lengthMm)};
}

} // namespace

std::string labelOfCenterlines(const study::Study& study, const std::string& centerlinesId)
{
    const auto& inputs = study.artifact(centerlinesId).provenance.inputs; // {skeleton, label} (the centerline step)
    if (inputs.size() > 1 && study.hasArtifact(inputs[1]) &&
        study.artifact(inputs[1]).kind == study::ArtifactKind::Label)
        return inputs[1];
    return study.newestArtifact(study::ArtifactKind::Label);
}

VesselNetwork networkFromImages(const SkeletonGraph& centerlines, const LabelVolume& label, const CtVolume* ct,
                                std::vector<std::string>& warnings, const Progress& progress,
                                const std::vector<std::string>& names)
{
    const imaging::VesselMeasurements measured = imaging::measureVessels(
        label, centerlines, ParameterSet(imaging::measurementParameters()), progress.subRange(0.0, ct ? 0.5 : 1.0));
    std::vector<std::array<double, 2>> endRadii;
    for (std::size_t e = 0; e < measured.segments.size(); ++e)
        endRadii.push_back(fittedEndRadii(measured.segments[e], centerlines.edges[e]));
    if (ct)
    {
        const std::vector<imaging::PartialVolumeRadius> radii =
            imaging::partialVolumeRadii(*ct, centerlines, progress.subRange(0.5, 1.0));
        for (std::size_t e = 0; e < radii.size(); ++e)
            if (radii[e].measured)
                endRadii[e] = {radii[e].startRadiusMm, radii[e].endRadiusMm};
    }
    return sim::network::networkFromCenterlines(centerlines, endRadii, &warnings, names);
}

VesselNetwork buildStudyNetwork(const study::Study& study, const std::string& centerlinesId,
                                std::vector<std::string>& warnings, const Progress& progress)
{
    const SkeletonGraph centerlines = study.loadSkeleton(centerlinesId);
    std::vector<std::string> names = segmentNames(study, centerlinesId, centerlines);
    for (std::string& name : names)
        if (name == imaging::kUnnamedSegment)
            name.clear();
    const std::string labelId = labelOfCenterlines(study, centerlinesId);
    if (labelId.empty())
        return sim::network::networkFromCenterlines(centerlines, {}, &warnings, names);
    // The CT the label came from (the segment step's input).
    const auto& labelInputs = study.artifact(labelId).provenance.inputs;
    std::optional<CtVolume> ct;
    if (!labelInputs.empty() && study.hasArtifact(labelInputs.front()) &&
        study.artifact(labelInputs.front()).kind == study::ArtifactKind::Image)
        ct = study.loadImage(labelInputs.front());
    return networkFromImages(centerlines, study.loadLabel(labelId), ct ? &*ct : nullptr, warnings, progress, names);
}

std::function<bool(const Eigen::Vector3d&)> volumeRegion(const study::Study& study, const std::string& artifactId,
                                                         int value)
{
    const study::ArtifactKind kind = study.artifact(artifactId).kind;
    auto regionOf = [value](const auto& volume) -> std::function<bool(const Eigen::Vector3d&)> {
        bool any = false;
        for (std::size_t i = 0; i < volume.size() && !any; ++i)
            any = value == 0 ? volume.data()[i] != 0 : volume.data()[i] == value;
        if (!any)
            throw Error(Pattern{"the tumour volume has no voxel of value %1", {std::to_string(value)}});
        return [volume, value](const Eigen::Vector3d& p) {
            const Eigen::Vector3d index = volume.geometry().patientToIndex(p);
            const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
            if (!volume.geometry().contains(i, j, k))
                return false;
            const int v = int(volume.at(i, j, k));
            return value == 0 ? v != 0 : v == value;
        };
    };
    if (kind == study::ArtifactKind::Label)
        return regionOf(study.loadLabel(artifactId));
    if (kind == study::ArtifactKind::Image)
        return regionOf(study.loadImage(artifactId));
    throw Error(Pattern{"the tumour must be a label or image artifact, not a %1", {study::kindName(kind)}});
}

LabelVolume labelArtifact(const study::Study& study, const std::string& artifactId, const std::string& what)
{
    const study::ArtifactKind kind = study.artifact(artifactId).kind;
    if (kind == study::ArtifactKind::Label)
        return study.loadLabel(artifactId);
    if (kind != study::ArtifactKind::Image)
        throw Error(Pattern{"the %1 must be a label or image artifact, not a %2", {what, study::kindName(kind)}});
    const CtVolume image = study.loadImage(artifactId);
    LabelVolume label(image.geometry());
    for (std::size_t i = 0; i < image.size(); ++i)
        label.data()[i] = std::uint8_t(std::clamp<int>(image.data()[i], 0, 255));
    return label;
}

sim::network::SharedLabel sharedLabel(const study::Study& study, const std::string& artifactId, int value,
                                      const std::string& what)
{
    return {std::make_shared<const LabelVolume>(labelArtifact(study, artifactId, what)), value};
}

void applyRecordedChoices(sim::network::NetworkRunSetup& setup, const std::map<std::string, std::string>& source)
{
    if (const auto inlet = source.find("inlet"); inlet != source.end() && !inlet->second.empty())
        setup.inletSegment = sim::network::inletSegment(setup.network, inlet->second);
    auto segments = [&](const char* key) {
        std::vector<int> list;
        const auto found = source.find(key);
        std::stringstream text(found == source.end() ? std::string() : found->second);
        for (std::string item; std::getline(text, item, ',');)
        {
            item.erase(std::remove(item.begin(), item.end(), ' '), item.end());
            if (item.empty() || !std::all_of(item.begin(), item.end(), [](unsigned char c) { return std::isdigit(c); }))
                throw Error(Pattern{"%1: '%2' is not a segment number (feeders.csv lists them)",
                                    {std::string(key), item}});
            list.push_back(std::stoi(item));
        }
        return list;
    };
    setup.feederEdits = {segments("feeders_added"), segments("feeders_removed")};
}

sim::network::NetworkRunSetup recordedNetworkSetup(const study::Study& study, const study::Artifact& run,
                                                   std::vector<std::string>& warnings, const Progress& progress)
{
    sim::network::NetworkRunSetup setup;
    const std::map<std::string, std::string>& recorded = run.provenance.parameters;
    for (const ParameterSpec& spec : setup.parameters.specs())
        if (const auto value = recorded.find(spec.key); value != recorded.end())
            setup.parameters.setFromText(spec.key + "=" + value->second);
    if (run.provenance.inputs.empty() || !study.hasArtifact(run.provenance.inputs.front()))
        throw Error("the drug run records no centerlines to run again from", {{"artifact", run.id}});
    setup.network = buildStudyNetwork(study, run.provenance.inputs.front(), warnings, progress);
    auto text = [&](const char* key) {
        const auto found = recorded.find(key);
        return found == recorded.end() ? std::string() : found->second;
    };
    auto numbers = [](const std::string& list) { // "x, y, z" -> numbers; what is not one ends the list
        std::vector<double> values;
        std::stringstream stream(list);
        for (std::string item; std::getline(stream, item, ',');)
            try
            {
                values.push_back(std::stod(item));
            }
            catch (const std::exception&)
            {
                break;
            }
        return values;
    };
    auto labelAndValue = [](const std::string& recordedLabel) { // "label-9:2" -> {"label-9", 2}
        const std::size_t colon = recordedLabel.find(':');
        return std::pair{recordedLabel.substr(0, colon), colon == std::string::npos ? 0 : std::stoi(recordedLabel.substr(colon + 1))};
    };
    applyRecordedChoices(setup, recorded);
    if (const std::string tip = text("tip"); tip.find(',') != std::string::npos)
    {
        if (const std::vector<double> xyz = numbers(tip); xyz.size() == 3)
            setup.tipPointMm = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
    }
    else if (!tip.empty() && tip != "root")
        setup.tipNode = std::stoi(tip);
    if (const std::vector<double> sphere = numbers(text("tumour_mm")); sphere.size() == 4)
        setup.tumour = sim::network::TumourSphere{Eigen::Vector3d(sphere[0], sphere[1], sphere[2]), sphere[3]}.region();
    if (const std::string label = text("tumour_label"); !label.empty())
    {
        const auto [id, value] = labelAndValue(label);
        setup.tumour = volumeRegion(study, id, value);
        if (!text("liver_label").empty())
            setup.tumourLabel = sharedLabel(study, id, value, "tumour");
    }
    if (const std::string label = text("liver_label"); !label.empty())
    {
        const auto [id, value] = labelAndValue(label);
        setup.liver = sharedLabel(study, id, value, "liver");
    }
    std::stringstream controls(text("control_points"));
    for (std::string point; std::getline(controls, point, ';');)
        if (const std::vector<double> xyz = numbers(point); xyz.size() == 3)
            setup.controlPointsMm.emplace_back(xyz[0], xyz[1], xyz[2]);
    return setup;
}

std::string networkRunDocument(const sim::network::NetworkRunResult& run, const ParameterSet& parameters,
                               const std::map<std::string, std::string>& source)
{
    nlohmann::json controls = nlohmann::json::array(), ranking = nlohmann::json::array();
    for (const sim::network::ControlPoint& c : run.controls)
        controls.push_back({{"name", c.name},
                            {"point_mm", {c.pointMm.x(), c.pointMm.y(), c.pointMm.z()}},
                            {"segment", c.segment},
                            {"drug_flow_two_phase_ml_min", c.drugFlowTwoPhaseMlMin},
                            {"drug_flow_liquid_ml_min", c.drugFlowLiquidMlMin},
                            {"drop_percent", c.dropPercent},
                            {"drop_same_pressure_percent", c.dropAtSamePressurePercent},
                            {"split_shift_percent", c.splitShiftPercent}});
    for (std::size_t i = 0; i < run.ranking.size() && i < 10; ++i)
    {
        const auto& c = run.ranking[i];
        const Eigen::Vector3d& p = run.network.nodes[std::size_t(c.node)].positionMm;
        ranking.push_back({{"node", c.node},
                           {"point_mm", {p.x(), p.y(), p.z()}},
                           {"tumour_fraction", c.tumourFraction},
                           {"depth", c.depth},
                           {"radius_mm", c.radiusMm}});
        if (c.grade != '-')
            ranking.back().update({{"grade", std::string(1, c.grade)},
                                   {"lesions_covered_percent", c.coveredPercent},
                                   {"non_target_liver_ml", c.nonTargetMl}});
    }
    nlohmann::json lesions = nlohmann::json::array(), feeders = nlohmann::json::array();
    for (std::size_t l = 0; l < run.lesions.size(); ++l)
    {
        const sim::network::Lesion& lesion = run.lesions[l];
        const sim::network::LesionCoverage& c = run.coverage->lesions[l];
        lesions.push_back({{"centre_mm", {lesion.centreMm.x(), lesion.centreMm.y(), lesion.centreMm.z()}},
                           {"longest_diameter_mm", lesion.diameterMm},
                           {"volume_ml", lesion.volumeMl},
                           {"margin_mm", lesion.marginMm},
                           {"covered_percent", c.coveredPercent},
                           {"margin_covered_percent", c.marginCoveredPercent},
                           {"grade", std::string(1, c.grade)}});
    }
    for (const sim::network::Feeder& f : run.feeders)
    {
        const auto& segment = run.network.segments[std::size_t(f.segment)];
        feeders.push_back({{"segment", f.segment},
                           {"name", sim::network::branchName(run.network, f.segment)},
                           {"nodes", {segment.from, segment.to}},
                           {"lesion", f.lesion + 1},
                           {"enters_lesion_or_margin", f.entersLesion},
                           {"entry_mm", {f.entryMm.x(), f.entryMm.y(), f.entryMm.z()}},
                           {"radius_mm", f.radiusMm},
                           {"added_by_hand", f.byHand},
                           {"reached_from_tip", f.reached},
                           {"drug_flow_ml_min", run.network.segmentFields.at("drug_flow_ml_min")[std::size_t(f.segment)]}});
    }
    nlohmann::json nonTarget = nlohmann::json::array(); // the drug leaving the liver, outlet by outlet
    if (run.perfused)
    {
        const std::vector<std::vector<int>> incident = run.network.incidentSegments();
        for (const auto& [node, share] : run.perfused->extrahepaticDrug)
            if (share > 0.0)
            {
                const int segment = incident[std::size_t(node)].front();
                nonTarget.push_back({{"outlet", node},
                                     {"name", sim::network::branchName(run.network, segment)},
                                     {"drug_percent", 100.0 * share}});
            }
    }
    return nlohmann::json{{"source", source},
                          {"metrics", run.metrics},
                          {"run_status", nlohmann::json::parse(runStatusJson(run.status))},
                          {"control_points", controls},
                          {"tumour_outlets", run.tumourOutlets},
                          {"tip_ranking", ranking},
                          {"lesions", lesions},
                          {"feeders", feeders},
                          {"extrahepatic_drug", nonTarget},
                          {"warnings", run.warnings},
                          {"parameters", parameters.valuesAsText()}}
        .dump(2);
}

NetworkRunIds addNetworkRun(study::Study& study, const sim::network::NetworkRunResult& run, const ParameterSet& parameters,
                          const std::vector<std::string>& inputs, const std::map<std::string, std::string>& source,
                          const std::vector<std::string>& moreWarnings)
{
    study::Provenance provenance;
    provenance.command = "simulate network";
    provenance.inputs = inputs;
    provenance.parameters = parameters.valuesAsText();
    for (const auto& [key, value] : source)
        provenance.parameters[key] = value;
    std::vector<std::string> warnings = moreWarnings;
    warnings.insert(warnings.end(), run.warnings.begin(), run.warnings.end());
    if (const std::string status = runStatusWarning(run.status); !status.empty())
        warnings.push_back(status);
    SolverRun filling = sim::network::fillingRun(run);
    filling.provenance.parameters = provenance.parameters;
    for (std::size_t i = 0; i < inputs.size(); ++i)
        filling.provenance.inputs[i == 0 ? "centerlines" : "input " + std::to_string(i + 1)] = inputs[i];
    NetworkRunIds ids;
    ids.run = study.addRun(filling, storedText("Drug filling"), provenance, warnings);
    const std::string id = ids.network = study.addNetwork(run.network, storedText("Drug flow"), provenance, warnings);
    std::map<std::string, std::string> attributes = runAttributes(run.metrics, run.status);
    attributes["run_artifact"] = ids.run;
    // The best tip positions, for the report.
    for (std::size_t i = 0; i < run.ranking.size() && i < kRankedTipsKept; ++i)
    {
        const sim::network::TipCandidate& c = run.ranking[i];
        const Eigen::Vector3d& p = run.network.nodes[std::size_t(c.node)].positionMm;
        const std::string prefix = "tip_rank_" + std::to_string(i + 1) + "_";
        attributes[prefix + "node"] = std::to_string(c.node);
        attributes[prefix + "x_mm"] = preciseNumberText(p.x());
        attributes[prefix + "y_mm"] = preciseNumberText(p.y());
        attributes[prefix + "z_mm"] = preciseNumberText(p.z());
        attributes[prefix + "tumour_fraction"] = preciseNumberText(c.tumourFraction);
        attributes[prefix + "depth"] = std::to_string(c.depth);
        if (c.grade != '-') // ranked by coverage (territories)
        {
            attributes[prefix + "grade"] = std::string(1, c.grade);
            attributes[prefix + "covered_percent"] = preciseNumberText(c.coveredPercent);
            attributes[prefix + "non_target_ml"] = preciseNumberText(c.nonTargetMl);
        }
    }
    study.setArtifactAttributes(id, attributes);
    return ids;
}

void writeNetworkRun(const std::filesystem::path& folder, const sim::network::NetworkRunResult& run,
                     const std::string& document)
{
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error)
        throw Error("cannot create the run folder", {{"folder", folder.string()}});
    study::writeNetworkFile(run.network, folder / "network.json");
    {
        std::ofstream csv = openForWriting(folder / "segments.csv");
        const auto& f = run.network.segmentFields;
        csv << "segment,from,to,start_radius_mm,end_radius_mm,length_mm";
        for (const auto& [name, values] : f)
            csv << "," << name;
        csv << "\n";
        for (std::size_t s = 0; s < run.network.segments.size(); ++s)
        {
            const auto& segment = run.network.segments[s];
            csv << s << "," << segment.from << "," << segment.to << "," << numberText(segment.startRadiusMm) << ","
                << numberText(segment.endRadiusMm) << "," << numberText(segment.lengthMm);
            for (const auto& [name, values] : f)
                csv << "," << numberText(values[s]);
            csv << "\n";
        }
    }
    {
        std::ofstream csv = openForWriting(folder / "outlets.csv");
        csv << "node,x_mm,y_mm,z_mm,flow_ml_min,drug_share,arrival_s\n"; // flow: blood and drug; share of the injected
        for (const auto& [node, flow] : run.twoPhase.outletFlow)
        {
            const Eigen::Vector3d& p = run.network.nodes[std::size_t(node)].positionMm;
            const double arrival = sim::network::arrivalAt(run.filling, node);
            csv << node << "," << numberText(p.x()) << "," << numberText(p.y()) << "," << numberText(p.z()) << ","
                << numberText(units::m3PerSToMlPerMin(flow)) << "," << numberText(sim::network::deliveredFraction(run.twoPhase, {node})) << ","
                << (arrival == sim::network::kNever ? std::string("-1") : numberText(arrival)) << "\n";
        }
    }
    {
        // The filling: every segment's filled length (mm, from its upstream end) at 101 times from the start of
        // the injection to the last outlet's arrival.
        std::ofstream csv = openForWriting(folder / "filling.csv");
        csv << "time_s";
        for (std::size_t s = 0; s < run.network.segments.size(); ++s)
            csv << ",segment_" << s << "_filled_mm";
        csv << "\n";
        std::vector<double> lengths;
        for (int step = 0; step <= 100; ++step)
        {
            const double time = run.filling.lastArrival * step / 100.0;
            sim::network::filledLengths(run.network, run.twoPhase, run.filling, time, lengths);
            csv << numberText(time);
            for (double length : lengths)
                csv << "," << numberText(length);
            csv << "\n";
        }
    }
    if (run.territories && run.perfused)
    {
        interop::writeNrrd(sim::network::territoryLabel(*run.territories, *run.perfused, run.lesions),
                           folder / "territory.nrrd", true);
        std::ofstream csv = openForWriting(folder / "feeders.csv");
        // entry_*_mm: patient frame (LPS), where the feeder enters the lesion or its margin (else its end nearest it)
        csv << "segment,name,from,to,lesion,enters_lesion_or_margin,added_by_hand,reached_from_tip,radius_mm,drug_flow_ml_min,"
               "entry_x_mm,entry_y_mm,entry_z_mm\n";
        for (const sim::network::Feeder& f : run.feeders)
        {
            const auto& segment = run.network.segments[std::size_t(f.segment)];
            csv << f.segment << ",\"" << sim::network::branchName(run.network, f.segment) << "\"," << segment.from << ","
                << segment.to << "," << f.lesion + 1 << ","
                << (f.entersLesion ? 1 : 0) << "," << (f.byHand ? 1 : 0) << "," << (f.reached ? 1 : 0) << ","
                << numberText(f.radiusMm) << ","
                << numberText(run.network.segmentFields.at("drug_flow_ml_min")[std::size_t(f.segment)]) << ","
                << numberText(f.entryMm.x()) << "," << numberText(f.entryMm.y()) << "," << numberText(f.entryMm.z()) << "\n";
        }
    }
    if (run.workingAngle) // DSA-like views at the working angle and from the front (8-bit PGM, the head up)
        for (const auto& [name, angles] : {std::pair{"working-view.pgm", run.workingAngle->angles},
                                           std::pair{"frontal-view.pgm", sim::network::CArmAngles{}}})
        {
            const sim::network::ProjectionImage image = sim::network::dsaProjection(run.network, run.tipNode, angles);
            std::ofstream pgm(folder / name, std::ios::binary | std::ios::trunc);
            pgm << "P5\n# VascuSim DSA-like view, LAO " << angles.laoDeg << " cranial " << angles.cranialDeg << " deg, "
                << image.pixelMm << " mm pixels\n"
                << image.width << " " << image.height << "\n255\n";
            for (float t : image.transmission)
                pgm.put(char(std::uint8_t(std::lround(255.0f * t))));
            if (!pgm.flush())
                throw Error("cannot write the run file", {{"file", (folder / name).string()}});
        }
    std::ofstream metrics = openForWriting(folder / "metrics.json");
    metrics << document << "\n";
    if (!metrics.flush())
        throw Error("cannot write metrics.json", {{"folder", folder.string()}});
}

} // namespace vsim::app
