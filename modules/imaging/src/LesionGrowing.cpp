#include "vsim/imaging/LesionGrowing.h"

#include "MaskOps.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Median.h"
#include "vsim/core/StoredText.h"

#include <algorithm>
#include <cmath>

namespace vsim::imaging {
namespace {

constexpr double kLesionCoreMm = 5.0;       ///< the lesion level is read within this of the points
constexpr double kLeastContrastShare = 0.25; ///< the boundary's least distance from the parenchyma (see below)

/// One axis of a separable Gaussian (sigma in voxels) over `values` (dims, x fastest), in place; edges clamped.
void smoothAxis(std::vector<float>& values, const Dims& dims, int axis, double sigmaVoxels)
{
    if (sigmaVoxels < 0.3)
        return;
    const int radius = int(std::ceil(3.0 * sigmaVoxels));
    std::vector<double> kernel(std::size_t(2 * radius + 1));
    double sum = 0.0;
    for (int t = -radius; t <= radius; ++t)
        sum += kernel[std::size_t(t + radius)] = std::exp(-0.5 * t * t / (sigmaVoxels * sigmaVoxels));
    for (double& w : kernel)
        w /= sum;
    const std::size_t stride = axis == 0 ? 1 : axis == 1 ? std::size_t(dims[0]) : std::size_t(dims[0]) * std::size_t(dims[1]);
    const int length = dims[std::size_t(axis)];
    std::vector<float> line(static_cast<std::size_t>(length));
    for (std::size_t start = 0; start < values.size(); ++start)
    {
        const int i = int(start % std::size_t(dims[0])), j = int((start / std::size_t(dims[0])) % std::size_t(dims[1]));
        const int k = int(start / (std::size_t(dims[0]) * std::size_t(dims[1])));
        if ((axis == 0 ? i : axis == 1 ? j : k) != 0) // one pass per line, from its first voxel
            continue;
        for (int t = 0; t < length; ++t)
            line[std::size_t(t)] = values[start + std::size_t(t) * stride];
        for (int t = 0; t < length; ++t)
        {
            double v = 0.0;
            for (int u = -radius; u <= radius; ++u)
                v += kernel[std::size_t(u + radius)] * line[std::size_t(std::clamp(t + u, 0, length - 1))];
            values[start + std::size_t(t) * stride] = float(v);
        }
    }
}

/// The parenchyma's level and spread (HU): the peak of the histogram of its smoothed HU (1 HU bins, a 5-bin moving
/// average) and its full width at half maximum / 2.355 (a normal's). The peak's own width, not the tails: the lesion
/// in the liver label widens one side, the enhanced vessels through the liver the other.
std::pair<double, double> parenchymaPeak(const std::vector<double>& values)
{
    if (values.empty())
        throw Error("the liver label holds no voxel near the points");
    const double low = *std::min_element(values.begin(), values.end());
    const double high = *std::max_element(values.begin(), values.end());
    const int bins = std::max(1, int(std::ceil(high - low)) + 1);
    std::vector<double> counts(std::size_t(bins), 0.0), smoothed(std::size_t(bins), 0.0);
    for (double v : values)
        counts[std::size_t(std::clamp(int(v - low), 0, bins - 1))] += 1.0;
    for (int b = 0; b < bins; ++b)
        for (int d = -2; d <= 2; ++d)
            smoothed[std::size_t(b)] += counts[std::size_t(std::clamp(b + d, 0, bins - 1))] / 5.0;
    const int peak = int(std::max_element(smoothed.begin(), smoothed.end()) - smoothed.begin());
    const double half = 0.5 * smoothed[std::size_t(peak)];
    int left = peak, right = peak;
    while (left > 0 && smoothed[std::size_t(left)] > half)
        --left;
    while (right < bins - 1 && smoothed[std::size_t(right)] > half)
        ++right;
    return {low + peak + 0.5, std::max(1.0, double(right - left) / 2.355)};
}

} // namespace

std::vector<ParameterSpec> lesionGrowingParameters()
{
    return {
        {"lesion_sigmas", "Lesion threshold", "sigma", 2.0, 0.5, 6.0, "Lesion growing",
         "The lesion's boundary: this many spreads of the smoothed liver parenchyma (its histogram peak's full width "
         "at half maximum / 2.355) below the peak (hypodense lesions; above it for hyperdense ones), and at least a "
         "quarter of the lesion's contrast."},
        {"lesion_smoothing_mm", "Smoothing", "mm", 2.0, 0.0, 5.0, "Lesion growing",
         "Standard deviation of the Gaussian the CT is smoothed with before the threshold."},
        {"lesion_opening_mm", "Opening radius", "mm", 3.0, 0.0, 10.0, "Lesion growing",
         "Bridges thinner than twice this (along vessels, to a neighbouring lesion) are cut."},
        {"lesion_closing_mm", "Closing radius", "mm", 6.0, 0.0, 15.0, "Lesion growing",
         "Gaps narrower than twice this (the enhancing rim, vessels through the lesion) are taken in."},
        {"lesion_reach_mm", "Reach from the points", "mm", 80.0, 20.0, 200.0, "Lesion growing",
         "The label stays within a box this far around the points."},
    };
}

LesionGrowing growLesion(const CtVolume& ct, const std::vector<Eigen::Vector3d>& pointsMm, const LabelVolume& liver,
                         const ParameterSet& parameters, const Progress& progress)
{
    if (pointsMm.empty())
        throw Error("place at least one point inside the lesion");
    const VolumeGeometry& g = ct.geometry();
    auto inLiver = [&](int i, int j, int k) {
        const Eigen::Vector3d index = liver.geometry().patientToIndex(g.indexToPatient(Eigen::Vector3d(i, j, k))).array().round();
        return liver.geometry().contains(int(index.x()), int(index.y()), int(index.z())) &&
               liver.at(int(index.x()), int(index.y()), int(index.z())) != 0;
    };
    std::vector<Eigen::Vector3i> seeds;
    for (const Eigen::Vector3d& p : pointsMm)
    {
        const Eigen::Vector3i ijk = g.patientToIndex(p).array().round().cast<int>();
        const std::string where = std::to_string(p.x()) + "," + std::to_string(p.y()) + "," + std::to_string(p.z());
        if (!g.contains(ijk.x(), ijk.y(), ijk.z()))
            throw Error("a point lies outside the CT", {{"point_mm", where}});
        if (!inLiver(ijk.x(), ijk.y(), ijk.z()))
            throw Error("a point lies outside the liver label: place the points inside the lesion, in the liver",
                        {{"point_mm", where}});
        seeds.push_back(ijk);
    }
    // The working box, the liver in it and the smoothed CT.
    std::array<int, 3> first{}, size{};
    for (int a = 0; a < 3; ++a)
    {
        int lo = seeds.front()[a], hi = lo;
        for (const Eigen::Vector3i& s : seeds)
            lo = std::min(lo, s[a]), hi = std::max(hi, s[a]);
        const int margin = int(std::ceil(parameters.get("lesion_reach_mm") / g.spacing[a]));
        first[std::size_t(a)] = std::max(0, lo - margin);
        size[std::size_t(a)] = std::min(g.dims[std::size_t(a)] - 1, hi + margin) - first[std::size_t(a)] + 1;
    }
    const Dims dims{size[0], size[1], size[2]};
    const std::size_t count = std::size_t(size[0]) * std::size_t(size[1]) * std::size_t(size[2]);
    auto boxIndex = [&](int i, int j, int k) {
        return std::size_t(i) + std::size_t(size[0]) * (std::size_t(j) + std::size_t(size[1]) * std::size_t(k));
    };
    std::vector<float> smooth(count);
    std::vector<std::uint8_t> inside(count, 0);
    for (int k = 0; k < size[2]; ++k)
    {
        progress.throwIfCancelled();
        for (int j = 0; j < size[1]; ++j)
            for (int i = 0; i < size[0]; ++i)
            {
                smooth[boxIndex(i, j, k)] = ct.at(first[0] + i, first[1] + j, first[2] + k);
                inside[boxIndex(i, j, k)] = inLiver(first[0] + i, first[1] + j, first[2] + k) ? 1 : 0;
            }
        progress.report(0.2 * double(k + 1) / size[2], localized("vsim::Progress", "liver"));
    }
    const double sigmaMm = parameters.get("lesion_smoothing_mm");
    for (int a = 0; a < 3; ++a)
    {
        progress.throwIfCancelled();
        smoothAxis(smooth, dims, a, sigmaMm / g.spacing[a]);
        progress.report(0.2 + 0.15 * (a + 1), localized("vsim::Progress", "smoothing"));
    }
    // The parenchyma's level and spread, and the lesion's near the points.
    std::vector<double> parenchyma, core;
    for (std::size_t v = 0; v < count; ++v)
        if (inside[v])
            parenchyma.push_back(smooth[v]);
    for (const Eigen::Vector3i& s : seeds)
    {
        const Eigen::Vector3i r = (Eigen::Vector3d::Constant(kLesionCoreMm).cwiseQuotient(g.spacing)).array().ceil().cast<int>();
        for (int dk = -r.z(); dk <= r.z(); ++dk)
            for (int dj = -r.y(); dj <= r.y(); ++dj)
                for (int di = -r.x(); di <= r.x(); ++di)
                {
                    const int i = s.x() + di - first[0], j = s.y() + dj - first[1], k = s.z() + dk - first[2];
                    if (i >= 0 && j >= 0 && k >= 0 && i < size[0] && j < size[1] && k < size[2] &&
                        Eigen::Vector3d(di, dj, dk).cwiseProduct(g.spacing).norm() <= kLesionCoreMm)
                        core.push_back(smooth[boxIndex(i, j, k)]);
                }
    }
    const auto [level, spread] = parenchymaPeak(parenchyma);
    const double lesion = median(core);
    const bool hypodense = lesion < level;
    const double k = parameters.get("lesion_sigmas");
    // At least kLeastContrastShare of the way from the parenchyma to the lesion: a boundary nearer the parenchyma's
    // level lies out in the smoothing's blur of the edge (a quarter of a step's contrast: 0.67 sigma out from it).
    const double margin = std::max(k * spread, kLeastContrastShare * std::abs(level - lesion));
    const double threshold = hypodense ? level - margin : level + margin;
    if (hypodense ? lesion > threshold : lesion < threshold)
        throw Error(Pattern{"the points' tissue (%1 HU) lies within the liver's own range (%2 +/- %3 HU): place them "
                            "in the lesion's darker (or brighter) part, or lower lesion_sigmas",
                            {std::to_string(int(std::lround(lesion))), std::to_string(int(std::lround(level))),
                             std::to_string(int(std::lround(k * spread)))}});

    // Growing, the opening by reconstruction, the closing and the cavities, within the liver.
    std::vector<std::size_t> seedIndices;
    for (const Eigen::Vector3i& s : seeds)
        seedIndices.push_back(boxIndex(s.x() - first[0], s.y() - first[1], s.z() - first[2]));
    std::vector<std::uint8_t> grown(count, 0);
    floodFill(dims, seedIndices,
              [&](std::size_t v) { return inside[v] && (hypodense ? smooth[v] <= threshold : smooth[v] >= threshold); },
              grown, true);
    progress.report(0.7, localized("vsim::Progress", "growing"));
    const std::array<double, 3> spacing{g.spacing.x(), g.spacing.y(), g.spacing.z()};
    LesionGrowing result;
    std::vector<std::uint8_t> kept = grown;
    if (const double opening = parameters.get("lesion_opening_mm"); opening > 0.0)
    {
        const std::vector<std::uint8_t> eroded = erodeBall(dims, grown, spacing, opening);
        std::vector<std::size_t> coreSeeds;
        for (std::size_t s : seedIndices)
            if (eroded[s])
                coreSeeds.push_back(s);
        if (coreSeeds.empty())
            result.warnings.push_back(storedText("the opening removed every point's surroundings: the lesion is "
                                                 "thinner than the opening there; the label is the grown region "
                                                 "without the opening"));
        else
        {
            std::vector<std::uint8_t> reached(count, 0);
            floodFill(dims, coreSeeds, [&](std::size_t v) { return eroded[v] != 0; }, reached, true);
            kept = dilateBall(dims, reached, spacing, opening);
            for (std::size_t v = 0; v < count; ++v)
                kept[v] = kept[v] && grown[v];
        }
    }
    progress.report(0.8, localized("vsim::Progress", "opening"));
    if (const double closing = parameters.get("lesion_closing_mm"); closing > 0.0)
        kept = erodeBall(dims, dilateBall(dims, kept, spacing, closing), spacing, closing);
    kept = withCavitiesFilled(dims, kept);
    progress.report(0.95, localized("vsim::Progress", "closing"));

    result.label = LabelVolume(g);
    std::size_t voxels = 0;
    for (int c = 0; c < size[2]; ++c)
        for (int b = 0; b < size[1]; ++b)
            for (int a = 0; a < size[0]; ++a)
                if (kept[boxIndex(a, b, c)] && inside[boxIndex(a, b, c)])
                {
                    result.label.at(first[0] + a, first[1] + b, first[2] + c) = 1;
                    ++voxels;
                }
    result.figures["volume_ml"] = double(voxels) * g.spacing.prod() * 1e-3;
    result.figures["parenchyma_hu"] = level;
    result.figures["parenchyma_sd_hu"] = spread;
    result.figures["lesion_hu"] = lesion;
    result.figures["threshold_hu"] = threshold;
    progress.report(1.0, localized("vsim::Progress", "lesion grown"));
    return result;
}

} // namespace vsim::imaging
