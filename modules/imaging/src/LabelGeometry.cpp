#include "LabelGeometry.h"

#include "vsim/core/Error.h"
#include "vsim/interop/ItkImage.h"

#include <itkSignedMaurerDistanceMapImageFilter.h>

#include <algorithm>

namespace vsim::imaging {

std::optional<std::pair<std::array<int, 3>, std::array<int, 3>>> labelBounds(const LabelVolume& label,
                                                                             std::uint8_t value)
{
    const auto& d = label.geometry().dims;
    std::array<int, 3> low{d[0], d[1], d[2]}, high{-1, -1, -1};
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
                if (label.at(i, j, k) == value)
                {
                    low = {std::min(low[0], i), std::min(low[1], j), std::min(low[2], k)};
                    high = {std::max(high[0], i), std::max(high[1], j), std::max(high[2], k)};
                }
    if (high[0] < 0)
        return std::nullopt;
    return std::make_pair(low, high);
}

RealVolume insideDistanceMm(const LabelVolume& label, std::uint8_t value)
{
    LabelVolume binary(label.geometry());
    std::transform(label.data(), label.data() + label.size(), binary.data(),
                   [value](std::uint8_t v) { return std::uint8_t(v == value); });
    auto filter =
        itk::SignedMaurerDistanceMapImageFilter<interop::ItkImage3<std::uint8_t>, itk::Image<float, 3>>::New();
    filter->SetInput(interop::toItk(binary));
    filter->SetUseImageSpacing(true);
    filter->SetInsideIsPositive(true);
    filter->SetSquaredDistance(false);
    filter->Update();
    return interop::fromItk<float>(filter->GetOutput());
}

LabelCrop cropLabel(const LabelVolume& label, std::uint8_t value, int margin)
{
    const auto bounds = labelBounds(label, value);
    if (!bounds)
        throw Error("the label is empty: segment the vessels first");
    const auto& [low, high] = *bounds;
    const auto& d = label.geometry().dims;
    VolumeGeometry geometry = label.geometry();
    LabelCrop crop;
    for (int a = 0; a < 3; ++a)
    {
        crop.start[a] = std::max(0, low[a] - margin);
        geometry.dims[a] = std::min(d[a] - 1, high[a] + margin) - crop.start[a] + 1;
    }
    geometry.origin = label.geometry().indexToPatient(Eigen::Vector3d(crop.start[0], crop.start[1], crop.start[2]));
    crop.binary = LabelVolume(geometry);
    for (int k = 0; k < geometry.dims[2]; ++k)
        for (int j = 0; j < geometry.dims[1]; ++j)
            for (int i = 0; i < geometry.dims[0]; ++i)
                crop.binary.at(i, j, k) = label.at(crop.start[0] + i, crop.start[1] + j, crop.start[2] + k) == value;
    return crop;
}

CroppedDistance croppedInsideDistanceMm(const LabelVolume& label, std::uint8_t value, int margin)
{
    const LabelCrop crop = cropLabel(label, value, margin);
    return {insideDistanceMm(crop.binary, 1), crop.start};
}

} // namespace vsim::imaging
