#pragma once

// A working C-arm angle for the catheter's path (issue 19, item 4): the path from the common hepatic artery when
// the tree names it, else from the tree's root (where the guiding catheter sits), to the tip, seen with the least foreshortening and the least overlap with the rest of
// the tree, which the contrast injected at the root opacifies.
//
// Angles (patient supine): LAO positive / RAO negative rotates the detector towards the patient's left / right,
// cranial positive / caudal negative tilts it towards the head / feet. The detector's direction from the
// isocentre in the patient frame (LPS) is d = (sin a cos b, -cos a cos b, sin b) for LAO a and cranial b: at 0 / 0
// the detector is anterior (an AP view). Images are shown as radiologists read them: the head up, the patient's
// left on the right at 0 / 0.
//
// Objective: foreshortening + overlap, both fractions of the path:
//   foreshortening = 1 - (projected length / length) over the path's pieces (Dumay et al., IEEE TMI 1994);
//   overlap = the share of points along the path (every 0.5 mm, the last 3 mm before the tip left out) whose
//   projection falls on another vessel's projection (within the two radii) while the two are apart in 3D (by the
//   two radii and 1 mm: where a branch leaves the path is no overlap).
// Search: 5 degree steps over the C-arm's range, then 1 and 0.25 degree steps around the best.

#include "vsim/core/Progress.h"
#include "vsim/core/VesselNetwork.h"

#include <vector>

namespace vsim::sim::network {

struct CArmAngles
{
    double laoDeg = 0.0;     ///< + LAO, - RAO
    double cranialDeg = 0.0; ///< + cranial, - caudal
};

/// The detector's direction from the isocentre (LPS, unit) for a C-arm position.
Eigen::Vector3d detectorDirection(const CArmAngles& angles);

struct ViewQuality
{
    double foreshortening = 0.0; ///< 0 .. 1
    double overlap = 0.0;        ///< 0 .. 1
    double objective() const { return foreshortening + overlap; }
};

/// The path and the tree as the views see them: pieces with radii (mm).
struct AngleScene
{
    struct Piece
    {
        Eigen::Vector3d a, b;
        double radiusMm = 0.0;
        int segment = -1;
    };
    std::vector<Piece> path;                 ///< the path's start to the tip
    std::vector<Piece> others;               ///< every other vessel the contrast opacifies (beyond the guiding vessel)
    std::vector<std::pair<Eigen::Vector3d, double>> samples; ///< along the path (point, radius), the tip's end left out
    int start = -1;                          ///< the path's first node
};

/// The path's name where the guiding catheter sits (issue 19: "the path from the common hepatic artery").
inline constexpr const char* kGuidingVessel = "common hepatic artery";

/// The scene of the path to `tipNode` from the upper end of the segment named kGuidingVessel on it (any case),
/// else from `network`'s root. Throws vsim::Error for a tip at the path's start.
AngleScene angleScene(const VesselNetwork& network, int tipNode);

/// The quality of the view along `direction` (unit).
ViewQuality viewQuality(const AngleScene& scene, const Eigen::Vector3d& direction);

struct WorkingAngle
{
    CArmAngles angles;
    ViewQuality quality;
    ViewQuality frontal; ///< at 0 / 0, for comparison
    int evaluated = 0;   ///< views evaluated
    int pathStart = -1;  ///< the path's first node (AngleScene::start)
};

/// The C-arm's range searched: |LAO/RAO| <= 60 and |cranial/caudal| <= 40 degrees.
inline constexpr double kLaoRangeDeg = 60.0;
inline constexpr double kCranialRangeDeg = 40.0;

/// The working angle for the path to `tipNode` (see above).
WorkingAngle workingAngle(const VesselNetwork& network, int tipNode, const Progress& progress = {});

/// A DSA-like projection: every vessel of the tree as contrast-filled tubes seen along the C-arm's beam at
/// `angles`, white background, vessels dark (transmission exp(-0.1 / mm x the iodinated path length, summed over
/// the vessels a ray crosses), the path to the tip twice as dense; `pixelMm` square pixels over the tree's
/// projected extent and a 5 mm border.
struct ProjectionImage
{
    int width = 0, height = 0;
    double pixelMm = 0.0;
    std::vector<float> transmission; ///< 0 .. 1, row by row from the top (the head)
};
ProjectionImage dsaProjection(const VesselNetwork& network, int tipNode, const CArmAngles& angles, double pixelMm = 0.3);

/// The image-plane axes for a view: right and up (unit, LPS), as the image is shown.
std::pair<Eigen::Vector3d, Eigen::Vector3d> imageAxes(const Eigen::Vector3d& direction);

} // namespace vsim::sim::network
