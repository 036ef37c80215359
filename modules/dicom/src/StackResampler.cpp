#include "StackResampler.h"

#include "vsim/core/Localized.h"
#include "vsim/core/ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace vsim::dicom {
namespace {

/// Bilinear sample of one slice at continuous pixel (a, b); NaN beyond half a pixel outside.
double bilinear(const std::int16_t* slice, int columns, int rows, double a, double b)
{
    if (a < -0.5 || b < -0.5 || a > columns - 0.5 || b > rows - 0.5)
        return std::nan("");
    a = std::clamp(a, 0.0, double(columns - 1));
    b = std::clamp(b, 0.0, double(rows - 1));
    const int i = std::min(int(a), columns - 2 < 0 ? 0 : columns - 2);
    const int j = std::min(int(b), rows - 2 < 0 ? 0 : rows - 2);
    const int i1 = std::min(i + 1, columns - 1), j1 = std::min(j + 1, rows - 1);
    const double fa = a - i, fb = b - j;
    const double top = (1 - fa) * slice[j * columns + i] + fa * slice[j * columns + i1];
    const double bottom = (1 - fa) * slice[j1 * columns + i] + fa * slice[j1 * columns + i1];
    return (1 - fb) * top + fb * bottom;
}

} // namespace

CtVolume resampleStack(const CtVolume& pixels, const SliceStack& stack, const std::vector<double>& offsets,
                       const VolumeGeometry& grid, const Progress& progress)
{
    CtVolume out = CtVolume::uninitialized(grid); // every voxel is written below
    const Eigen::Vector3d normal = stack.normal();
    const Eigen::Vector3d x = stack.xDirection / stack.columnSpacing, y = stack.yDirection / stack.rowSpacing;
    const std::size_t perSlice = std::size_t(stack.columns) * std::size_t(stack.rows);
    constexpr double kEdgeToleranceMm = 1e-3;
    const auto sample = [&](std::size_t k, const Eigen::Vector3d& p) {
        const Eigen::Vector3d q = p - stack.positions[k];
        return bilinear(pixels.data() + k * perSlice, stack.columns, stack.rows, q.dot(x), q.dot(y));
    };
    parallelFor(
        std::size_t(grid.dims[2]),
        [&](std::size_t kz) {
            std::int16_t* slice = out.data() + kz * std::size_t(grid.dims[0]) * std::size_t(grid.dims[1]);
            std::size_t index = 0;
            for (int j = 0; j < grid.dims[1]; ++j)
                for (int i = 0; i < grid.dims[0]; ++i, ++index)
                {
                    const Eigen::Vector3d p = grid.indexToPatient(Eigen::Vector3d(i, j, double(kz)));
                    const double h = (p - stack.positions[0]).dot(normal);
                    double value = std::nan("");
                    if (h >= offsets.front() - kEdgeToleranceMm && h <= offsets.back() + kEdgeToleranceMm)
                    {
                        const auto upper = std::upper_bound(offsets.begin(), offsets.end(), h);
                        const std::size_t k1 = std::min<std::size_t>(std::size_t(upper - offsets.begin()), offsets.size() - 1);
                        const std::size_t k0 = k1 == 0 ? 0 : k1 - 1;
                        const double span = offsets[k1] - offsets[k0];
                        const double w = span > 0 ? std::clamp((h - offsets[k0]) / span, 0.0, 1.0) : 0.0;
                        if (w <= 0.0)
                            value = sample(k0, p);
                        else if (w >= 1.0)
                            value = sample(k1, p);
                        else
                            value = (1 - w) * sample(k0, p) + w * sample(k1, p); // NaN outside either plane
                    }
                    slice[index] = std::isnan(value) ? kPaddingHu : std::int16_t(std::lround(value));
                }
        },
        [&](std::size_t done) { progress.report(double(done) / grid.dims[2], localized("vsim::Progress", "resampling")); });
    return out;
}

} // namespace vsim::dicom
