#pragma once

// Pixel checks shared by the GUI tests: how many pixels of a picture carry the measurements' and calipers' cyan
// (viz: SliceMeasurementLayer, PlaneImageView), whatever their antialiased brightness.
#include <QImage>

namespace vsim::test {

inline int cyanPixels(const QImage& image)
{
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
        {
            const QRgb p = image.pixel(x, y);
            count += qBlue(p) > 150 && qGreen(p) > 0.7 * qBlue(p) && qRed(p) < 0.5 * qBlue(p);
        }
    return count;
}

} // namespace vsim::test
