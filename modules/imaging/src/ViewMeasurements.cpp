#include "vsim/imaging/ViewMeasurements.h"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

#include <cmath>

namespace vsim::imaging {
namespace {

void measureRoi(ViewMeasurement& roi, const CtVolume& ct)
{
    const RoiEllipse ellipse = roiEllipse(roi);
    const VolumeGeometry& geometry = ct.geometry();
    const double step = geometry.spacing.minCoeff();
    const int halfRight = int(std::ceil(ellipse.semiAxisRightMm / step)), halfUp = int(std::ceil(ellipse.semiAxisUpMm / step));
    double sum = 0.0, sumSquares = 0.0;
    long long count = 0;
    for (int v = -halfUp; v <= halfUp; ++v)
        for (int u = -halfRight; u <= halfRight; ++u)
        {
            const double x = u * step, y = v * step;
            const double a = ellipse.semiAxisRightMm, b = ellipse.semiAxisUpMm;
            if (a <= 0.0 || b <= 0.0 || (x * x) / (a * a) + (y * y) / (b * b) > 1.0)
                continue;
            const Eigen::Vector3d index = geometry.patientToIndex(ellipse.centreMm + x * roi.planeRight + y * roi.planeUp);
            const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
            if (!geometry.contains(i, j, k))
                continue;
            const double value = ct.at(i, j, k);
            sum += value;
            sumSquares += value * value;
            ++count;
        }
    if (count == 0)
        throw Error("the ROI holds no voxel of the image: draw it larger or inside the volume");
    roi.samples = count;
    roi.meanHu = sum / double(count);
    roi.sdHu = count > 1 ? std::sqrt(std::max(0.0, (sumSquares - sum * sum / double(count)) / double(count - 1))) : 0.0;
    roi.areaMm2 = M_PI * ellipse.semiAxisRightMm * ellipse.semiAxisUpMm;
}

} // namespace

void measure(ViewMeasurement& measurement, const CtVolume& ct)
{
    const auto& p = measurement.pointsMm;
    if (int(p.size()) != pointCount(measurement.kind))
        throw Error(Pattern{"a %1 takes %2 points",
                            {kindName(measurement.kind), std::to_string(pointCount(measurement.kind))}});
    switch (measurement.kind)
    {
    case ViewMeasurement::Kind::Ruler: measurement.lengthMm = (p[1] - p[0]).norm(); break;
    case ViewMeasurement::Kind::Angle:
    {
        const Eigen::Vector3d a = p[0] - p[1], b = p[2] - p[1];
        if (a.norm() < 1e-9 || b.norm() < 1e-9)
            throw Error("an angle's arms must have a length: its points coincide");
        measurement.angleDegrees = std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI;
        break;
    }
    case ViewMeasurement::Kind::Roi: measureRoi(measurement, ct); break;
    }
}

} // namespace vsim::imaging
