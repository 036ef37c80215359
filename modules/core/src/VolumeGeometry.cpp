#include "vsim/core/VolumeGeometry.h"

#include "vsim/core/Error.h"

#include <Eigen/Dense>

#include <cmath>
#include <string>

namespace vsim {

void VolumeGeometry::validate() const
{
    for (int axis = 0; axis < 3; ++axis)
    {
        if (dims[axis] <= 0)
            throw Error("volume dimension is not positive",
                        {{"axis", std::to_string(axis)}, {"size", std::to_string(dims[axis])}});
        if (!(spacing[axis] > 0.0) || !std::isfinite(spacing[axis]))
            throw Error("voxel spacing must be positive and finite (mm)",
                        {{"axis", std::to_string(axis)}, {"spacing", std::to_string(spacing[axis])}});
    }
    if (!origin.allFinite())
        throw Error("volume origin is not finite");
    const double orthonormalError = (direction.transpose() * direction - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(orthonormalError < 1e-6))
        throw Error("direction matrix is not orthonormal", {{"deviation", std::to_string(orthonormalError)}});
}

bool VolumeGeometry::isClose(const VolumeGeometry& other, double tolerance) const
{
    return dims == other.dims && (spacing - other.spacing).cwiseAbs().maxCoeff() <= tolerance &&
           (origin - other.origin).cwiseAbs().maxCoeff() <= tolerance &&
           (direction - other.direction).cwiseAbs().maxCoeff() <= tolerance;
}

} // namespace vsim
