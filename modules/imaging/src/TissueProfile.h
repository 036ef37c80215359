#pragma once

// The tissue level around a vessel for the partial-volume radii (PartialVolumeRadii.cpp): medians of the voxels of a
// shell around the tube, along its length (HU; arcs in mm).

#include "vsim/core/Median.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace vsim::imaging::detail {

using vsim::median;

/// The level of the tissue that fills most of a shell: the median, then three times the median of the values within
/// 2.5 robust standard deviations (1.4826 x the median absolute deviation) of the last level. A touching vein or a
/// neighbour's blurred lumen in part of the shell pulls the plain median up (a portal vein beside a hepatic artery by
/// 8 HU: 7 % on the radius of a 1.3 mm artery); its voxels lie several standard deviations above the parenchyma and
/// drop out.
inline double dominantLevel(std::vector<double> values)
{
    double level = median(values);
    for (int round = 0; round < 3 && values.size() >= 20; ++round)
    {
        std::vector<double> deviation;
        for (double v : values)
            deviation.push_back(std::abs(v - level));
        const double spread = 1.4826 * median(deviation);
        std::vector<double> kept;
        for (double v : values)
            if (std::abs(v - level) <= 2.5 * spread)
                kept.push_back(v);
        if (kept.size() < 20)
            break;
        level = median(kept);
        values = std::move(kept);
    }
    return level;
}

inline constexpr double kTissueWindowMm = 2.0; // the level at an arc: the shell within this distance along the tube
inline constexpr double kProfileStepMm = 0.5;

/// The tissue level (HU) along one tube: the dominant level of its shell's voxels within kTissueWindowMm of each arc, in
/// 0.5 mm steps (the background changes along a vessel, e.g. where it enters a tumour); the whole shell's level
/// where a window holds fewer than 20 voxels.
class TissueProfile
{
public:
    TissueProfile() = default;
    TissueProfile(std::vector<std::pair<float, float>> shell, double lengthMm) // (arc mm, HU)
    {
        std::vector<double> all;
        for (const auto& [arc, hu] : shell)
            all.push_back(hu);
        overall_ = dominantLevel(all);
        std::sort(shell.begin(), shell.end());
        std::size_t first = 0, last = 0;
        for (double at = 0.0; at <= lengthMm + kProfileStepMm; at += kProfileStepMm)
        {
            while (first < shell.size() && shell[first].first < at - kTissueWindowMm)
                ++first;
            last = std::max(last, first);
            while (last < shell.size() && shell[last].first <= at + kTissueWindowMm)
                ++last;
            std::vector<double> window;
            for (std::size_t k = first; k < last; ++k)
                window.push_back(shell[k].second);
            levels_.push_back(window.size() >= 20 ? dominantLevel(window) : overall_);
        }
    }
    double at(double arcMm) const
    {
        if (levels_.empty())
            return overall_;
        return levels_[std::min(levels_.size() - 1, std::size_t(std::max(0.0, std::round(arcMm / kProfileStepMm))))];
    }
    double overall() const { return overall_; }

private:
    std::vector<double> levels_;
    double overall_ = std::nan("");
};

} // namespace vsim::imaging::detail
