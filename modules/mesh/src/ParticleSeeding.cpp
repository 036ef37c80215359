#include "vsim/mesh/ParticleSeeding.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace vsim::mesh {
namespace {

/// The lattice: its corner (mm, a lattice point), spacing and points per axis.
struct Lattice
{
    Eigen::Vector3d origin;
    double spacing;
    std::array<long, 3> dims;

    std::size_t index(long i, long j, long k) const { return std::size_t(i + dims[0] * (j + dims[1] * k)); }
    Eigen::Vector3d point(long i, long j, long k) const { return origin + spacing * Eigen::Vector3d(double(i), double(j), double(k)); }
};

/// The lumen voxels' bounding box in the patient frame (mm), from their centres.
void lumenBounds(const LabelVolume& label, std::uint8_t lumen, Eigen::Vector3d& low, Eigen::Vector3d& high)
{
    const VolumeGeometry& g = label.geometry();
    low = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
    high = -low;
    bool any = false;
    for (int k = 0; k < g.dims[2]; ++k)
        for (int j = 0; j < g.dims[1]; ++j)
            for (int i = 0; i < g.dims[0]; ++i)
                if (label.at(i, j, k) == lumen)
                {
                    const Eigen::Vector3d p = g.indexToPatient(Eigen::Vector3d(i, j, k));
                    low = low.cwiseMin(p), high = high.cwiseMax(p);
                    any = true;
                }
    if (!any)
        throw Error(Pattern{"the label has no lumen voxels (value %1) to fill with particles",
                            {std::to_string(int(lumen))}});
}

/// Where a lattice point stands against the open ends: in an end's buffer (its index), cut off beyond a buffer, or
/// neither (the label decides).
struct EndPlacement
{
    enum Kind { None, Buffer, Cut } kind = None;
    std::size_t end = 0;
    Eigen::Vector3d projected = Eigen::Vector3d::Zero(); ///< a buffer point's foot on the plane, nudged into the lumen
    bool withinDisk = false;
};

EndPlacement placeAgainstEnds(const std::vector<OpenEnd>& ends, const Eigen::Vector3d& point, double wallMarginMm,
                              double nudgeMm)
{
    for (std::size_t e = 0; e < ends.size(); ++e)
    {
        const OpenEnd& end = ends[e];
        const Eigen::Vector3d offset = point - end.centreMm;
        const double s = offset.dot(end.normal);
        const double lateral = (offset - s * end.normal).norm();
        if (s >= 0.0 || lateral > end.radiusMm + wallMarginMm)
            continue;
        if (s < -end.bufferDepthMm)
            return {EndPlacement::Cut, e, {}, false};
        return {EndPlacement::Buffer, e, point - s * end.normal + nudgeMm * end.normal, lateral <= end.radiusMm};
    }
    return {};
}

} // namespace

