#pragma once

// A CT for view tests: air with a bright 5x5x5 voxel block (3000 HU) at a known LPS position, stored with a flipped
// direction matrix (x and y reversed, as RAS-ordered scanners write it) and anisotropic voxels (0.8, 0.9, 1.5 mm);
// and where the white block lands in a picture.
#include "vsim/core/ImageVolume.h"

#include <QImage>
#include <QPointF>

#include <algorithm>
#include <cstdint>

namespace vsim::test {

constexpr std::int16_t kMarkerHu = 3000;

struct Phantom
{
    vsim::CtVolume image;
    Eigen::Vector3d marker; // LPS mm
};

inline Phantom markerPhantom()
{
    vsim::VolumeGeometry geometry;
    geometry.dims = {100, 90, 80};
    geometry.spacing = {0.8, 0.9, 1.5};
    geometry.origin = {40.0, 30.0, -60.0};
    geometry.direction.diagonal() << -1.0, -1.0, 1.0; // i runs right-ward, j anterior-ward
    Phantom phantom{vsim::CtVolume(geometry), {}};
    std::fill(phantom.image.data(), phantom.image.data() + phantom.image.size(), std::int16_t(-1000));
    const int centre[3] = {30, 62, 55}; // some voxel off the volume centre
    for (int k = -2; k <= 2; ++k)
        for (int j = -2; j <= 2; ++j)
            for (int i = -2; i <= 2; ++i)
                phantom.image.at(centre[0] + i, centre[1] + j, centre[2] + k) = kMarkerHu;
    phantom.marker = geometry.indexToPatient({double(centre[0]), double(centre[1]), double(centre[2])});
    return phantom;
}

/// Centroid of the pixels brighter than `threshold` in all three channels (white marker; yellow labels excluded).
inline QPointF brightCentroid(const QImage& image, int threshold, int* count)
{
    double sumX = 0, sumY = 0;
    *count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
        {
            const QRgb pixel = image.pixel(x, y);
            if (qRed(pixel) > threshold && qGreen(pixel) > threshold && qBlue(pixel) > threshold)
                sumX += x, sumY += y, ++*count;
        }
    return *count ? QPointF(sumX / *count, sumY / *count) : QPointF(-1, -1);
}

} // namespace vsim::test
