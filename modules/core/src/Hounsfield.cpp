#include "vsim/core/Hounsfield.h"

#include "vsim/core/Error.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace vsim {
namespace {

constexpr double kHighestMedianHu = 500.0; // a body's median is fat, soft tissue or air; never bone
constexpr std::size_t kSamples = 1 << 18;   // for the median: every k-th voxel, ~262k values

std::string text(double value)
{
    return std::to_string(long(std::lround(value)));
}

} // namespace

std::string whyNotHounsfield(const CtVolume& ct)
{
    if (ct.isEmpty())
        return "the volume is empty";
    const std::int16_t* data = ct.data();
    const std::size_t count = ct.size();
    const std::int16_t lowest = *std::min_element(data, data + count);
    const std::size_t stride = std::max<std::size_t>(1, count / kSamples);
    std::vector<std::int16_t> sample;
    sample.reserve(count / stride + 1);
    for (std::size_t v = 0; v < count; v += stride)
        sample.push_back(data[v]);
    std::nth_element(sample.begin(), sample.begin() + long(sample.size() / 2), sample.end());
    const double median = sample[sample.size() / 2];
    if (lowest >= 0)
        return "no voxel is below 0 (lowest " + text(lowest) + ", median " + text(median) +
               "): CT in HU has air, fat or fluid below 0 HU";
    if (median > kHighestMedianHu)
        return "the median is " + text(median) + " (lowest " + text(lowest) + "): a body's median in HU is fat, soft "
               "tissue or air, below " + text(kHighestMedianHu);
    return {};
}

void acceptAsHounsfield(CtVolume& ct, const std::optional<HounsfieldRescale>& rescale, std::vector<std::string>& warnings)
{
    if (rescale)
    {
        if (!std::isfinite(rescale->slope) || !std::isfinite(rescale->intercept) || rescale->slope == 0.0)
            throw Error("--rescale needs a finite, non-zero slope and a finite intercept");
        std::size_t clamped = 0;
        constexpr double kLowest = std::numeric_limits<std::int16_t>::min();
        constexpr double kHighest = std::numeric_limits<std::int16_t>::max();
        std::int16_t* data = ct.data();
        for (std::size_t v = 0; v < ct.size(); ++v)
        {
            const double hu = std::round(rescale->slope * data[v] + rescale->intercept);
            const double kept = std::clamp(hu, kLowest, kHighest);
            clamped += kept != hu;
            data[v] = static_cast<std::int16_t>(kept);
        }
        warnings.push_back(storedText(Pattern{"values rescaled to HU by the user's rescale: HU = %1 x stored + %2",
                                              {numberText(rescale->slope), numberText(rescale->intercept)}}) +
                           (clamped ? "; " + storedText(Pattern{"%1 voxels clamped to the int16 range",
                                                                {std::to_string(clamped)}})
                                    : ""));
    }
    const std::string why = whyNotHounsfield(ct);
    if (why.empty())
        return;
    throw Error(Pattern{"the values are not CT Hounsfield units: %1%2",
                        {why, (rescale ? ", even after the rescale given"
                             : ". If they are CT numbers stored without their rescale, import again with "
                               "--rescale SLOPE,INTERCEPT (stored values 0..4095 usually need --rescale 1,-1024)")}},
                {{"option", "--rescale"}});
}

} // namespace vsim
