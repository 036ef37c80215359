#pragma once

// Views along a vessel: the centerline resampled by arc length with rotation-minimising frames (double reflection,
// Wang et al., ACM TOG 27(1) 2008), the straightened curved planar reformation (Kanitsar et al., IEEE Visualization
// 2002: each row one point of the centerline, the columns across it along a direction that turns about the
// centerline by an angle the user sets) and the cross-section perpendicular to the centerline at an arc position.
// The CT is sampled trilinearly in the patient frame (mm); outside the volume -1024 HU.

#include "vsim/core/ImageVolume.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace vsim::imaging {

/// A centerline resampled every `stepMm` of arc with a rotation-minimising frame at each point.
struct CenterlineFrames
{
    double stepMm = 0.5;
    std::vector<double> arcMm;            ///< from the start
    std::vector<Eigen::Vector3d> points;  ///< mm, LPS
    std::vector<Eigen::Vector3d> tangents, normals, binormals; ///< unit, right-handed (t, n, b)
    std::vector<double> radiiMm;          ///< lumen radius interpolated from the polyline's
    double lengthMm() const { return arcMm.empty() ? 0.0 : arcMm.back(); }
    /// The index nearest an arc position (clamped to the path).
    std::size_t indexAt(double arcMm) const;
};

/// Resamples `polyline` (at least two distinct points) with `radiiMm` (one per point, or empty) every `stepMm`.
/// Throws vsim::Error for a path shorter than one step.
CenterlineFrames centerlineFrames(const std::vector<Eigen::Vector3d>& polyline, const std::vector<double>& radiiMm,
                                  double stepMm);

/// A 2D picture of CT values (HU), row-major from the top row, square pixels of `pixelMm`.
struct PlaneImage
{
    int width = 0, height = 0;
    double pixelMm = 0.5;
    std::vector<float> values;
    float at(int column, int row) const { return values[std::size_t(row) * std::size_t(width) + std::size_t(column)]; }
};

/// Trilinear CT value at a patient point (mm); -1024 outside the volume.
double sampleTrilinear(const CtVolume& ct, const Eigen::Vector3d& pointMm);

/// The direction across the centerline at frame `i` turned by `angleDegrees` from the normal towards the binormal.
Eigen::Vector3d acrossDirection(const CenterlineFrames& frames, std::size_t i, double angleDegrees);

/// Straightened CPR: row r is the centerline point r (top: the start), column c the offset
/// (c - (width - 1) / 2) * step along acrossDirection(r, angle); width covers +-halfWidthMm.
PlaneImage straightenedReformation(const CtVolume& ct, const CenterlineFrames& frames, double halfWidthMm, double angleDegrees);

/// The plane perpendicular to the centerline at `arcMm`: columns along acrossDirection(angle), rows (top to bottom)
/// along minus the direction 90 degrees further, centred on the centerline, +-halfWidthMm, pixels of `pixelMm`.
PlaneImage crossSection(const CtVolume& ct, const CenterlineFrames& frames, double arcMm, double halfWidthMm, double pixelMm,
                        double angleDegrees);

/// The same plane through a label volume: each pixel the label of the voxel nearest its point (0 outside).
PlaneImage labelCrossSection(const LabelVolume& labels, const CenterlineFrames& frames, double arcMm, double halfWidthMm,
                             double pixelMm, double angleDegrees);

/// The largest caliper (Feret diameter) of a plane's labelled region about its centre pixel: the farthest pair of its
/// boundary pixels (4-connected region of nonzero pixels), ends in mm from the top-left pixel's centre, the length
/// reaching their outer edges. None when the centre pixel is not labelled.
struct PlaneCaliper
{
    Eigen::Vector2d fromMm = Eigen::Vector2d::Zero(), toMm = Eigen::Vector2d::Zero();
    double lengthMm = 0.0;
};
std::optional<PlaneCaliper> largestCaliper(const PlaneImage& labels);

} // namespace vsim::imaging
