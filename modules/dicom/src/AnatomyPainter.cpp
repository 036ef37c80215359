#include "AnatomyPainter.h"

#include <algorithm>
#include <cmath>

namespace vsim::dicom::detail {
namespace {

using Eigen::Vector3d;

/// The uniform-voxel test needs a true lower bound of the distance; the cone distance over-estimates by up to
/// the taper slope times the distance, so the half diagonal is widened by this factor.
constexpr double kBoundSafety = 1.25;

struct Box
{
    Vector3d low, high;
};

Box solidBox(const Solid& solid)
{
    if (solid.type == Solid::Type::EllipticCylinder)
    {
        const Vector3d half(solid.semiAxes.x(), solid.semiAxes.y(), 0.0);
        return {Vector3d(solid.centre.x() - half.x(), solid.centre.y() - half.y(), solid.zMin),
                Vector3d(solid.centre.x() + half.x(), solid.centre.y() + half.y(), solid.zMax)};
    }
    const Vector3d half = solid.rotation.cwiseAbs() * solid.semiAxes; // extent of the rotated ellipsoid
    return {solid.centre - half, solid.centre + half};
}

Box pieceBox(const TubePiece& piece)
{
    const double r = std::max(piece.ra, piece.rb);
    return {piece.a.cwiseMin(piece.b).array() - r, piece.a.cwiseMax(piece.b).array() + r};
}

/// Calls visit(pixel, centre) for the voxels of slice `slice` whose centre lies within half a voxel of the box.
template <typename Visit>
void forEachVoxelIn(const VolumeGeometry& geometry, int slice, const Box& box, const Visit& visit)
{
    Vector3d low = Vector3d::Constant(1e300), high = Vector3d::Constant(-1e300);
    for (int corner = 0; corner < 8; ++corner)
    {
        const Vector3d p((corner & 1) ? box.high.x() : box.low.x(), (corner & 2) ? box.high.y() : box.low.y(),
                         (corner & 4) ? box.high.z() : box.low.z());
        const Vector3d index = geometry.patientToIndex(p);
        low = low.cwiseMin(index), high = high.cwiseMax(index);
    }
    if (slice < std::floor(low.z() - 0.5) || slice > std::ceil(high.z() + 0.5))
        return;
    const int i0 = std::max(0, int(std::floor(low.x() - 0.5))), i1 = std::min(geometry.dims[0] - 1, int(std::ceil(high.x() + 0.5)));
    const int j0 = std::max(0, int(std::floor(low.y() - 0.5))), j1 = std::min(geometry.dims[1] - 1, int(std::ceil(high.y() + 0.5)));
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i)
            visit(std::size_t(i) + std::size_t(geometry.dims[0]) * std::size_t(j),
                  geometry.indexToPatient(Vector3d(i, j, slice)));
}

} // namespace

double solidDistanceBound(const Solid& solid, const Vector3d& p)
{
    if (solid.type == Solid::Type::EllipticCylinder)
    {
        const double qx = (p.x() - solid.centre.x()) / solid.semiAxes.x();
        const double qy = (p.y() - solid.centre.y()) / solid.semiAxes.y();
        const double radial = (std::sqrt(qx * qx + qy * qy) - 1.0) * std::min(solid.semiAxes.x(), solid.semiAxes.y());
        return std::max({radial, solid.zMin - p.z(), p.z() - solid.zMax}); // intersection of bounds
    }
    // |grad |q|| <= 1 / (smallest semi-axis): (|q| - 1) * smallest semi-axis bounds the distance.
    const Vector3d q = (solid.rotation.transpose() * (p - solid.centre)).cwiseQuotient(solid.semiAxes);
    return (q.norm() - 1.0) * solid.semiAxes.minCoeff();
}

double pieceDistance(const TubePiece& piece, const Vector3d& p, double& t)
{
    const Vector3d axis = piece.b - piece.a;
    const double length2 = axis.squaredNorm();
    const double along = (p - piece.a).dot(axis) / length2;
    t = std::clamp(along, 0.0, 1.0);
    if (along >= 0.0 && along <= 1.0) // the frustum: perpendicular cross-sections of radius r(t)
        return (p - (piece.a + t * axis)).norm() - (piece.ra + t * (piece.rb - piece.ra));
    // Beyond an end: the sphere tangent to the frustum's cone (radius r cos(alpha), alpha the cone's half-angle),
    // which fills the joints of a bent tube without bulging past a narrower neighbour.
    const double slope = (piece.rb - piece.ra) / std::sqrt(length2);
    const double cosine = 1.0 / std::sqrt(1.0 + slope * slope);
    return along < 0.0 ? (p - piece.a).norm() - piece.ra * cosine : (p - piece.b).norm() - piece.rb * cosine;
}

