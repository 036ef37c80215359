// EndoscopeOptics.h: thin-lens blur by a stack of Gaussian-blurred copies, the lamp's fall-off and the
// defocus noise.
#include "vsim/viz/EndoscopeOptics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

namespace vsim::viz {
namespace {

/// The blur levels of the stack (standard deviation, pixels), a factor sqrt(2) apart; a pixel's blur is
/// interpolated between the two about it.
constexpr std::array<double, 12> kLevels{0.0,   1.0, 1.414, 2.0,  2.828, 4.0,
                                         5.657, 8.0, 11.31, 16.0, 22.63, 32.0};

using Planes = std::array<std::vector<float>, 3>; // R, G, B, row-major

/// The widths of three box filters whose succession approximates a Gaussian of `sigma` (odd widths; the
/// variance of a box of width w is (w^2 - 1) / 12).
std::array<int, 3> boxWidths(double sigma)
{
    const double ideal = std::sqrt(12.0 * sigma * sigma / 3.0 + 1.0);
    int lower = int(std::floor(ideal));
    if (lower % 2 == 0)
        --lower;
    const int upper = lower + 2;
    const int lowerCount = int(std::lround((12.0 * sigma * sigma - 3.0 * lower * lower - 12.0 * lower - 9.0) /
                                           (-4.0 * lower - 4.0)));
    std::array<int, 3> widths{};
    for (int i = 0; i < 3; ++i)
        widths[std::size_t(i)] = i < lowerCount ? lower : upper;
    return widths;
}

/// A box filter of odd `boxWidth` along rows, edges replicated: a running sum over a padded copy of each row.
void boxRows(std::vector<float>& plane, int width, int height, int boxWidth)
{
    const int radius = boxWidth / 2;
    std::vector<float> padded(std::size_t(width + 2 * radius));
    const float scale = 1.0f / float(boxWidth);
    for (int y = 0; y < height; ++y)
    {
        float* row = plane.data() + std::size_t(y) * std::size_t(width);
        std::fill(padded.begin(), padded.begin() + radius, row[0]);
        std::copy(row, row + width, padded.begin() + radius);
        std::fill(padded.begin() + radius + width, padded.end(), row[width - 1]);
        double sum = 0.0;
        for (int k = 0; k < boxWidth; ++k)
            sum += padded[std::size_t(k)];
        for (int x = 0; x < width; ++x)
        {
            row[x] = float(sum) * scale;
            if (x + 1 < width)
                sum += padded[std::size_t(x + boxWidth)] - padded[std::size_t(x)];
        }
    }
}

/// The same along columns, all columns at once (a running sum per column, rows replicated past the edges).
void boxColumns(std::vector<float>& plane, int width, int height, int boxWidth)
{
    const int radius = boxWidth / 2;
    const float scale = 1.0f / float(boxWidth);
    auto row = [&](int y) { return plane.data() + std::size_t(std::clamp(y, 0, height - 1)) * std::size_t(width); };
    std::vector<float> sum(std::size_t(width), 0.0f), out(plane.size());
    for (int k = -radius; k <= radius; ++k)
    {
        const float* source = row(k);
        for (int x = 0; x < width; ++x)
            sum[std::size_t(x)] += source[x];
    }
    for (int y = 0; y < height; ++y)
    {
        float* target = out.data() + std::size_t(y) * std::size_t(width);
        const float *entering = row(y + radius + 1), *leaving = row(y - radius);
        for (int x = 0; x < width; ++x)
        {
            target[x] = sum[std::size_t(x)] * scale;
            sum[std::size_t(x)] += entering[x] - leaving[x];
        }
    }
    plane.swap(out);
}

/// A Gaussian blur as three box blurs each way: time independent of sigma.
std::vector<float> gaussianBlur(std::vector<float> plane, int width, int height, double sigma)
{
    for (int boxWidth : boxWidths(sigma))
    {
        boxRows(plane, width, height, boxWidth);
        boxColumns(plane, width, height, boxWidth);
    }
    return plane;
}

} // namespace

double horizontalFieldOfViewDegrees(const EndoscopeLens& lens)
{
    return 2.0 * std::atan(lens.sensorWidthMm / (2.0 * lens.focalLengthMm)) * 180.0 / std::numbers::pi;
}

double circleOfConfusionMm(const EndoscopeLens& lens, double depthMm)
{
    const double f = lens.focalLengthMm;
    const double focus = std::max(lens.focusDistanceMm, 1.01 * f); // a lens cannot focus nearer than f
    if (!std::isfinite(depthMm))
        return f * f / (lens.fNumber * (focus - f)); // the limit d -> infinity
    return f * f / (lens.fNumber * (focus - f)) * std::abs(depthMm - focus) / std::max(depthMm, 1e-6);
}

double blurSigmaPx(const EndoscopeLens& lens, double depthMm, int widthPx)
{
    return 0.25 * circleOfConfusionMm(lens, depthMm) * double(widthPx) / lens.sensorWidthMm;
}

QImage lensImage(const QImage& sharp, const std::vector<float>& depthMm, const EndoscopeLens& lens,
                 std::uint32_t seed, double* medianBlurPx)
{
    const QImage rgb = sharp.convertToFormat(QImage::Format_RGB888);
    const int width = rgb.width(), height = rgb.height();
    const std::size_t count = std::size_t(width) * std::size_t(height);
    Planes planes;
    for (auto& plane : planes)
        plane.resize(count);
    std::vector<float> sigma(count);
    for (int y = 0; y < height; ++y)
    {
        const uchar* line = rgb.constScanLine(y);
        for (int x = 0; x < width; ++x)
        {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            const double depth = depthMm[i];
            const double lamp =
                std::isfinite(depth) ? std::min(1.0, std::pow(lens.lampReachMm / depth, 2.0)) : 0.0;
            for (std::size_t c = 0; c < 3; ++c)
                planes[c][i] = float(lamp * line[3 * x + int(c)]);
            sigma[i] = float(std::min(blurSigmaPx(lens, depth, width), kLevels.back()));
        }
    }
    if (lens.autoGain && count)
    {
        std::vector<float> brightness(count);
        for (std::size_t i = 0; i < count; ++i)
            brightness[i] = std::max({planes[0][i], planes[1][i], planes[2][i]});
        const auto p90 = brightness.begin() + std::ptrdiff_t(0.9 * double(count - 1));
        std::nth_element(brightness.begin(), p90, brightness.end());
        const float gain = *p90 > 0.0f ? std::clamp(200.0f / *p90, 1.0f, 8.0f) : 1.0f;
        for (auto& plane : planes)
            for (float& v : plane)
                v *= gain;
    }
    std::vector<float> sorted = sigma;
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(count / 2), sorted.end());
    const double median = count ? sorted[count / 2] : 0.0;
    if (medianBlurPx)
        *medianBlurPx = median;

