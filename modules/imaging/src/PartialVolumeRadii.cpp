#include "vsim/imaging/PartialVolumeRadii.h"

#include "vsim/core/Error.h"

#include "BlurredTubeFit.h"
#include "TissueProfile.h"
#include "vsim/core/Localized.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

namespace vsim::imaging {
namespace {

using detail::median;
using detail::TissueProfile;

constexpr double kFirstMarginMm = 2.0; // pass 1: beyond the distance radius (its threshold bias and the blur)
constexpr double kBlurMarginMm = 1.0;  // pass 2: beyond the lumen found, plus half a voxel (3 sigma of the blur)
constexpr double kShellMm = 1.5;       // tissue sampled this far beyond the tube
/// Tubes this wide read their own blood in their core (within 0.4 radii of the axis: over 98 % of the contrast
/// through a blur of sigma 0.5 mm); thinner ones take it from the nearest such tube along the tree.
constexpr double kOwnBloodRadiusMm = 1.8;

struct Owner
{
    int edge = -1;
    float distance = 1e30f, arc = 0.0f;
    bool inTube = false; ///< within some edge's tube (not tissue for any shell)
};

constexpr double kFitMargin = 0.1;       // the first fit: the middle 80 % between the clearances
constexpr double kEndClearanceMm = 0.5; // the fit with the neighbours: this close to a fork or a free end
constexpr double kOverhangMm = 1.0;     // ... its tube 1 mm longer at both ends (its round caps off the voxels)

Eigen::Vector3d pointAt(const std::vector<Eigen::Vector3d>& path, const std::vector<double>& arc, double at)
{
    for (std::size_t i = 1; i < path.size(); ++i)
        if (arc[i] >= at)
        {
            const double t = arc[i] > arc[i - 1] ? (at - arc[i - 1]) / (arc[i] - arc[i - 1]) : 0.0;
            return path[i - 1] + std::clamp(t, 0.0, 1.0) * (path[i] - path[i - 1]);
        }
    return path.back();
}

/// The voxels each tube owns between arcs from[e] and to[e] (mm), within tube[e] of its centerline.
std::vector<detail::TubeSamples> collectSamples(const CtVolume& ct, const std::unordered_map<std::size_t, Owner>& owners,
                                                const std::vector<TissueProfile>& tissue, const std::vector<double>& tube,
                                                const std::vector<double>& from, const std::vector<double>& to)
{
    const VolumeGeometry& g = ct.geometry();
    std::vector<detail::TubeSamples> samples(tube.size());
    for (const auto& [index, owner] : owners)
    {
        const std::size_t e = std::size_t(owner.edge);
        if (owner.distance > tube[e] || owner.arc < from[e] || owner.arc > to[e])
            continue;
        const int i = int(index % std::size_t(g.dims[0])), j = int(index / std::size_t(g.dims[0]) % std::size_t(g.dims[1]));
        const int k = int(index / (std::size_t(g.dims[0]) * std::size_t(g.dims[1])));
        samples[e].points.push_back(g.indexToPatient(Eigen::Vector3d(i, j, k)));
        samples[e].values.push_back(ct.data()[index]);
        samples[e].tissue.push_back(tissue[e].at(owner.arc));
    }
    return samples;
}

/// A thin tube's fitted straight stretch between centerline arcs lo and hi (mm), extended along its line.
struct FittedLine
{
    Eigen::Vector3d start, end;
    double lo = 0.0, hi = 1.0, r1 = 0.0, r2 = 0.0;

