#include "vsim/imaging/PartialVolumeRadii.h"

#include "vsim/core/Error.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

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

/// A blurred tapering cylinder fitted to the CT around one centerline (Levenberg-Marquardt), evaluated at the voxel
/// centres themselves: intensity = tissue + (blood - tissue) Phi((r - d) / sigma) at distance d from the axis (the
/// partial-volume profile of an edge blurred by a Gaussian), the radius linear from r1 at arc `lower` to r2 at
/// `upper`. The reference vessel (the widest; `fitSigma`) keeps the centerline as its axis, shifted by (u, v), and
/// also fits sigma and the tissue level. A thin vessel fits a straight axis whose two ends move across it (a
/// smoothed centerline wanders by a third of such a radius, and may run off the lumen where it shares a stretch
/// with a neighbour), started at the contrast-weighted centres of its two halves, with sigma and the tissue fixed
/// (a free tissue level trades off against the radius of a thin tube). Neither the slab sampling of a blur finer
/// than the slices nor an axis off the lumen's centre biases the radius, as they bias a sum over slabs.
struct CylinderFit
{
    bool ok = false;
    double r1 = 0.0, r2 = 0.0, tissue = 0.0, sigma = 0.0;
};

CylinderFit fitCylinder(const std::vector<Eigen::Vector3d>& points, const std::vector<double>& values,
                        const std::vector<Eigen::Vector3d>& path, const std::vector<double>& arc, double lower, double upper,
                        double blood, double radius0, double tissue0, double sigma0, bool fitSigma)
{
    CylinderFit fit;
    if (points.size() < 30 || path.size() < 2 || !(upper > lower))
        return fit;
    // The straight axis of thin vessels: the centerline's points at `lower` and `upper`.
    auto pointAt = [&](double at) {
        for (std::size_t i = 1; i < path.size(); ++i)
            if (arc[i] >= at)
            {
                const double t = arc[i] > arc[i - 1] ? (at - arc[i - 1]) / (arc[i] - arc[i - 1]) : 0.0;
                return Eigen::Vector3d(path[i - 1] + std::clamp(t, 0.0, 1.0) * (path[i] - path[i - 1]));
            }
        return path.back();
    };
    const bool thin = !fitSigma;
    Eigen::Vector3d a0 = pointAt(lower), b0 = pointAt(upper);
    if (thin)
    {
        // Start the axis at the lumen itself: the contrast-weighted centres of the near and far halves of the voxels
        // (a centerline can run off a thin vessel where it shares a stretch with a neighbour).
        const Eigen::Vector3d direction = (b0 - a0).normalized();
        const double middle = 0.5 * (a0 + b0).dot(direction);
        Eigen::Vector3d centre[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
        double weight[2] = {0.0, 0.0};
        for (std::size_t k = 0; k < points.size(); ++k)
        {
            const double w = std::max(0.0, (values[k] - tissue0) / (blood - tissue0));
            const int half = points[k].dot(direction) >= middle ? 1 : 0;
            centre[half] += w * points[k], weight[half] += w;
        }
        if (weight[0] > 0.0 && weight[1] > 0.0)
        {
            const Eigen::Vector3d c0 = centre[0] / weight[0], c1 = centre[1] / weight[1];
            if ((c1 - c0).norm() > 0.25 * (b0 - a0).norm())
            {
                const Eigen::Vector3d d = (c1 - c0).normalized();
                a0 = c0 + (a0 - c0).dot(d) * d, b0 = c0 + (b0 - c0).dot(d) * d; // the same span, on the new line
            }
        }
    }
    const Eigen::Vector3d axis = thin ? Eigen::Vector3d((b0 - a0).normalized()) : Eigen::Vector3d((path.back() - path.front()).normalized());
    const Eigen::Vector3d f1 = axis.unitOrthogonal(), f2 = axis.cross(f1);
    // Parameters: u, v, r1, r2, then sigma and tissue (the reference) or the far end's u2, v2 (a thin vessel).
    constexpr int n = 6;
    Eigen::VectorXd x(n);
    x << 0.0, 0.0, radius0, radius0, thin ? 0.0 : sigma0, thin ? 0.0 : tissue0;
    auto residuals = [&](const Eigen::VectorXd& q, Eigen::VectorXd& out) {
        const double sigma = thin ? sigma0 : q[4], tissue = thin ? tissue0 : q[5];
        const Eigen::Vector3d offset = q[0] * f1 + q[1] * f2;
        std::vector<Eigen::Vector3d> line; // a thin vessel's axis
        std::vector<double> lineArc;
        if (thin)
            line = {a0 + offset, b0 + q[4] * f1 + q[5] * f2}, lineArc = {0.0, (line[1] - line[0]).norm()};
        out.resize(Eigen::Index(points.size()));
        for (std::size_t k = 0; k < points.size(); ++k)
        {
            // Distance to the axis and where along it (0..1 from `lower` to `upper`).
            double d = 0.0, t = 0.0;
            if (thin)
            {
                const auto [distance, s] = toPolyline(line, lineArc, points[k]);
                d = distance, t = std::clamp(s / lineArc[1], 0.0, 1.0);
            }
            else
            {
                const auto [distance, s] = toPolyline(path, arc, points[k] - offset);
                d = distance, t = std::clamp((s - lower) / (upper - lower), 0.0, 1.0);
            }
            const double r = q[2] + (q[3] - q[2]) * t;
            const double occupancy = 0.5 * std::erfc(-(r - d) / (sigma * std::numbers::sqrt2));
            out[Eigen::Index(k)] = values[k] - (tissue + (blood - tissue) * occupancy);
        }
    };
    Eigen::VectorXd r, trial;
    residuals(x, r);
    double cost = r.squaredNorm(), lambda = 1e-3;
    for (int iteration = 0; iteration < 40; ++iteration)
    {
        Eigen::MatrixXd jacobian(r.size(), n);
        for (int j = 0; j < n; ++j)
        {
            Eigen::VectorXd shifted = x;
            const double h = !thin && j == 5 ? 0.5 : 1e-4; // the tissue level in HU
            shifted[j] += h;
            residuals(shifted, trial);
            jacobian.col(j) = (trial - r) / h;
        }
        const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
        const Eigen::VectorXd gradient = jacobian.transpose() * r;
        bool improved = false;
        for (int attempt = 0; attempt < 8 && !improved; ++attempt)
        {
            Eigen::MatrixXd damped = normal;
            damped.diagonal() *= 1.0 + lambda;
            const Eigen::VectorXd step = damped.ldlt().solve(-gradient);
            const Eigen::VectorXd candidate = x + step;
            if (!(candidate[2] > 0.05 && candidate[3] > 0.05 && (thin || candidate[4] > 0.05)))
            {
                lambda *= 10.0;
                continue;
            }
            residuals(candidate, trial);
            const double candidateCost = trial.squaredNorm();
            if (candidateCost < cost)
            {
                improved = true;
                const bool converged = cost - candidateCost < 1e-10 * cost;
                x = candidate, r = trial, cost = candidateCost, lambda = std::max(1e-7, lambda / 10.0);
                if (converged)
                    iteration = 1000;
            }
            else
                lambda *= 10.0;
        }
        if (!improved)
            break;
    }
    fit.ok = std::isfinite(cost) && x[2] > 0.05 && x[3] > 0.05;
    fit.r1 = x[2], fit.r2 = x[3], fit.sigma = thin ? sigma0 : x[4], fit.tissue = thin ? tissue0 : x[5];
    return fit;
}

/// Refines each measured edge's radii with fitCylinder on the voxels of the middle 80 % of its tube between the
/// clearances (a vessel's end and a fork's merging lumens stay out): sigma from the widest edge first, then every
/// edge with it; the volume estimate stays where a fit fails or leaves it by more than a factor of two.
void fitCylinders(const CtVolume& ct, const SkeletonGraph& centerlines, const std::vector<std::vector<double>>& arcs,
                  const std::vector<double>& length, const std::vector<double>& tube, const std::vector<double>& lower,
                  const std::vector<double>& upper, const std::unordered_map<std::size_t, Owner>& owners, double blood,
                  const std::vector<double>& tissue, std::vector<PartialVolumeRadius>& result)
{
    const VolumeGeometry& g = ct.geometry();
    const std::size_t edges = result.size();
    std::vector<std::vector<Eigen::Vector3d>> points(edges);
    std::vector<std::vector<double>> values(edges);
    for (const auto& [index, owner] : owners)
    {
        const std::size_t e = std::size_t(owner.edge);
        const double margin = 0.1 * (upper[e] - lower[e]);
        if (!result[e].measured || owner.distance > tube[e] || owner.arc < lower[e] + margin || owner.arc > upper[e] - margin)
            continue;
        const int i = int(index % std::size_t(g.dims[0])), j = int(index / std::size_t(g.dims[0]) % std::size_t(g.dims[1]));
        const int k = int(index / (std::size_t(g.dims[0]) * std::size_t(g.dims[1])));
        points[e].push_back(g.indexToPatient(Eigen::Vector3d(i, j, k)));
        values[e].push_back(ct.data()[index]);
    }
    std::size_t widest = edges;
    for (std::size_t e = 0; e < edges; ++e)
        if (result[e].measured && (widest == edges || result[e].meanRadiusMm > result[widest].meanRadiusMm))
            widest = e;
    if (widest == edges)
        return;
    auto tissueOf = [&](std::size_t e) { return 0.5 * (tissue[2 * e] + tissue[2 * e + 1]); };
    const CylinderFit reference =
        fitCylinder(points[widest], values[widest], centerlines.edges[widest].points, arcs[widest], lower[widest],
                    upper[widest], blood, result[widest].meanRadiusMm, tissueOf(widest), 0.5 * g.spacing.x(), true);
    if (!reference.ok || !(reference.sigma > 0.05 && reference.sigma < 3.0))
        return;
    for (std::size_t e = 0; e < edges; ++e)
    {
        if (!result[e].measured)
            continue;
        const CylinderFit fit = fitCylinder(points[e], values[e], centerlines.edges[e].points, arcs[e], lower[e], upper[e],
                                            blood, result[e].meanRadiusMm, tissueOf(e), reference.sigma, false);
        const double mean = 0.5 * (fit.r1 + fit.r2);
        if (!fit.ok || !(mean > 0.5 * result[e].meanRadiusMm && mean < 2.0 * result[e].meanRadiusMm))
            continue; // keep the volume estimate
        // r1 and r2 are the radii at `lower` and `upper`: the segment's middle and ends along that line (the
        // taper clamped as elsewhere).
        PartialVolumeRadius& r = result[e];
        const double slope = (fit.r2 - fit.r1) / (upper[e] - lower[e]);
        r.meanRadiusMm = fit.r1 + slope * (0.5 * length[e] - lower[e]);
        r.startRadiusMm = std::clamp(fit.r1 - slope * lower[e], 0.75 * r.meanRadiusMm, 1.33 * r.meanRadiusMm);
        r.endRadiusMm = std::clamp(fit.r2 + slope * (length[e] - upper[e]), 0.75 * r.meanRadiusMm, 1.33 * r.meanRadiusMm);
    }
}

/// One pass: every voxel within tube[e] + kShellMm of a centerline to its nearest one; the lumen volume of each
/// tube (between the clearances, in two halves) from the contrast against its shell's tissue and the blood of the
/// widest vessels' cores.
std::vector<PartialVolumeRadius> measurePass(const CtVolume& ct, const SkeletonGraph& centerlines,
                                             const std::vector<std::vector<double>>& arcs, const std::vector<double>& length,
                                             const std::vector<double>& radius, const std::vector<double>& tube,
                                             bool fitModel, const Progress& progress)
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
    if (fitModel)
        fitCylinders(ct, centerlines, arcs, length, tube, lower, upper, owners, blood, tissue, result);
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
        measurePass(ct, centerlines, arcs, length, radius, tube, false, progress.subRange(0.0, 0.5));
    // Pass 2 also takes the clearances from pass 1's radii: the distance radii of a thresholded label can be half
    // the lumen of a thin vessel.
    const double blurMargin = kBlurMarginMm + 0.5 * ct.geometry().spacing.maxCoeff();
    std::vector<double> lumen = radius;
    for (std::size_t e = 0; e < edges; ++e)
        if (first[e].measured)
            tube[e] = first[e].meanRadiusMm + blurMargin, lumen[e] = first[e].meanRadiusMm;
    std::vector<PartialVolumeRadius> result =
        measurePass(ct, centerlines, arcs, length, lumen, tube, true, progress.subRange(0.5, 1.0));
    for (std::size_t e = 0; e < edges; ++e)
        if (!result[e].measured)
            result[e] = first[e];
    return result;
}

} // namespace vsim::imaging
