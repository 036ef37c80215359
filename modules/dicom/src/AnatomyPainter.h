#pragma once

// The painter's algorithm of the patient-like phantoms on one axial slice: every layer in order, each voxel
// either wholly inside or outside a solid (decided from a Lipschitz bound of the signed distance at its centre) or
// sampled on 4 x 4 x 4 sub-voxels. Shared by the CT (HU per sub-voxel) and the truth labels (centre only).

#include "vsim/core/VolumeGeometry.h"
#include "vsim/dicom/AnatomyPhantom.h"

#include <cstdint>
#include <vector>

namespace vsim::dicom::detail {

/// Sub-voxels per axis.
inline constexpr int kSubSamples = 4;
inline constexpr int kSubVoxels = kSubSamples * kSubSamples * kSubSamples;

/// Signed distance bound (mm) of a solid other than tubes: |bound| <= |true distance|, the same sign.
double solidDistanceBound(const Solid& solid, const Eigen::Vector3d& p);

/// Signed distance (mm) to a cone piece's surface: within the piece, the distance to the axis minus the radius
/// there (exact perpendicular cross-sections; it over-states the true distance by at most 1 / cos(half-angle));
/// beyond its ends, spheres tangent to the cone. t in [0, 1]: the axial parameter of the nearest axis point.
double pieceDistance(const TubePiece& piece, const Eigen::Vector3d& p, double& t);

/// One slice's canvas: the mean HU of each voxel from its sub-voxel HU, and the blooming excess.
class SliceCanvas
{
public:
    SliceCanvas(const VolumeGeometry& geometry, int slice);
    void paint(const AnatomyLayer& layer);
    /// Mean HU of each voxel (row-major, columns fastest) and the blooming excess (HU, 0 where none).
    void resolve(float* meanHu, float* bloomExcess) const;

private:
    template <typename InsideHu>
    void paintVoxel(std::size_t pixel, const Eigen::Vector3d& centre, double distance, bool blooms,
                    const InsideHu& insideHu);

    const VolumeGeometry& m_geometry;
    int m_slice;
    double m_halfDiagonal;
    std::vector<Eigen::Vector3d> m_subOffsets;
    std::vector<float> m_value;        ///< HU of voxels wholly inside one region
    std::vector<std::int32_t> m_mixed; ///< index into m_samples / kSubVoxels, -1 when uniform
    std::vector<float> m_samples;      ///< kSubVoxels HU per mixed voxel
    std::vector<float> m_bloom;        ///< blooming excess HU, voxel mean
};

/// The truth label at every voxel centre of a slice, layers in order.
void labelSlice(const AnatomyPhantom& phantom, const VolumeGeometry& geometry, int slice, std::uint8_t* out);

} // namespace vsim::dicom::detail