    Eigen::Vector3d at(double s) const { return start + (s - lo) / (hi - lo) * (end - start); }
    double radiusAt(double s) const { return r1 + (r2 - r1) * (s - lo) / (hi - lo); }
};

/// The edge's radii from its fitted line: the middle and the two ends (the taper clamped: vessels taper by tens of
/// percent along a segment at most, a steeper line is noise).
void storeFit(const FittedLine& line, double length, PartialVolumeRadius& r)
{
    r.meanRadiusMm = line.radiusAt(0.5 * length);
    r.startRadiusMm = std::clamp(line.radiusAt(0.0), 0.75 * r.meanRadiusMm, 1.33 * r.meanRadiusMm);
    r.endRadiusMm = std::clamp(line.radiusAt(length), 0.75 * r.meanRadiusMm, 1.33 * r.meanRadiusMm);
}

/// The largest distance (mm) of the centerline between arcs lo and hi from a fitted straight tube's axis.
double departure(const std::vector<Eigen::Vector3d>& path, const std::vector<double>& arc, const FittedLine& line,
                 double lo, double hi)
{
    const std::vector<Eigen::Vector3d> axis{line.at(lo), line.at(hi)};
    const std::vector<double> axisArc{0.0, (axis[1] - axis[0]).norm()};
    double largest = 0.0;
    for (std::size_t i = 0; i < path.size(); ++i)
        if (arc[i] >= lo && arc[i] <= hi)
            largest = std::max(largest, detail::toPolyline(axis, axisArc, path[i]).first);
    return largest;
}

/// What one measuring pass knows of the tubes: the centerlines with their arc lengths (mm), the tubes' reach (mm),
/// the voxels' owners, blood (HU), the tissue along each tube, and the clearances of pass 1 (mm).
struct TubeVoxels
{
    const CtVolume& ct;
    const SkeletonGraph& centerlines;
    const std::vector<std::vector<double>>& arcs;
    const std::vector<double>& length;
    const std::vector<double>& lumen; ///< the radius each tube was drawn with
    const std::vector<double>& tube;
    const std::vector<double>& lower;
    const std::vector<double>& upper;
    const std::unordered_map<std::size_t, Owner>& owners;
    const std::vector<double>& blood; ///< per tube, HU
    const std::vector<TissueProfile>& tissue;
};

/// Refines the measured edges' radii with blurred-tube fits (BlurredTubeFit.h): first each tube alone on the
/// voxels of the middle 80 % between its clearances (sigma from the widest edge, then every edge with it), then each
/// nearly straight tube with its neighbours (refitWithNeighbours). The volume estimate stays where a fit fails or
/// leaves it by more than a factor of two.
class TubeFitter
{
public:
    TubeFitter(const TubeVoxels& v, std::vector<PartialVolumeRadius>& result)
        : v_(v), result_(result), edges_(result.size()), lines_(edges_), fitted_(edges_, false), models_(edges_)
    {
        for (const PartialVolumeRadius& r : result)
            volumeRadius_.push_back(r.meanRadiusMm);
    }

    void run()
    {
        std::vector<double> from(edges_, 1.0), to(edges_, 0.0);
        for (std::size_t e = 0; e < edges_; ++e)
            if (result_[e].measured)
            {
                const double margin = kFitMargin * (v_.upper[e] - v_.lower[e]);
                from[e] = v_.lower[e] + margin, to[e] = v_.upper[e] - margin;
            }
        const std::vector<detail::TubeSamples> samples = collectSamples(v_.ct, v_.owners, v_.tissue, v_.tube, from, to);
        if (!fitSigma(samples, from, to))
            return;
        for (std::size_t e = 0; e < edges_; ++e)
            if (result_[e].measured)
            {
                const auto [a, b] = detail::lumenLine(samples[e], pointAt(path(e), v_.arcs[e], from[e]),
                                                      pointAt(path(e), v_.arcs[e], to[e]), v_.blood[e]);
                fitThin(e, samples[e], from[e], to[e], a, b);
            }
        refitWithNeighbours();
    }

private:
    const std::vector<Eigen::Vector3d>& path(std::size_t e) const { return v_.centerlines.edges[e].points; }

    /// The blur's sigma from the widest measured edge (its centerline as the axis, sigma and tissue free).
    bool fitSigma(const std::vector<detail::TubeSamples>& samples, const std::vector<double>& from,
                  const std::vector<double>& to)
    {
        std::size_t widest = edges_;
        for (std::size_t e = 0; e < edges_; ++e)
            if (result_[e].measured && (widest == edges_ || volumeRadius_[e] > volumeRadius_[widest]))
                widest = e;
        if (widest == edges_)
            return false;
        const detail::TubeFit reference =
            detail::fitReferenceTube(samples[widest], path(widest), v_.arcs[widest], from[widest], to[widest], v_.blood[widest],
                                     volumeRadius_[widest], v_.tissue[widest].overall(), 0.5 * v_.ct.geometry().spacing.x());
        sigma_ = reference.sigma;
        return reference.ok && sigma_ > 0.05 && sigma_ < 3.0;
    }

