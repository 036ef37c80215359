#include "vsim/imaging/OrganGrowing.h"

#include "GuidedHelpers.h"
#include "MaskOps.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Median.h"
#include "vsim/core/StoredText.h"

#include <algorithm>
#include <cmath>

namespace vsim::imaging {
namespace {

/// A box of the CT: its first voxel and its size.
struct Box
{
    std::array<int, 3> first{}, dims{};
    std::size_t size() const { return std::size_t(dims[0]) * std::size_t(dims[1]) * std::size_t(dims[2]); }
    std::size_t index(int i, int j, int k) const
    {
        return std::size_t(i) + std::size_t(dims[0]) * (std::size_t(j) + std::size_t(dims[1]) * std::size_t(k));
    }
};

/// Steps of 6-neighbour erosion or dilation for a radius (mm) on the finest axis.
int stepsFor(double radiusMm, const Eigen::Vector3d& spacing) { return std::max(0, int(std::lround(radiusMm / spacing.minCoeff()))); }

} // namespace

std::vector<ParameterSpec> organGrowingParameters()
{
    return {
        {"window_sigmas", "Intensity window", "sigma", 2.5, 1.0, 6.0, "Organ growing",
         "Half-width of the HU window around the points' median, in robust standard deviations of the HU near them."},
        {"opening_mm", "Opening radius", "mm", 3.0, 0.0, 10.0, "Organ growing",
         "Bridges thinner than twice this to touching organs of the same density are cut."},
        {"closing_mm", "Closing radius", "mm", 4.0, 0.0, 10.0, "Organ growing",
         "Gaps narrower than twice this inside the organ (small vessels, noise) are taken in."},
        {"reach_mm", "Reach from the points", "mm", 150.0, 20.0, 400.0, "Organ growing",
         "The label stays within a box this far around the points."},
    };
}

OrganGrowing growOrgan(const CtVolume& ct, const std::vector<Eigen::Vector3d>& pointsMm, const ParameterSet& parameters,
                       const Progress& progress)
{
    if (pointsMm.empty())
        throw Error("place at least one point inside the organ");
    const VolumeGeometry& g = ct.geometry();
    std::vector<Eigen::Vector3i> seeds;
    for (const Eigen::Vector3d& p : pointsMm)
    {
        const Eigen::Vector3d index = g.patientToIndex(p).array().round();
        const Eigen::Vector3i ijk = index.cast<int>();
        if (!g.contains(ijk.x(), ijk.y(), ijk.z()))
            throw Error("a point lies outside the CT", {{"point_mm", std::to_string(p.x()) + "," + std::to_string(p.y()) + "," + std::to_string(p.z())}});
        seeds.push_back(ijk);
    }
    // The working box.
    Box box;
    const double reach = parameters.get("reach_mm");
    for (int a = 0; a < 3; ++a)
    {
        int lo = seeds.front()[a], hi = lo;
        for (const Eigen::Vector3i& s : seeds)
            lo = std::min(lo, s[a]), hi = std::max(hi, s[a]);
        const int margin = int(std::ceil(reach / g.spacing[a]));
        box.first[std::size_t(a)] = std::max(0, lo - margin);
        box.dims[std::size_t(a)] = std::min(g.dims[std::size_t(a)] - 1, hi + margin) - box.first[std::size_t(a)] + 1;
    }
    // The smoothed CT in the box (the binomial 3 x 3 x 3 the guided segmentation reads).
    std::vector<float> smooth(box.size());
    for (int k = 0; k < box.dims[2]; ++k)
    {
        progress.throwIfCancelled();
        for (int j = 0; j < box.dims[1]; ++j)
            for (int i = 0; i < box.dims[0]; ++i)
                smooth[box.index(i, j, k)] = float(detail::smoothedHu(ct, box.first[0] + i, box.first[1] + j, box.first[2] + k));
        progress.report(0.4 * double(k + 1) / box.dims[2], localized("vsim::Progress", "smoothing"));
    }
    // The points' window: the median and the robust spread of the smoothed HU within 7 mm of them.
    std::vector<double> near;
    for (const Eigen::Vector3i& s : seeds)
    {
        const Eigen::Vector3i r = (Eigen::Vector3d::Constant(7.0).cwiseQuotient(g.spacing)).array().ceil().cast<int>();
        for (int dk = -r.z(); dk <= r.z(); ++dk)
            for (int dj = -r.y(); dj <= r.y(); ++dj)
                for (int di = -r.x(); di <= r.x(); ++di)
                {
                    const int i = s.x() + di - box.first[0], j = s.y() + dj - box.first[1], k = s.z() + dk - box.first[2];
                    if (i < 0 || j < 0 || k < 0 || i >= box.dims[0] || j >= box.dims[1] || k >= box.dims[2] ||
                        Eigen::Vector3d(di, dj, dk).cwiseProduct(g.spacing).norm() > 7.0)
                        continue;
                    near.push_back(smooth[box.index(i, j, k)]);
                }
    }
    const double centre = median(near);
    std::vector<double> deviation;
    for (double v : near)
        deviation.push_back(std::abs(v - centre));
    const double sigma = std::max(8.0, 1.4826 * median(deviation));
    const double low = centre - parameters.get("window_sigmas") * sigma, high = centre + parameters.get("window_sigmas") * sigma;

    // Growing, then the opening by reconstruction, the closing and the cavities.
    const Dims dims{box.dims[0], box.dims[1], box.dims[2]};
    std::vector<std::size_t> seedIndices;
    for (const Eigen::Vector3i& s : seeds)
        seedIndices.push_back(box.index(s.x() - box.first[0], s.y() - box.first[1], s.z() - box.first[2]));
    std::vector<std::uint8_t> grown(box.size(), 0);
    floodFill(dims, seedIndices, [&](std::size_t i) { return smooth[i] >= low && smooth[i] <= high; }, grown, true);
    progress.report(0.55, localized("vsim::Progress", "growing"));
    std::vector<std::uint8_t> core = grown;
    const int opening = stepsFor(parameters.get("opening_mm"), g.spacing);
    for (int s = 0; s < opening; ++s)
        core = erode6(dims, core);
    std::vector<std::uint8_t> kept(box.size(), 0);
    std::vector<std::size_t> coreSeeds;
    for (std::size_t i = 0; i < core.size(); ++i) // the core's parts that hold a point
        if (core[i] && std::find(seedIndices.begin(), seedIndices.end(), i) != seedIndices.end())
            coreSeeds.push_back(i);
    OrganGrowing result;
    if (coreSeeds.empty())
    {
        result.warnings.push_back(storedText("the opening removed every point's surroundings: the organ is thinner "
                                             "than the opening there; the label is the grown region without the "
                                             "opening"));
        kept = grown;
    }
    else
    {
        floodFill(dims, coreSeeds, [&](std::size_t i) { return core[i] != 0; }, kept, true);
        for (int s = 0; s < opening; ++s)
            kept = dilate6(dims, kept);
        for (std::size_t i = 0; i < kept.size(); ++i)
            kept[i] = kept[i] && grown[i];
    }
    progress.report(0.75, localized("vsim::Progress", "opening"));
    const int closing = stepsFor(parameters.get("closing_mm"), g.spacing);
    for (int s = 0; s < closing; ++s)
        kept = dilate6(dims, kept);
    for (int s = 0; s < closing; ++s)
        kept = erode6(dims, kept);
    kept = withCavitiesFilled(dims, kept);
    progress.report(0.95, localized("vsim::Progress", "closing"));

    result.label = LabelVolume(g);
    std::size_t voxels = 0;
    for (int k = 0; k < box.dims[2]; ++k)
        for (int j = 0; j < box.dims[1]; ++j)
            for (int i = 0; i < box.dims[0]; ++i)
                if (kept[box.index(i, j, k)])
                {
                    result.label.at(box.first[0] + i, box.first[1] + j, box.first[2] + k) = 1;
                    ++voxels;
                }
    if (voxels == 0)
        throw Error("the points' intensity window holds nothing: place them inside the organ");
    result.figures["volume_ml"] = double(voxels) * g.spacing.prod() * 1e-3;
    result.figures["window_low_hu"] = low;
    result.figures["window_high_hu"] = high;
    result.figures["seed_median_hu"] = centre;
    progress.report(1.0, localized("vsim::Progress", "organ grown"));
    return result;
}

} // namespace vsim::imaging
