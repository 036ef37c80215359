#include "vsim/app/ProjectionPicture.h"

#include <cmath>

namespace vsim::app {

QImage projectionPicture(const sim::network::ProjectionImage& image)
{
    QImage picture(image.width, image.height, QImage::Format_Grayscale8);
    for (int y = 0; y < image.height; ++y)
    {
        uchar* row = picture.scanLine(y);
        for (int x = 0; x < image.width; ++x)
            row[x] = uchar(std::lround(255.0f * image.transmission[std::size_t(y) * std::size_t(image.width) + std::size_t(x)]));
    }
    return picture;
}

} // namespace vsim::app
