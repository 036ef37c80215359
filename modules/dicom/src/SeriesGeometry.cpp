#include "vsim/dicom/SeriesGeometry.h"

#include "vsim/core/Median.h"
#include "vsim/core/StoredText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace vsim::dicom {
namespace {

using Eigen::Vector3d;

constexpr double kDuplicateToleranceMm = 0.01;


void requirePlacement(const DicomSeries& series)
{
    for (const DicomSlice& slice : series.slices)
    {
        const FrameGeometry& geometry = series.geometryOf(slice);
        if (!geometry.hasPosition || !geometry.hasOrientation)
            throw Error("the series has images without Image Position/Orientation (Patient): it cannot be placed "
                        "in the patient frame");
        if (geometry.rowSpacing <= 0.0 || geometry.columnSpacing <= 0.0)
            throw Error("the series has images without Pixel Spacing");
    }
}

/// Grid of a tilted stack: third axis along the direction the slices advance, first axis the image rows'
/// direction made orthogonal to it; the extent covers every source pixel.
VolumeGeometry tiltedGrid(const SliceStack& stack, const Vector3d& advance, double advanceSpacing)
{
    const Vector3d s = advance.normalized();
    const Vector3d x = (stack.xDirection - stack.xDirection.dot(s) * s).normalized();
    const Vector3d y = s.cross(x);
    Eigen::Matrix3d frame;
    frame << x, y, s;
    Vector3d low = Vector3d::Constant(1e300), high = Vector3d::Constant(-1e300);
    for (std::size_t k : {std::size_t(0), stack.positions.size() - 1})
        for (double i : {0.0, double(stack.columns - 1)})
            for (double j : {0.0, double(stack.rows - 1)})
            {
                const Vector3d local = frame.transpose() * stack.pixelPosition(k, i, j);
                low = low.cwiseMin(local);
                high = high.cwiseMax(local);
            }
    VolumeGeometry grid;
    grid.spacing = {stack.columnSpacing, stack.rowSpacing, advanceSpacing};
    grid.direction = frame;
    grid.origin = frame * low;
    for (int axis = 0; axis < 3; ++axis)
        grid.dims[axis] = int(std::floor((high[axis] - low[axis]) / grid.spacing[axis] + 1e-6)) + 1;
    return grid;
}

} // namespace

SliceStack SeriesGeometry::sourceStack(const DicomSeries& series) const
{
    const FrameGeometry& first = series.geometryOf(sorted.front());
    SliceStack stack;
    stack.columns = series.format().columns;
    stack.rows = series.format().rows;
    stack.columnSpacing = first.columnSpacing;
    stack.rowSpacing = first.rowSpacing;
    stack.xDirection = first.xDirection;
    stack.yDirection = first.yDirection;
    for (const DicomSlice& slice : sorted)
        stack.positions.push_back(series.geometryOf(slice).position);
    return stack;
}

SeriesGeometry planSeriesGeometry(const DicomSeries& series)
{
    if (series.slices.empty())
        throw Error("the series has no images");
    requirePlacement(series);
    SeriesGeometry plan;
    const FrameGeometry& first = series.firstGeometry();
    const Vector3d normal = first.xDirection.cross(first.yDirection).normalized();

    // Sort along the normal; equal positions keep the lowest instance number first.
    std::vector<DicomSlice> slices = series.slices;
    auto height = [&](const DicomSlice& slice) { return series.geometryOf(slice).position.dot(normal); };
    std::stable_sort(slices.begin(), slices.end(), [&](const DicomSlice& a, const DicomSlice& b) {
        const double ha = height(a), hb = height(b);
        if (std::abs(ha - hb) > kDuplicateToleranceMm)
            return ha < hb;
        return std::make_pair(series.headerOf(a).instanceNumber, a.frame) <
               std::make_pair(series.headerOf(b).instanceNumber, b.frame);
    });
    for (const DicomSlice& slice : slices)
    {
        if (!plan.sorted.empty() && std::abs(height(slice) - height(plan.sorted.back())) <= kDuplicateToleranceMm)
        {
            ++plan.duplicateSlices;
            continue;
        }
        plan.sorted.push_back(slice);
    }
    if (plan.duplicateSlices > 0)
        plan.warnings.push_back(storedText(Pattern{
            "%1 slices at duplicate positions dropped (kept the lowest instance number)",
            {std::to_string(plan.duplicateSlices)}}));
    const double h0 = height(plan.sorted.front());
    for (const DicomSlice& slice : plan.sorted)
        plan.offsets.push_back(height(slice) - h0);

    const SliceStack stack = plan.sourceStack(series);
    const std::size_t count = plan.sorted.size();
    if (count == 1)
    {
        plan.grid = stack.nominalGeometry();
        plan.grid.spacing.z() = first.sliceThickness > 0.0 ? first.sliceThickness : 1.0;
        plan.warnings.push_back(storedText("the series has a single slice"));
        return plan;
    }

    // Spacing, gaps, unevenness.
    std::vector<double> gaps;
    for (std::size_t k = 1; k < count; ++k)
        gaps.push_back(plan.offsets[k] - plan.offsets[k - 1]);
    const double spacing = median(gaps);
    const double tolerance = std::max(1e-3, 0.01 * spacing);
    bool uneven = false;
    for (double gap : gaps)
    {
        const double multiple = std::round(gap / spacing);
        if (multiple >= 2.0 && std::abs(gap - multiple * spacing) <= tolerance * multiple)
            plan.missingSlices += int(multiple) - 1;
        else if (std::abs(gap - spacing) > tolerance)
            uneven = true;
    }
    const auto [smallest, largest] = std::minmax_element(gaps.begin(), gaps.end());
    if (plan.missingSlices > 0)
        plan.warnings.push_back(storedText(Pattern{
            "%1 missing slices (gaps up to %2 mm where the spacing is %3 mm): filled by interpolation",
            {std::to_string(plan.missingSlices), storedNumber(*largest, 2), storedNumber(spacing, 2)}}));
    if (uneven)
        plan.warnings.push_back(storedText(Pattern{"uneven slice spacing (%1 to %2 mm): resampled to %3 mm",
                                                   {storedNumber(*smallest, 3), storedNumber(*largest, 3),
                                                    storedNumber(spacing, 3)}}));

    // Gantry tilt: the slices advance off their normal.
    const Vector3d advance = stack.positions.back() - stack.positions.front();
    const Vector3d inPlane = advance - advance.dot(normal) * normal;
    const bool tilted = inPlane.norm() > 0.1 * std::min(stack.columnSpacing, stack.rowSpacing);
    plan.tiltDegrees = std::atan2(inPlane.norm(), advance.dot(normal)) * 180.0 / std::numbers::pi;

    plan.resample = tilted || uneven || plan.missingSlices > 0;
    if (tilted)
    {
        const double advanceSpacing = spacing / std::cos(plan.tiltDegrees * std::numbers::pi / 180.0);
        plan.grid = tiltedGrid(stack, advance, advanceSpacing);
        plan.warnings.push_back(storedText(Pattern{"gantry tilt of %1 degrees: resampled onto an orthogonal grid",
                                                   {storedNumber(plan.tiltDegrees, 2)}}));
    }
    else
    {
        // Even stacks keep their slices; otherwise the grid spans the same extent at the median spacing.
        plan.grid = stack.nominalGeometry();
        plan.grid.dims[2] = plan.resample ? int(std::lround(plan.offsets.back() / spacing)) + 1 : int(count);
        plan.grid.spacing.z() = plan.offsets.back() / double(plan.grid.dims[2] - 1);
    }
    plan.grid.validate();
    return plan;
}

} // namespace vsim::dicom
