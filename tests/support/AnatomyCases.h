#pragma once

// Patient-like phantom cases for the segmentation and naming tests: the anatomy, its CT on a grid shifted from the
// phantom's centre, its truth labels; the truth artery of a name and its point at a height.

#include "vsim/core/Error.h"
#include "vsim/dicom/AnatomyPhantom.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace vsim::test {

struct AnatomyCase
{
    dicom::AnatomyPhantom phantom;
    CtVolume ct;
    LabelVolume truth; ///< empty unless asked for
};

/// The patient-like phantom of `kind` rendered on `size` voxels of `spacing` mm around the phantom's centre moved by
/// `shiftMm`; the truth labels too when `withTruth`.
inline AnatomyCase makeAnatomyCase(dicom::PhantomKind kind, std::array<int, 3> size, const Eigen::Vector3d& spacing,
                                   std::uint64_t seed, const Eigen::Vector3d& shiftMm, bool withTruth)
{
    dicom::PhantomOptions options;
    options.style = dicom::PhantomStyle::Patient;
    options.size = size;
    options.spacing = spacing;
    options.seed = seed;
    AnatomyCase c{dicom::buildAnatomyPhantom(kind, options), {}, {}};
    VolumeGeometry geometry = dicom::phantomGeometry(options);
    geometry.origin += shiftMm;
    c.ct = dicom::renderAnatomyCt(c.phantom, geometry, seed);
    if (withTruth)
        c.truth = dicom::renderAnatomyLabels(c.phantom, geometry);
    return c;
}

/// The phantom's first truth artery of that name; throws vsim::Error when there is none.
inline const dicom::VesselSegment& segmentNamed(const dicom::AnatomyPhantom& phantom, const std::string& name)
{
    for (const dicom::VesselSegment& segment : phantom.arteries.segments)
        if (segment.name == name)
            return segment;
    throw Error("no segment " + name);
}

/// The point of `segment`'s centerline nearest to height z (mm).
inline Eigen::Vector3d pointAtZ(const dicom::VesselSegment& segment, double z)
{
    return *std::min_element(segment.points.begin(), segment.points.end(),
                             [&](const auto& a, const auto& b) { return std::abs(a.z() - z) < std::abs(b.z() - z); });
}

} // namespace vsim::test
