#pragma once

// The centerline as a choice for the views that follow it (the vessel view, the endoscope): each segment,
// "name (length mm)", and each path from the tree's inlet (the end where the lumen is widest) to an outlet
// across the junctions, "inlet name -> outlet name (length mm)"; a choice's data is its steps, edge + 1 run
// forwards or
// -(edge + 1) backwards. A choice's rotation-minimising frames (CurvedReformation.h).
#include "vsim/core/SkeletonGraph.h"
#include "vsim/imaging/CurvedReformation.h"

#include <QString>
#include <QVariantList>

#include <optional>
#include <string>
#include <utility>
#include <vector>

class QComboBox;

namespace vsim::gui {

/// A choice's steps: edge + 1 forwards, -(edge + 1) backwards.
using VesselPath = QVariantList;

/// A segment's name: its anatomical name, else "segment N".
QString segmentName(const SkeletonGraph& centerlines, const std::vector<std::string>& names, std::size_t e);

/// The paths from the inlet (the endpoint of the widest end radius) to every other endpoint across two
/// segments or more, longest first, at most `limit`.
std::vector<std::pair<VesselPath, double>> inletPaths(const SkeletonGraph& centerlines,
                                                      std::size_t limit = 12);

/// Fills `choices` with the segments of two points or more, then the inlet paths; returns the index of the
/// longest segment's choice, -1 when there is none.
int fillSegmentChoices(QComboBox* choices, const SkeletonGraph& centerlines,
                       const std::vector<std::string>& names);

/// Shows `path` as the current choice without announcing it (the owner changed the path itself).
void showSegmentChoice(QComboBox* choices, const VesselPath& path);

/// A path's points and radii, its segments joined end to start; empty for a step out of range.
std::pair<std::vector<Eigen::Vector3d>, std::vector<double>> pathPolyline(const SkeletonGraph& centerlines,
                                                                          const VesselPath& path);

/// The frames of a path every `stepMm`; none for a path out of range or shorter than one step.
std::optional<imaging::CenterlineFrames> pathFrames(const SkeletonGraph& centerlines, const VesselPath& path,
                                                    double stepMm);

/// The one segment a path runs along; -1 for a path of several (or none).
int singleSegment(const VesselPath& path);

/// A view that follows the centerline takes `path`: its frames into `frames`, `current` set, the choices
/// showing it. False (nothing changed) when it is `current` already or has no frames.
bool adoptPath(const SkeletonGraph& centerlines, const VesselPath& path, double stepMm, QComboBox* choices,
               VesselPath& current, imaging::CenterlineFrames& frames);

} // namespace vsim::gui
