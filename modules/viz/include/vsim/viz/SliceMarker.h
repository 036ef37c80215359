#pragma once

#include <Eigen/Core>

#include <array>
#include <string>

namespace vsim::viz {

/// A point drawn on the MPR views, e.g. an include or exclude point of the guided segmentation: a ring and its
/// text in every view whose slice passes within one slice spacing of it. The user can drag it (SliceView).
struct SliceMarker
{
    int id = 0;                             ///< the owner's key, reported back when the marker is dragged
    Eigen::Vector3d pointMm = Eigen::Vector3d::Zero(); ///< patient frame (LPS), mm
    std::array<double, 3> rgb{0.2, 1.0, 0.3};
    std::string text;                       ///< drawn beside the ring (Latin-1)
};

} // namespace vsim::viz
