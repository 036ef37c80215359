#pragma once

// A noisy phantom CT segmented with the default parameters and the automatic seed: the input of the skeleton,
// centerline, measurement and surface tests that start from a segmentation rather than from the truth label.

#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/VesselSegmentation.h"

namespace vsim::test {

struct SegmentedPhantom
{
    dicom::PhantomModel model;
    LabelVolume label;
};

/// Renders `kind` (20 HU noise, `seed`) on `size` voxels of `spacing` mm and segments it.
inline SegmentedPhantom segmentPhantom(dicom::PhantomKind kind, std::array<int, 3> size, Eigen::Vector3d spacing,
                                       std::uint64_t seed)
{
    dicom::PhantomOptions options;
    options.size = size;
    options.spacing = spacing;
    options.seed = seed;
    SegmentedPhantom result;
    result.model = dicom::buildPhantomModel(kind, options);
    const VolumeGeometry geometry = dicom::phantomGeometry(options);
    const CtVolume ct = dicom::renderPhantomCt(result.model, dicom::stackOf(geometry), options);
    result.label = imaging::segmentVessels(ct, ParameterSet(imaging::segmentationParameters())).label;
    return result;
}

} // namespace vsim::test
