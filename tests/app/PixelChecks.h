#pragma once

// Pixel checks shared by the GUI tests: how many pixels of a picture carry the measurements' and calipers' cyan
// (viz: SliceMeasurementLayer, PlaneImageView), or the outer-wall caliper's yellow within a part of the picture,
// whatever their antialiased brightness.
#include <QImage>
#include <QRect>

#include <algorithm>

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

inline int yellowPixels(const QImage& image, const QRect& within)
{
    int count = 0;
    for (int y = std::max(0, within.top()); y <= std::min(image.height() - 1, within.bottom()); ++y)
        for (int x = std::max(0, within.left()); x <= std::min(image.width() - 1, within.right()); ++x)
        {
            const QRgb p = image.pixel(x, y);
            count += qRed(p) > 150 && qGreen(p) > 0.6 * qRed(p) && qBlue(p) < 0.45 * qRed(p);
        }
    return count;
}

} // namespace vsim::test
