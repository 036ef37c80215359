#pragma once

// The aorta of a lumen label as axial sections (AneurysmSac.h): followed slice by slice, each with its outer contour
// traced by rays, smoothed across sections, and cut perpendicular to the contour's centerline.

#include "vsim/core/ImageVolume.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace vsim::imaging::detail {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kMaxRadiusMm = 60.0;
constexpr int kRays = 360;
constexpr double kMinAorticAreaMm2 = 50.0;

/// One slice of the tracked aorta.
struct Section
{
    int k = 0;
    std::vector<std::uint32_t> lumenPixels;   ///< the aortic lumen piece (i + nx * j)
    Vector2d lumenCentre = Vector2d::Zero();  ///< continuous index (i, j)
    std::array<double, kRays> outer{};        ///< outer contour radius (mm) per degree from lumenCentre
    std::array<double, kRays> lumenEdge{};    ///< where each ray left the lumen (mm)
    Vector3d outerCentreMm = Vector3d::Zero();
    double diameterMm = 0.0, areaMm2 = 0.0, lumenAreaMm2 = 0.0, arcMm = 0.0;
    int escapedRays = 0;                      ///< rays that met no edge within kMaxRadiusMm
};


/// The 4-connected pieces of the nonzero lumen voxels of slice k.
std::vector<std::vector<std::uint32_t>> slicePieces(const LabelVolume& lumen, int k);
Eigen::Vector2d centroidOf(const std::vector<std::uint32_t>& pixels, int nx);
Section makeSection(int k, const std::vector<std::uint32_t>& pixels, int nx);

/// The aortic lumen slice by slice: from the widest piece up and down, the piece nearest the last one, until none
/// is near or it halves (the bifurcation). Superior first. Throws vsim::Error without an aorta-sized piece.
std::vector<Section> trackAorta(const LabelVolume& lumen);

/// The outer contour of one section: rays from the lumen centre, then a median filter over +-10 degrees.
void castRays(const CtVolume& ct, const LabelVolume& lumen, Section& section);

/// Per direction, the median of the outer radius over +-4 neighbouring sections: a slice through an intervertebral
/// disc or a partial-volume gap is pulled back to its neighbours.
void smoothAcrossSections(std::vector<Section>& sections);

/// The contour radius (mm) in the direction of an in-plane offset (mm), interpolated between rays.
double contourRadius(const std::array<double, kRays>& radii, const Eigen::Vector2d& offsetMm);

/// The largest caliper (mm) and area (mm2) of the cross-section perpendicular to `normal` through `centre` of the
/// contours `radii` (per section and ray, from each section's lumen centre): where the plane cuts the surface
/// between neighbouring sections' contours, ray by ray (continuous, no voxel quantization).
std::pair<double, double> perpendicularSection(const std::vector<Section>& sections, const VolumeGeometry& g,
                                               const std::array<double, kRays> Section::*radii,
                                               const Eigen::Vector3d& centre, const Eigen::Vector3d& normal);

} // namespace vsim::imaging::detail