    /// A thin tube's fit on `s` with its straight axis from a (arc lo) to b (arc hi); kept when it agrees with the
    /// volume estimate within a factor of two.
    void fitThin(std::size_t e, const detail::TubeSamples& s, double lo, double hi, const Eigen::Vector3d& a,
                 const Eigen::Vector3d& b)
    {
        const detail::TubeFit fit = detail::fitThinTube(s, a, b, v_.blood[e], result_[e].meanRadiusMm, sigma_);
        const double mean = 0.5 * (fit.r1 + fit.r2);
        if (!fit.ok || !(mean > 0.5 * volumeRadius_[e] && mean < 2.0 * volumeRadius_[e]))
            return;
        lines_[e] = {fit.start, fit.end, lo, hi, fit.r1, fit.r2};
        storeFit(lines_[e], v_.length[e], result_[e]);
        fitted_[e] = true;
    }

    /// Edge e's tube as its neighbours see it: the fitted line over the whole edge, or the centerline.
    void updateModel(std::size_t e)
    {
        detail::TubeModel& m = models_[e];
        if (fitted_[e])
            m.axis = {lines_[e].at(0.0), lines_[e].at(v_.length[e])}, m.arc = {0.0, v_.length[e]};
        else
            m.axis = path(e), m.arc = v_.arcs[e];
        m.startRadiusMm = result_[e].measured ? result_[e].startRadiusMm : v_.lumen[e];
        m.endRadiusMm = result_[e].measured ? result_[e].endRadiusMm : v_.lumen[e];
    }

    /// Twice over, each tube whose centerline stays within a voxel of its fitted line, again on the voxels from
    /// 0.5 mm of its ends (its line 1 mm longer, so its round caps stay off them), a voxel reading the largest
    /// occupancy of the tube and its neighbours (the tubes sharing a node with it, held as fitted) where lumens
    /// merge at a fork: near twice the voxels of a short tip, whose radius a flow split takes cubed.
    void refitWithNeighbours()
    {
        const SkeletonGraph& graph = v_.centerlines;
        std::vector<std::vector<std::size_t>> neighbours(edges_);
        for (std::size_t e = 0; e < edges_; ++e)
        {
            updateModel(e);
            for (std::size_t n = 0; n < edges_; ++n)
            {
                const auto& a = graph.edges[e];
                const auto& b = graph.edges[n];
                if (n != e && (a.from == b.from || a.from == b.to || a.to == b.from || a.to == b.to))
                    neighbours[e].push_back(n);
            }
        }
        std::vector<double> from(edges_, kEndClearanceMm), to(edges_);
        for (std::size_t e = 0; e < edges_; ++e)
            to[e] = v_.length[e] - kEndClearanceMm;
        std::vector<detail::TubeSamples> samples = collectSamples(v_.ct, v_.owners, v_.tissue, v_.tube, from, to);
        const double straightness = v_.ct.geometry().spacing.maxCoeff();
        for (int sweep = 0; sweep < 2; ++sweep)
            for (std::size_t e = 0; e < edges_; ++e)
            {
                if (!fitted_[e] || !(to[e] - from[e] > 2.0) ||
                    departure(path(e), v_.arcs[e], lines_[e], v_.lower[e], v_.upper[e]) > straightness)
                    continue;
                detail::TubeSamples& s = samples[e];
                s.floor.assign(s.points.size(), 0.0);
                for (std::size_t k = 0; k < s.points.size(); ++k)
                    for (std::size_t n : neighbours[e])
                        s.floor[k] = std::max(s.floor[k], models_[n].occupancy(s.points[k], sigma_));
                const FittedLine previous = lines_[e];
                const double lo = from[e] - kOverhangMm, hi = to[e] + kOverhangMm;
                fitThin(e, s, lo, hi, previous.at(lo), previous.at(hi));
                updateModel(e);
            }
    }

