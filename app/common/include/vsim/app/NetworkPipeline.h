#pragma once

// The drug-delivery steps as the CLI and the workstation both run them: a study's vessel network (centerlines with
// end radii from the CT's partial-volume contrast, else the label's cross-sections), a network run added to the
// study, and its files.

#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/VesselNetwork.h"
#include "vsim/sim/network/NetworkRun.h"
#include "vsim/study/Study.h"

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace vsim::app {

/// The vessel label the centerlines were extracted from (their provenance), else the newest label; "" if none.
std::string labelOfCenterlines(const study::Study& study, const std::string& centerlinesId);

/// One conical segment per centerline, lengths along the centerlines. End radii from the CT the label was segmented
/// from (imaging::partialVolumeRadii) where `ct` is given and a segment is long enough between its clearances, else
/// a line through the equivalent radii of the label's cross-sections away from junctions (imaging::measureVessels).
/// Loops of the skeleton are broken at their thinnest segment, each named in `warnings`.
VesselNetwork networkFromImages(const SkeletonGraph& centerlines, const LabelVolume& label, const CtVolume* ct,
                                std::vector<std::string>& warnings, const Progress& progress = {},
                                const std::vector<std::string>& names = {});

/// networkFromImages on the study's centerlines, the label they came from and that label's source image; the
/// segments carry the centerlines' anatomical names (app::segmentNames, "unnamed" left empty).
VesselNetwork buildStudyNetwork(const study::Study& study, const std::string& centerlinesId,
                                std::vector<std::string>& warnings, const Progress& progress = {});

/// A tumour region from a label or image artifact: the points whose nearest voxel holds `value` (any non-zero
/// value when 0). Throws vsim::Error for another kind of artifact or no such voxel.
std::function<bool(const Eigen::Vector3d&)> volumeRegion(const study::Study& study, const std::string& artifactId,
                                                         int value);

/// A label artifact's volume, or an image artifact's as a label (its values cut to 0-255); `what` names it in
/// the message for any other kind.
LabelVolume labelArtifact(const study::Study& study, const std::string& artifactId, const std::string& what);

/// labelArtifact shared, with the value marking the region (0: any non-zero), for a run's setup.
sim::network::SharedLabel sharedLabel(const study::Study& study, const std::string& artifactId, int value,
                                      const std::string& what);

/// The choices a run's source records beside its tip and labels, as the CLI and the workstation record them and a
/// reopened study runs them again: "inlet" (a segment's name or number: NetworkRunSetup::inletSegment, resolved on
/// `setup.network`), "feeders_added" and "feeders_removed" (segment numbers, comma-separated). Throws vsim::Error
/// for an unknown inlet or a list that is not whole numbers.
void applyRecordedChoices(sim::network::NetworkRunSetup& setup, const std::map<std::string, std::string>& source);

/// The setup a recorded drug run (its network artifact) was run with, to run it again (reopening, the report): the
/// study's network from the same centerlines, the recorded parameters, tip, tumour (sphere or label), liver label,
/// control points and applyRecordedChoices. `warnings` gets the network's. Throws vsim::Error for a run with no
/// centerlines recorded (a hand-written network) or a label that is gone.
sim::network::NetworkRunSetup recordedNetworkSetup(const study::Study& study, const study::Artifact& run,
                                                   std::vector<std::string>& warnings, const Progress& progress = {});

/// What a run report shows of a network run (metrics, control points, the ten best tip positions, warnings) as
/// JSON text; `source` names where the network came from.
std::string networkRunDocument(const sim::network::NetworkRunResult& run, const ParameterSet& parameters,
                               const std::map<std::string, std::string>& source);

/// How many of the best tip positions a network run keeps in the study (attributes tip_rank_<k>_node, _x_mm, _y_mm,
/// _z_mm, _tumour_fraction, _depth).
inline constexpr std::size_t kRankedTipsKept = 5;

/// Adds the solved network ("Drug flow") with its per-segment fields to the study, the metrics as attributes and
/// `source` (inputs, tip, tumour) in the provenance, the run's warnings and `moreWarnings`, and its filling over time
/// ("Drug filling", a Run artifact of 101 frames: sim::network::fillingRun; the network's attribute run_artifact
/// names it). The study is not saved.
struct NetworkRunIds
{
    std::string network; ///< the solved network (the report's and the panel's)
    std::string run;     ///< the filling over time (the player's and ParaView's)
};
NetworkRunIds addNetworkRun(study::Study& study, const sim::network::NetworkRunResult& run, const ParameterSet& parameters,
                          const std::vector<std::string>& inputs, const std::map<std::string, std::string>& source,
                          const std::vector<std::string>& moreWarnings = {});

/// Writes a run into `folder`: network.json (the solved network with its fields), segments.csv (per segment:
/// flow, drug flow, pressures, velocity, Reynolds number, filling times), outlets.csv (flow share and arrival
/// time per outlet), filling.csv (every segment's filled length at 101 times up to the last arrival),
/// metrics.json (`document`), with a liver territory.nrrd (sim::network::territoryLabel) and feeders.csv, and
/// with a working angle working-view.pgm and frontal-view.pgm (sim::network::dsaProjection). Throws vsim::Error when a file cannot be written.
void writeNetworkRun(const std::filesystem::path& folder, const sim::network::NetworkRunResult& run,
                     const std::string& document);

} // namespace vsim::app
