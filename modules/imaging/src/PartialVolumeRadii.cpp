#include "vsim/imaging/PartialVolumeRadii.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace vsim::imaging {
namespace {

constexpr double kFirstMarginMm = 2.0; // pass 1: beyond the distance radius (its threshold bias and the blur)
constexpr double kBlurMarginMm = 1.0;  // pass 2: beyond the lumen found, plus half a voxel (3 sigma of the blur)
constexpr double kShellMm = 1.5;       // tissue sampled this far beyond the tube

double median(std::vector<double> values)
{
    if (values.empty())
        return std::nan("");
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

/// Distance (mm) from p to a polyline and the arc length (mm) of the nearest point.
std::pair<double, double> toPolyline(const std::vector<Eigen::Vector3d>& path, const std::vector<double>& arc,
                                     const Eigen::Vector3d& p)
{
    double best = 1e300, at = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i)
    {
        const Eigen::Vector3d d = path[i] - path[i - 1];
        const double length2 = d.squaredNorm();
        const double t = length2 > 0.0 ? std::clamp((p - path[i - 1]).dot(d) / length2, 0.0, 1.0) : 0.0;
        const double distance = (path[i - 1] + t * d - p).squaredNorm();
        if (distance < best)
            best = distance, at = arc[i - 1] + t * (arc[i] - arc[i - 1]);
    }
    return {std::sqrt(best), at};
}

struct Owner
{
    int edge = -1;
    float distance = 1e30f, arc = 0.0f;
    bool inTube = false; ///< within some edge's tube (not tissue for any shell)
};


/// One pass: every voxel within tube[e] + kShellMm of a centerline to its nearest one; the lumen volume of each
/// tube (between the clearances, in two halves) from the contrast against its shell's tissue and the blood of the
/// widest vessels' cores.
std::vector<PartialVolumeRadius> measurePass(const CtVolume& ct, const SkeletonGraph& centerlines,
                                             const std::vector<std::vector<double>>& arcs, const std::vector<double>& length,
                                             const std::vector<double>& radius, const std::vector<double>& tube,
                                             const Progress& progress)
{
    const VolumeGeometry& g = ct.geometry();
    const std::size_t edges = centerlines.edges.size();
    std::unordered_map<std::size_t, Owner> owners;
    for (std::size_t e = 0; e < edges; ++e)
    {
        progress.throwIfCancelled();
        const auto& points = centerlines.edges[e].points;
        const double reach = tube[e] + kShellMm;
        Eigen::Vector3d low = Eigen::Vector3d::Constant(1e300), high = Eigen::Vector3d::Constant(-1e300);
        for (const Eigen::Vector3d& p : points)
            for (int corner = 0; corner < 8; ++corner)
            {
                const Eigen::Vector3d c = p + reach * Eigen::Vector3d(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
                const Eigen::Vector3d index = g.patientToIndex(c);
                low = low.cwiseMin(index), high = high.cwiseMax(index);
            }
        for (int k = std::max(0, int(std::floor(low.z()))); k <= std::min(g.dims[2] - 1, int(std::ceil(high.z()))); ++k)
            for (int j = std::max(0, int(std::floor(low.y()))); j <= std::min(g.dims[1] - 1, int(std::ceil(high.y()))); ++j)
                for (int i = std::max(0, int(std::floor(low.x()))); i <= std::min(g.dims[0] - 1, int(std::ceil(high.x()))); ++i)
                {
                    const auto [distance, arc] = toPolyline(points, arcs[e], g.indexToPatient(Eigen::Vector3d(i, j, k)));
                    if (distance > reach)
                        continue;
                    Owner& owner = owners[g.linearIndex(i, j, k)];
                    owner.inTube = owner.inTube || distance <= tube[e];
                    if (distance < owner.distance)
                        owner = {int(e), float(distance), float(arc), owner.inTube};
                }
        progress.report(double(e + 1) / double(edges), "partial-volume radii");
    }
    // Clearances. Near a junction the branches' lumens merge (at 35 degrees two 0.7 mm branches part only 2.5 mm
    // from the fork) and thinning places the junction node towards the wider parent: three radii of the widest
    // vessel there, plus 1 mm. A free end loses its blurred cap: a radius plus 1 mm.
    std::vector<double> widestAt(centerlines.nodes.size(), 0.0);
    for (std::size_t e = 0; e < edges; ++e)
        for (int node : {centerlines.edges[e].from, centerlines.edges[e].to})
            widestAt[std::size_t(node)] = std::max(widestAt[std::size_t(node)], radius[e]);
    auto clearance = [&](int node, std::size_t e) {
        return centerlines.degree(node) >= 3 ? 3.0 * widestAt[std::size_t(node)] + 1.0 : radius[e] + 1.0;
    };
    std::vector<double> lower(edges), upper(edges), sums(2 * edges, 0.0);
    for (std::size_t e = 0; e < edges; ++e)
    {
        lower[e] = clearance(centerlines.edges[e].from, e);
        upper[e] = length[e] - clearance(centerlines.edges[e].to, e);
    }
    // Blood: the cores of the widest vessels. Tissue: each half's shell, away from every tube (the background
    // changes along a vessel, e.g. where it enters a tumour).
    std::vector<double> core;
    std::vector<std::vector<double>> shell(2 * edges);
    const double widest = *std::max_element(radius.begin(), radius.end());
    for (const auto& [index, owner] : owners)
    {
        const double hu = ct.data()[index];
        const std::size_t e = std::size_t(owner.edge);
        if (radius[e] >= 0.6 * widest && owner.distance <= 0.4 * radius[e])
            core.push_back(hu);
        if (!owner.inTube && owner.arc >= lower[e] && owner.arc <= upper[e])
            shell[2 * e + (owner.arc >= 0.5 * (lower[e] + upper[e]) ? 1 : 0)].push_back(hu);
    }
    const double blood = median(core);
    std::vector<double> tissue(2 * edges);
    for (std::size_t h = 0; h < 2 * edges; ++h)
        tissue[h] = median(shell[h]);

    const double voxelVolume = g.spacing.prod();
    for (const auto& [index, owner] : owners)
    {
        const std::size_t e = std::size_t(owner.edge);
        if (owner.distance > tube[e] || owner.arc < lower[e] || owner.arc > upper[e])
            continue;
        const std::size_t h = 2 * e + (owner.arc >= 0.5 * (lower[e] + upper[e]) ? 1 : 0);
        if (blood > tissue[h])
            sums[h] += (ct.data()[index] - tissue[h]) / (blood - tissue[h]) * voxelVolume;
    }
    std::vector<PartialVolumeRadius> result(edges);
    for (std::size_t e = 0; e < edges; ++e)
    {
        PartialVolumeRadius& r = result[e];
        r.usedLengthMm = upper[e] - lower[e];
        if (r.usedLengthMm < 2.0)
            continue;
        const double half = 0.5 * r.usedLengthMm;
        const double r1 = std::sqrt(std::max(0.0, sums[2 * e]) / half / std::numbers::pi);
        const double r2 = std::sqrt(std::max(0.0, sums[2 * e + 1]) / half / std::numbers::pi);
        if (!(r1 > 0.0 && r2 > 0.0))
            continue;
        r.measured = true;
        r.meanRadiusMm = std::sqrt((sums[2 * e] + sums[2 * e + 1]) / r.usedLengthMm / std::numbers::pi);
        const double s1 = lower[e] + 0.5 * half, s2 = upper[e] - 0.5 * half, slope = (r2 - r1) / (s2 - s1);
        // Vessels taper by tens of percent along a segment at most: a steeper line is noise.
        r.startRadiusMm = std::clamp(r1 - slope * s1, 0.75 * r.meanRadiusMm, 1.33 * r.meanRadiusMm);
        r.endRadiusMm = std::clamp(r2 + slope * (length[e] - s2), 0.75 * r.meanRadiusMm, 1.33 * r.meanRadiusMm);
    }
    return result;
}

} // namespace

std::vector<PartialVolumeRadius> partialVolumeRadii(const CtVolume& ct, const SkeletonGraph& centerlines,
                                                    const Progress& progress)
{
    if (centerlines.edges.empty())
        throw Error("no centerlines to measure");
    const std::size_t edges = centerlines.edges.size();
    std::vector<std::vector<double>> arcs(edges);
    std::vector<double> radius(edges), length(edges);
    for (std::size_t e = 0; e < edges; ++e)
    {
        const auto& edge = centerlines.edges[e];
        arcs[e].assign(1, 0.0);
        for (std::size_t i = 1; i < edge.points.size(); ++i)
            arcs[e].push_back(arcs[e].back() + (edge.points[i] - edge.points[i - 1]).norm());
        length[e] = arcs[e].back();
        std::vector<double> radii(edge.radii.begin(), edge.radii.end());
        radius[e] = radii.empty() ? 1.0 : median(radii);
    }
    // Pass 1 around the segmentation's distance radii (which a threshold biases), pass 2 around the lumen pass 1
    // found: a tube only as wide as the blur needs keeps less tissue, whose estimate's error weighs with the tube.
    std::vector<double> tube(edges);
    for (std::size_t e = 0; e < edges; ++e)
        tube[e] = radius[e] + kFirstMarginMm;
    const std::vector<PartialVolumeRadius> first =
        measurePass(ct, centerlines, arcs, length, radius, tube, progress.subRange(0.0, 0.5));
    // Pass 2 also takes the clearances from pass 1's radii: the distance radii of a thresholded label can be half
    // the lumen of a thin vessel.
    const double blurMargin = kBlurMarginMm + 0.5 * ct.geometry().spacing.maxCoeff();
    std::vector<double> lumen = radius;
    for (std::size_t e = 0; e < edges; ++e)
        if (first[e].measured)
            tube[e] = first[e].meanRadiusMm + blurMargin, lumen[e] = first[e].meanRadiusMm;
    std::vector<PartialVolumeRadius> result =
        measurePass(ct, centerlines, arcs, length, lumen, tube, progress.subRange(0.5, 1.0));
    for (std::size_t e = 0; e < edges; ++e)
        if (!result[e].measured)
            result[e] = first[e];
    return result;
}

} // namespace vsim::imaging