ParticleSet seedVesselParticles(const LabelVolume& label, const ParticleSeeding& seeding)
{
    if (!(seeding.spacingMm > 0.0) || seeding.wallLayers < 1 || seeding.wallLayers > 8)
        throw Error("particle seeding needs a positive spacing and 1 to 8 wall layers");
    const VolumeGeometry& g = label.geometry();
    Eigen::Vector3d low, high;
    lumenBounds(label, seeding.lumenValue, low, high);
    const double wallMargin = (seeding.wallLayers + 1) * seeding.spacingMm;
    for (const OpenEnd& end : seeding.openEnds)
    {
        if (std::abs(end.normal.norm() - 1.0) > 1e-9 || !(end.radiusMm > 0.0) || !(end.bufferDepthMm > 0.0))
            throw Error("an open end needs a unit normal, a positive radius and a positive buffer depth");
        const Eigen::Vector3d reach = Eigen::Vector3d::Constant(end.radiusMm + wallMargin);
        for (const Eigen::Vector3d& corner : {end.centreMm, Eigen::Vector3d(end.centreMm - end.bufferDepthMm * end.normal)})
            low = low.cwiseMin(corner - reach), high = high.cwiseMax(corner + reach);
    }
    // Half a voxel beyond the lumen's centres, then the wall layers and one spacing to spare.
    const double margin = 0.5 * g.spacing.maxCoeff() + (seeding.wallLayers + 1) * seeding.spacingMm;
    Lattice lattice{low - Eigen::Vector3d::Constant(margin), seeding.spacingMm, {}};
    double points = 1.0;
    for (int a = 0; a < 3; ++a)
    {
        lattice.dims[std::size_t(a)] = long(std::ceil((high[a] - low[a] + 2.0 * margin) / seeding.spacingMm)) + 1;
        points *= double(lattice.dims[std::size_t(a)]);
    }
    if (points > double(kMaxLatticePoints))
        throw Error(Pattern{"a particle spacing of %1 mm needs %2 lattice points over the lumen: choose a larger "
                            "spacing",
                            {std::to_string(seeding.spacingMm), std::to_string(points)}});

    // Fluid: the lattice points whose nearest voxel is lumen; behind an open end, those within its disk whose foot
    // on the plane is (the extruded section), and nothing beyond the buffer. `placement`: 0 free, e + 1 in end e's
    // buffer zone, kCut beyond it.
    constexpr std::uint8_t kCut = 255;
    std::vector<std::uint8_t> fluid(std::size_t(points), 0), placement(std::size_t(points), 0);
    auto lumenAt = [&](const Eigen::Vector3d& point)
    {
        const Eigen::Vector3d index = g.patientToIndex(point);
        const int vi = int(std::lround(index.x())), vj = int(std::lround(index.y())), vk = int(std::lround(index.z()));
        return g.contains(vi, vj, vk) && label.at(vi, vj, vk) == seeding.lumenValue;
    };
    const double nudge = 0.5 * g.spacing.maxCoeff();
    for (long k = 0; k < lattice.dims[2]; ++k)
        for (long j = 0; j < lattice.dims[1]; ++j)
            for (long i = 0; i < lattice.dims[0]; ++i)
            {
                const std::size_t n = lattice.index(i, j, k);
                const Eigen::Vector3d point = lattice.point(i, j, k);
                const EndPlacement at = placeAgainstEnds(seeding.openEnds, point, wallMargin, nudge);
                if (at.kind == EndPlacement::Cut)
                    placement[n] = kCut;
                else if (at.kind == EndPlacement::Buffer)
                    placement[n] = std::uint8_t(at.end + 1), fluid[n] = at.withinDisk && lumenAt(at.projected);
                else
                    fluid[n] = lumenAt(point);
            }

    // Squared lattice distance (in spacings^2) of every point near the lumen to its nearest fluid point, splatted
    // from the fluid points on the lumen's boundary: the nearest fluid point to an outside point always is one (a
    // step from an inner point towards the outside point along its largest offset comes closer).
    const int reach = seeding.wallLayers + 1;
    constexpr std::uint8_t kFar = 255;
    std::vector<std::uint8_t> nearest(fluid.size(), kFar);
    auto isFluid = [&](long i, long j, long k) { return fluid[lattice.index(i, j, k)] != 0; };
    for (long k = 1; k + 1 < lattice.dims[2]; ++k)
        for (long j = 1; j + 1 < lattice.dims[1]; ++j)
            for (long i = 1; i + 1 < lattice.dims[0]; ++i)
            {
                if (!isFluid(i, j, k) || (isFluid(i - 1, j, k) && isFluid(i + 1, j, k) && isFluid(i, j - 1, k) &&
                                          isFluid(i, j + 1, k) && isFluid(i, j, k - 1) && isFluid(i, j, k + 1)))
                    continue;
                for (long dk = -reach; dk <= reach; ++dk)
                    for (long dj = -reach; dj <= reach; ++dj)
                        for (long di = -reach; di <= reach; ++di)
                        {
                            const long ni = i + di, nj = j + dj, nk = k + dk;
                            if (ni < 0 || nj < 0 || nk < 0 || ni >= lattice.dims[0] || nj >= lattice.dims[1] ||
                                nk >= lattice.dims[2])
                                continue;
                            std::uint8_t& d2 = nearest[lattice.index(ni, nj, nk)];
                            d2 = std::min<std::uint8_t>(d2, std::uint8_t(di * di + dj * dj + dk * dk));
                        }
            }

    ParticleSet set;
    auto& wall = set.fields["wall"];
    auto& depth = set.fields["wall_depth_mm"];
    std::vector<double> buffer;
    const double deepest = (seeding.wallLayers + 0.5) * seeding.spacingMm; // beyond the last layer's distance
    for (long k = 0; k < lattice.dims[2]; ++k)
        for (long j = 0; j < lattice.dims[1]; ++j)
            for (long i = 0; i < lattice.dims[0]; ++i)
            {
                const std::size_t n = lattice.index(i, j, k);
                const double distance = seeding.spacingMm * std::sqrt(double(nearest[n]));
                if (placement[n] == kCut || (!fluid[n] && (nearest[n] == kFar || distance >= deepest)))
                    continue;
                set.positionsMm.push_back(lattice.point(i, j, k));
                wall.push_back(fluid[n] ? 0.0 : 1.0);
                buffer.push_back(fluid[n] ? double(placement[n]) : 0.0);
                // The surface lies half a spacing beyond the last fluid particle.
                depth.push_back(fluid[n] ? 0.0 : distance - 0.5 * seeding.spacingMm);
            }
    if (!seeding.openEnds.empty())
        set.fields["open_boundary"] = std::move(buffer);
    return set;
}

} // namespace vsim::mesh
