#pragma once

// The blurred-tube model behind the partial-volume radii (PartialVolumeRadii.cpp): a vessel is a tube whose radius
// runs linearly along its axis, seen through a Gaussian blur, so a voxel at distance d from the axis reads
// tissue + (blood - tissue) x the blurred disc's occupancy at d (BlurredDisc.h: a disc of radius r convolved with a
// 2D Gaussian of sigma). Near a fork the lumens merge: a voxel reads the largest occupancy of the tubes around it
// (`TubeSamples::floor` carries the neighbours' share, held fixed while one tube is fitted). Lengths in mm,
// intensities in HU.

#include <Eigen/Core>

#include <utility>
#include <vector>

namespace vsim::imaging::detail {

/// Distance (mm) from p to a polyline and the arc length (mm) of the nearest point on it (clamped to its ends).
std::pair<double, double> toPolyline(const std::vector<Eigen::Vector3d>& path, const std::vector<double>& arc,
                                     const Eigen::Vector3d& p);

/// The blurred occupancy of a tube of radius r at distance d from its axis (BlurredDisc.h); r below 0 reads as 0.
double blurredOccupancy(double radius, double distance, double sigma);

/// A fitted tube: its axis (a polyline; two points for a straight tube) with the radius linear in arc length from
/// startRadiusMm to endRadiusMm, and round caps past its ends.
struct TubeModel
{
    std::vector<Eigen::Vector3d> axis;
    std::vector<double> arc;
    double startRadiusMm = 0.0, endRadiusMm = 0.0;

    double occupancy(const Eigen::Vector3d& p, double sigma) const;
};

/// The voxels a tube is fitted to (centres in patient mm, HU), and the occupancy its neighbours give each of them.
struct TubeSamples
{
    std::vector<Eigen::Vector3d> points;
    std::vector<double> values;
    std::vector<double> tissue; ///< the tissue level around each point, HU (the background changes along a vessel,
                                ///< e.g. where it enters a tumour)
    std::vector<double> floor;  ///< empty: no neighbours
};

struct TubeFit
{
    bool ok = false;
    double r1 = 0.0, r2 = 0.0; ///< radii at the two ends of the fitted stretch, mm
    double tissue = 0.0, sigma = 0.0;
    Eigen::Vector3d start = Eigen::Vector3d::Zero(), end = Eigen::Vector3d::Zero(); ///< a straight tube's axis ends
};

/// The reference vessel (the widest): the centerline `path` shifted across itself as the axis, the radius linear
/// from r1 at arc `lower` to r2 at `upper`; fits the shift, the radii, sigma and the tissue level
/// (Levenberg-Marquardt on the voxel centres themselves, so neither slab sampling nor an axis off the lumen's centre
/// biases the radius). The one tissue level fitted here stands in for `samples.tissue`.
TubeFit fitReferenceTube(const TubeSamples& samples, const std::vector<Eigen::Vector3d>& path,
                         const std::vector<double>& arc, double lower, double upper, double blood, double radius0,
                         double tissue0, double sigma0);

/// A thin vessel: a straight axis from `start` to `end` whose two ends move across it (a smoothed centerline
/// wanders by a third of such a radius), the radius linear from r1 at `start` to r2 at `end`; sigma and the tissue
/// (`samples.tissue`) are held (a free tissue level trades off against the radius of a thin tube).
TubeFit fitThinTube(const TubeSamples& samples, const Eigen::Vector3d& start, const Eigen::Vector3d& end, double blood,
                    double radius0, double sigma);

/// The line through the contrast-weighted centres of the near and far halves of the samples, spanning the same
/// stretch as start..end: where a centerline runs off a thin vessel (it may share a stretch with a neighbour), the
/// lumen itself. Returns start..end unchanged when the halves carry no contrast.
std::pair<Eigen::Vector3d, Eigen::Vector3d> lumenLine(const TubeSamples& samples, const Eigen::Vector3d& start,
                                                      const Eigen::Vector3d& end, double blood);

} // namespace vsim::imaging::detail