    const TubeVoxels& v_;
    std::vector<PartialVolumeRadius>& result_;
    std::size_t edges_;
    std::vector<double> volumeRadius_;
    double sigma_ = 0.0;
    std::vector<FittedLine> lines_;
    std::vector<bool> fitted_;
    std::vector<detail::TubeModel> models_;
};

/// Each tube's blood (HU): the median of its own core where it is at least kOwnBloodRadiusMm wide, else that of
/// the nearest such tube, counted in tubes along the tree (wider tubes first); where no such tube connects, the
/// widest tubes' cores together (those at least 0.6 times the widest radius).
std::vector<double> bloodAlongTree(const SkeletonGraph& centerlines, const std::vector<double>& radius,
                                   const std::vector<std::vector<double>>& cores)
{
    const std::size_t edges = centerlines.edges.size();
    const double widest = *std::max_element(radius.begin(), radius.end());
    std::vector<double> pooled;
    for (std::size_t e = 0; e < edges; ++e)
        if (radius[e] >= 0.6 * widest)
            pooled.insert(pooled.end(), cores[e].begin(), cores[e].end());
    const double fallback = median(pooled);
    std::vector<double> blood(edges, std::nan(""));
    std::vector<std::size_t> frontier;
    for (std::size_t e = 0; e < edges; ++e)
        if (radius[e] >= kOwnBloodRadiusMm && cores[e].size() >= 20)
            blood[e] = median(cores[e]), frontier.push_back(e);
    while (!frontier.empty())
    {
        std::sort(frontier.begin(), frontier.end(), [&](std::size_t a, std::size_t b) { return radius[a] > radius[b]; });
        std::vector<std::size_t> next;
        for (std::size_t e : frontier)
            for (std::size_t n = 0; n < edges; ++n)
            {
                const auto& a = centerlines.edges[e];
                const auto& b = centerlines.edges[n];
                if (std::isnan(blood[n]) && (a.from == b.from || a.from == b.to || a.to == b.from || a.to == b.to))
                    blood[n] = blood[e], next.push_back(n);
            }
        frontier = std::move(next);
    }
    for (double& b : blood)
        if (std::isnan(b))
            b = fallback;
    return blood;
}

/// One pass: every voxel within tube[e] + kShellMm of a centerline to its nearest one; the lumen volume of each
/// tube (between the clearances, in two halves) from the contrast against its shell's tissue and its blood
/// (bloodAlongTree).
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
                    const auto [distance, arc] = detail::toPolyline(points, arcs[e], g.indexToPatient(Eigen::Vector3d(i, j, k)));
                    if (distance > reach)
                        continue;
                    Owner& owner = owners[g.linearIndex(i, j, k)];
                    owner.inTube = owner.inTube || distance <= tube[e];
                    if (distance < owner.distance)
                        owner = {int(e), float(distance), float(arc), owner.inTube};
                }
        progress.report(double(e + 1) / double(edges), localized("vsim::Progress", "partial-volume radii"));
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
    // Blood: each wide tube's core; the contrast falls along the arteries (by 10 % or more from the aorta to the
    // segmental arteries), so the aorta's blood would read thin distal vessels' contrast, and radii, low. Tissue:
    // each tube's shell, away from every tube, along its length.
    std::vector<std::vector<double>> cores(edges);
    std::vector<std::vector<std::pair<float, float>>> shell(edges);
    for (const auto& [index, owner] : owners)
    {
        const double hu = ct.data()[index];
        const std::size_t e = std::size_t(owner.edge);
        if (owner.distance <= 0.4 * radius[e])
            cores[e].push_back(hu);
        if (!owner.inTube)
            shell[e].emplace_back(owner.arc, float(hu));
    }
    const std::vector<double> blood = bloodAlongTree(centerlines, radius, cores);
    std::vector<TissueProfile> tissue(edges);
    for (std::size_t e = 0; e < edges; ++e)
        tissue[e] = TissueProfile(std::move(shell[e]), length[e]);

    const double voxelVolume = g.spacing.prod();
    for (const auto& [index, owner] : owners)
    {
        const std::size_t e = std::size_t(owner.edge);
        if (owner.distance > tube[e] || owner.arc < lower[e] || owner.arc > upper[e])
            continue;
        const double level = tissue[e].at(owner.arc);
        if (blood[e] > level)
            sums[2 * e + (owner.arc >= 0.5 * (lower[e] + upper[e]) ? 1 : 0)] +=
                (ct.data()[index] - level) / (blood[e] - level) * voxelVolume;
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
    {
        const TubeVoxels voxels{ct, centerlines, arcs, length, radius, tube, lower, upper, owners, blood, tissue};
        TubeFitter(voxels, result).run();
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
