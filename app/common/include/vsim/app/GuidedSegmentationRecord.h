#pragma once

// The guided segmentation (imaging::segmentFromPoints) as a study artifact, the same from the CLI (`segment
// --target`) and the workstation's Segmentation Points dock: the request (target, points, stop planes, length) is
// kept in the label's provenance, so that a reopened study can show its points again and run them again.

#include "vsim/core/Parameters.h"
#include "vsim/imaging/GuidedSegmentation.h"
#include "vsim/study/Study.h"

#include <optional>
#include <string>

namespace vsim::app {

/// Adds the label of a guided segmentation of image `imageId` to the study (not saved), named after its target,
/// with the request, the parameters and the warnings in its provenance; returns its id.
std::string recordGuidedSegmentation(study::Study& study, const imaging::SegmentationResult& result,
                                     const imaging::SegmentationRequest& request, const ParameterSet& parameters,
                                     const std::string& imageId);

/// The request a guided label was made with (its provenance); nullopt for a label made otherwise. The include
/// point found automatically is not returned as a point (a re-run finds it again).
std::optional<imaging::SegmentationRequest> guidedRequestOf(const study::Artifact& label);

/// "x,y,z; x,y,z" (mm) and back; throws vsim::Error for malformed text.
std::string pointsText(const std::vector<Eigen::Vector3d>& points);
std::vector<Eigen::Vector3d> pointsFromText(const std::string& text);

} // namespace vsim::app
