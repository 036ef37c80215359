#include "ScannerModel.h"

#include "vsim/core/Localized.h"
#include "vsim/core/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace vsim::dicom::detail {
namespace {

/// splitmix64 of the pair (seed, stream): independent, reproducible streams per slice.
std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t stream)
{
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + stream + 0x2545F4914F6CDD1Dull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/// Convolves `count` samples spaced `stride` apart with `kernel` (odd length), edges clamped.
void convolveLine(const float* in, float* out, std::size_t count, std::size_t stride, const std::vector<float>& kernel)
{
    const int half = int(kernel.size() / 2);
    const long last = long(count) - 1;
    for (long n = 0; n <= last; ++n)
    {
        double sum = 0.0;
        for (int t = -half; t <= half; ++t)
            sum += kernel[std::size_t(t + half)] * in[std::size_t(std::clamp(n + t, 0L, last)) * stride];
        out[std::size_t(n) * stride] = float(sum);
    }
}

/// In-plane separable blur of one slice into `out` (scratch: a slice-sized buffer).
void blurSlice(const float* in, float* out, float* scratch, int columns, int rows, const std::vector<float>& kernel)
{
    for (int j = 0; j < rows; ++j)
        convolveLine(in + std::size_t(j) * columns, scratch + std::size_t(j) * columns, columns, 1, kernel);
    for (int i = 0; i < columns; ++i)
        convolveLine(scratch + i, out + i, rows, std::size_t(columns), kernel);
}

} // namespace

std::vector<float> gaussianKernel(double sigmaVoxels)
{
    if (sigmaVoxels <= 0.0)
        return {1.0f};
    const int half = std::max(1, int(std::ceil(3.0 * sigmaVoxels)));
    std::vector<float> kernel(std::size_t(2 * half + 1));
    double sum = 0.0;
    for (int t = -half; t <= half; ++t)
        sum += kernel[std::size_t(t + half)] = float(std::exp(-0.5 * t * t / (sigmaVoxels * sigmaVoxels)));
    for (float& w : kernel)
        w = float(w / sum);
    return kernel;
}

void blurAlongAxis(FloatVolume& volume, int axis, double sigmaVoxels, const Progress& progress)
{
    if (sigmaVoxels <= 0.0)
        return;
    const std::vector<float> kernel = gaussianKernel(sigmaVoxels);
    const std::array<std::size_t, 3> stride{1, std::size_t(volume.dims[0]), volume.pixelsPerSlice()};
    const int a = axis == 0 ? 1 : 0, b = axis == 2 ? 1 : 2; // the two other axes: one line per (a, b) pair
    const std::size_t lines = std::size_t(volume.dims[a]) * std::size_t(volume.dims[b]);
    const std::size_t count = std::size_t(volume.dims[axis]);
    constexpr std::size_t kLinesPerItem = 256;
    const std::size_t items = (lines + kLinesPerItem - 1) / kLinesPerItem;
    parallelFor(
        items,
        [&](std::size_t item) {
            std::vector<float> line(count), blurred(count);
            for (std::size_t l = item * kLinesPerItem; l < std::min(lines, (item + 1) * kLinesPerItem); ++l)
            {
                const std::size_t start = (l % std::size_t(volume.dims[a])) * stride[a] +
                                          (l / std::size_t(volume.dims[a])) * stride[b];
                for (std::size_t n = 0; n < count; ++n)
                    line[n] = volume.values[start + n * stride[axis]];
                convolveLine(line.data(), blurred.data(), count, 1, kernel);
                for (std::size_t n = 0; n < count; ++n)
                    volume.values[start + n * stride[axis]] = blurred[n];
            }
        },
        [&](std::size_t done) { progress.report(double(done) / double(items), localized("vsim::Progress", "point-spread function")); });
}

void addCorrelatedNoise(float* slice, int columns, int rows, double noiseHu, double grainVoxels, std::uint64_t seed,
                        std::uint64_t sliceIndex)
{
    if (noiseHu <= 0.0)
        return;
    const std::vector<float> fine = gaussianKernel(grainVoxels), coarse = gaussianKernel(3.0 * grainVoxels);
    // Norm of the 2-D filter fine x fine - coarse x coarse, on the coarse kernel's support.
    const int half = int(coarse.size() / 2), fineHalf = int(fine.size() / 2);
    double norm2 = 0.0;
    for (int y = -half; y <= half; ++y)
        for (int x = -half; x <= half; ++x)
        {
            const double f = (std::abs(x) <= fineHalf && std::abs(y) <= fineHalf)
                                 ? double(fine[std::size_t(x + fineHalf)]) * fine[std::size_t(y + fineHalf)]
                                 : 0.0;
            const double k = f - double(coarse[std::size_t(x + half)]) * coarse[std::size_t(y + half)];
            norm2 += k * k;
        }
    const std::size_t pixels = std::size_t(columns) * std::size_t(rows);
    std::vector<float> white(pixels), a(pixels), b(pixels), scratch(pixels);
    std::mt19937_64 random(mixSeed(seed, sliceIndex));
    std::normal_distribution<float> normal(0.0f, 1.0f);
    for (float& w : white)
        w = normal(random);
    blurSlice(white.data(), a.data(), scratch.data(), columns, rows, fine);
    blurSlice(white.data(), b.data(), scratch.data(), columns, rows, coarse);
    const float scale = float(noiseHu / std::sqrt(norm2));
    for (std::size_t p = 0; p < pixels; ++p)
        slice[p] += scale * (a[p] - b[p]);
}

} // namespace vsim::dicom::detail
