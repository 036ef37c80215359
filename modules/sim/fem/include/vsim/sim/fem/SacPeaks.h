#pragma once

// The wall-stress figures a clinician reads, inside the aneurysm sac only (issue 16): over the elements whose
// centroid lies in the sac (as the AAA measurement defines it: the aortic outer contour between the neck and the
// bifurcation), the 99th percentile of the element values and the maximum of the nodal (volume-weighted) field,
// with the place of that maximum as the distance along the centerline from a reference (the aorta at the lowest
// renal artery's origin) and a clock position (viewed from the feet as an axial image is read: 12 anterior, 3 the
// patient's left, 6 posterior, 9 the patient's right). A branch ostium or the iliac crotch outside the sac does not
// set them (the peak of the demo AAA sat at the left renal ostium, 100 mm above the sac).

#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/TetMesh.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace vsim::sim::fem {

/// The sac's own geometry at a wall point, for the strength model (Vande Geest 2006: ILT and NORD).
struct LocalSac
{
    double outerDiameterMm = 0.0; ///< outer wall to outer wall through the centerline, along the point's radius
    double thrombusMm = 0.0;      ///< intraluminal thrombus crossed along that radius
};

struct SacRegion
{
    /// Whether a point (mm, patient frame) lies in the sac.
    std::function<bool(const Eigen::Vector3d& pointMm)> contains;
    /// The sac's geometry at a point in it; empty: the strength takes the centerline radius and `thrombus_mm`.
    std::function<LocalSac(const Eigen::Vector3d& pointMm)> local;
    /// Where the distance along the centerline starts (mm): the aorta at the lowest renal artery's origin.
    Eigen::Vector3d referenceMm = Eigen::Vector3d::Zero();
    /// The neck's outer diameter (mm; 0: not measured): the strength's non-aneurysmal reference unless one is given.
    double neckDiameterMm = 0.0;
};

struct SacPeak
{
    std::size_t elements = 0;      ///< elements in the sac
    double percentile99 = 0.0;     ///< of the element values in the sac
    double nodalMax = 0.0;         ///< the largest nodal (volume-weighted mean of the adjacent elements) value
    Eigen::Vector3d whereMm = Eigen::Vector3d::Zero(); ///< the node of nodalMax
    double alongCenterlineMm = 0.0; ///< path length along the centerline from the reference to the nearest point
    double clockHours = 0.0;       ///< 0 < h <= 12, of the node around the centerline
};

/// Throws vsim::Error when no element lies in the sac (the sac does not belong to this wall) or the field's size
/// is not the mesh's element count.
/// Elements of the thrombus (cell field "material" 1, where the frame has one) are left out: the wall's figures.
SacPeak peakInSac(const TetMesh& frameMm, const std::vector<double>& elementValues, const SacRegion& sac,
                  const SkeletonGraph& centerlines);

/// Path length (mm) along the centerline graph between the points nearest to `fromMm` and `toMm`; -1 when they
/// are not connected.
double distanceAlongCenterline(const SkeletonGraph& centerlines, const Eigen::Vector3d& fromMm, const Eigen::Vector3d& toMm);

/// The centerline point nearest to `pointMm` and the unit direction along its edge there (over +-2 points).
struct CenterlinePlace
{
    Eigen::Vector3d pointMm = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();
};
CenterlinePlace nearestCenterlinePlace(const SkeletonGraph& centerlines, const Eigen::Vector3d& pointMm);

/// The clock position (0 < h <= 12) of `pointMm` around the centerline point nearest to it, seen from the feet.
double clockPosition(const SkeletonGraph& centerlines, const Eigen::Vector3d& pointMm);

} // namespace vsim::sim::fem