    // The stack, only as deep as the blurs present need.
    // The stack: only the levels about the blurs present (the sharp level 0 is free); each level's channels are
    // blurred in parallel.
    const auto [shallowest, deepest] = count ? std::minmax_element(sigma.begin(), sigma.end())
                                             : std::pair{sigma.begin(), sigma.begin()};
    std::vector<Planes> stack(kLevels.size());
    stack[0] = planes;
    std::vector<std::pair<std::size_t, std::size_t>> jobs; // (level, channel)
    std::size_t levels = 1;
    for (std::size_t level = 1; level < kLevels.size() && count && kLevels[level - 1] < *deepest; ++level, ++levels)
        if (level + 1 >= kLevels.size() || kLevels[level + 1] >= *shallowest)
            for (std::size_t c = 0; c < 3; ++c)
                jobs.emplace_back(level, c);
    stack.resize(levels);
#pragma omp parallel for schedule(dynamic)
    for (std::ptrdiff_t j = 0; j < std::ptrdiff_t(jobs.size()); ++j)
    {
        const auto [level, c] = jobs[std::size_t(j)];
        stack[level][c] = gaussianBlur(planes[c], width, height, kLevels[level]);
    }

    const double noiseSd = lens.noiseAtFullDefocus * std::min(1.0, median / (lens.fullDefocusBlurFraction * width));
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, 1.0);
    QImage result(width, height, QImage::Format_RGB888);
    for (int y = 0; y < height; ++y)
    {
        uchar* line = result.scanLine(y);
        for (int x = 0; x < width; ++x)
        {
            const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
            std::size_t upper = 1;
            while (upper + 1 < stack.size() && kLevels[upper] < sigma[i])
                ++upper;
            upper = std::min(upper, stack.size() - 1);
            const std::size_t lower = upper == 0 ? 0 : upper - 1;
            const double span = kLevels[upper] - kLevels[lower];
            const double t = span > 0.0 ? std::clamp((sigma[i] - kLevels[lower]) / span, 0.0, 1.0) : 0.0;
            const double grain =
                noiseSd > 0.0 ? noiseSd * noise(random) : 0.0; // luminance noise, as a sensor's
            for (std::size_t c = 0; c < 3; ++c)
            {
                const double value = (1.0 - t) * stack[lower][c][i] + t * stack[upper][c][i] + grain;
                line[3 * x + int(c)] = uchar(std::clamp(std::lround(value), 0L, 255L));
            }
        }
    }
    return result;
}

} // namespace vsim::viz
