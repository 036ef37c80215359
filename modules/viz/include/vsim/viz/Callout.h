#pragma once

// A place called out in a 3D picture (the report's snapshots, the workstation's 3D view): a caption left of the
// surface at the point's height with a line to the point, and a dark ball on it (hidden where the point lies on
// the far side, so the text should say so).

#include <Eigen/Core>

#include <string>

namespace vsim::viz {

struct Callout
{
    Eigen::Vector3d pointMm = Eigen::Vector3d::Zero();
    std::string text; ///< "PWS 242 kPa, 4.04 h (posterior)"
};

} // namespace vsim::viz