SliceCanvas::SliceCanvas(const VolumeGeometry& geometry, int slice)
    : m_geometry(geometry), m_slice(slice), m_halfDiagonal(0.5 * geometry.spacing.norm() * kBoundSafety)
{
    const std::size_t pixels = std::size_t(geometry.dims[0]) * std::size_t(geometry.dims[1]);
    m_value.assign(pixels, -1000.0f); // air
    m_mixed.assign(pixels, -1);
    m_bloom.assign(pixels, 0.0f);
    for (int c = 0; c < kSubSamples; ++c)
        for (int b = 0; b < kSubSamples; ++b)
            for (int a = 0; a < kSubSamples; ++a)
            {
                const Vector3d fraction((a + 0.5) / kSubSamples - 0.5, (b + 0.5) / kSubSamples - 0.5,
                                        (c + 0.5) / kSubSamples - 0.5);
                m_subOffsets.push_back(geometry.direction * geometry.spacing.cwiseProduct(fraction));
            }
}

template <typename InsideHu>
void SliceCanvas::paintVoxel(std::size_t pixel, const Vector3d& centre, double distance, bool blooms,
                             const InsideHu& insideHu)
{
    if (distance > m_halfDiagonal)
        return;
    if (distance < -m_halfDiagonal) // wholly inside
    {
        double hu = 0.0;
        insideHu(centre, hu);
        if (blooms)
        {
            const float beneath = m_mixed[pixel] < 0 ? m_value[pixel] : [&] {
                const float* s = &m_samples[std::size_t(m_mixed[pixel]) * kSubVoxels];
                double sum = 0.0;
                for (int v = 0; v < kSubVoxels; ++v)
                    sum += s[v];
                return float(sum / kSubVoxels);
            }();
            m_bloom[pixel] = float(hu) - beneath;
            return;
        }
        m_value[pixel] = float(hu);
        m_mixed[pixel] = -1;
        return;
    }
    if (m_mixed[pixel] < 0)
    {
        m_mixed[pixel] = std::int32_t(m_samples.size() / kSubVoxels);
        m_samples.resize(m_samples.size() + kSubVoxels, m_value[pixel]);
    }
    float* samples = &m_samples[std::size_t(m_mixed[pixel]) * kSubVoxels];
    double bloom = 0.0;
    for (int v = 0; v < kSubVoxels; ++v)
    {
        double hu = 0.0;
        if (!insideHu(Vector3d(centre + m_subOffsets[v]), hu))
            continue;
        if (blooms)
            bloom += hu - samples[v];
        else
            samples[v] = float(hu);
    }
    if (blooms)
        m_bloom[pixel] = std::max(m_bloom[pixel], float(bloom / kSubVoxels));
}

void SliceCanvas::paint(const AnatomyLayer& layer)
{
    const Solid& solid = layer.solid;
    if (solid.type != Solid::Type::Tubes)
    {
        const Box box = solidBox(solid);
        forEachVoxelIn(m_geometry, m_slice, box, [&](std::size_t pixel, const Vector3d& centre) {
            paintVoxel(pixel, centre, solidDistanceBound(solid, centre), layer.blooms,
                       [&](const Vector3d& p, double& hu) {
                           hu = layer.hu;
                           return solidDistanceBound(solid, p) < 0.0;
                       });
        });
        return;
    }
    for (const TubePiece& piece : solid.pieces)
    {
        const Box box = pieceBox(piece);
        forEachVoxelIn(m_geometry, m_slice, box, [&](std::size_t pixel, const Vector3d& centre) {
            double t = 0.0;
            const double distance = pieceDistance(piece, centre, t);
            paintVoxel(pixel, centre, distance, layer.blooms, [&](const Vector3d& p, double& hu) {
                double s = 0.0;
                if (pieceDistance(piece, p, s) >= 0.0)
                    return false;
                hu = piece.huA + s * (piece.huB - piece.huA);
                return true;
            });
        });
    }
}

void SliceCanvas::resolve(float* meanHu, float* bloomExcess) const
{
    for (std::size_t pixel = 0; pixel < m_value.size(); ++pixel)
    {
        if (m_mixed[pixel] < 0)
            meanHu[pixel] = m_value[pixel];
        else
        {
            const float* s = &m_samples[std::size_t(m_mixed[pixel]) * kSubVoxels];
            double sum = 0.0;
            for (int v = 0; v < kSubVoxels; ++v)
                sum += s[v];
            meanHu[pixel] = float(sum / kSubVoxels);
        }
        bloomExcess[pixel] = m_bloom[pixel];
    }
}

void labelSlice(const AnatomyPhantom& phantom, const VolumeGeometry& geometry, int slice, std::uint8_t* out)
{
    std::fill(out, out + std::size_t(geometry.dims[0]) * std::size_t(geometry.dims[1]), label::kBackground);
    for (const AnatomyLayer& layer : phantom.layers)
    {
        const Solid& solid = layer.solid;
        if (solid.type != Solid::Type::Tubes)
        {
            forEachVoxelIn(geometry, slice, solidBox(solid), [&](std::size_t pixel, const Vector3d& p) {
                if (solidDistanceBound(solid, p) < 0.0)
                    out[pixel] = layer.label;
            });
            continue;
        }
        for (const TubePiece& piece : solid.pieces)
            forEachVoxelIn(geometry, slice, pieceBox(piece), [&](std::size_t pixel, const Vector3d& p) {
                double t = 0.0;
                if (pieceDistance(piece, p, t) < 0.0)
                    out[pixel] = layer.label;
            });
    }
}

} // namespace vsim::dicom::detail
