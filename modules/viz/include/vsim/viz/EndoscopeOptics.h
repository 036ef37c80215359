#pragma once

// The virtual endoscope's optics (issue 20, item 8; thesis 5.5.2): a thin lens of adjustable focal length and
// focus distance in front of a small sensor, and what it does to a sharp rendered picture with its depth. Out
// of focus a point at depth d spreads into a circle of confusion of diameter
//     c(d) = f^2 / (N (d_f - f)) * |d - d_f| / d      (on the sensor, mm; f focal length, N f-number, d_f
//     focus)
// (the thin-lens equation; e.g. Potmesil & Chakravarty, Computer Graphics 15(3) 1981). The picture is blurred
// per pixel by a Gaussian of standard deviation c / 4 (a uniform disc's, per axis), gathered from a stack of
// blurred copies. The thesis's observation that an unfocused probe shows "a significant amount of noise" that
// focusing removes is modelled as sensor noise that grows with the defocus: the standard deviation of added
// Gaussian noise is noiseAtFullDefocus x min(1, median blur / (fullDefocusBlurFraction x width)). Light falls off from the
// probe's lamp as min(1, (lampReachMm / d)^2), and the camera's automatic gain lifts a wide lumen's dim
// picture. No Qt widgets, no VTK: the view (EndoscopeView) renders and calls these.

#include <QImage>

#include <cstdint>
#include <vector>

namespace vsim::viz {

struct EndoscopeLens
{
    double focalLengthMm = 2.0;    ///< sets the field of view with the sensor (2 mm: 90 degrees across)
    double fNumber = 2.0;          ///< aperture: smaller opens it and shortens the depth of field
    double focusDistanceMm = 15.0; ///< the depth in focus, along the view axis
    double sensorWidthMm = 4.0;    ///< a small CMOS probe camera
    double lampReachMm = 12.0;     ///< full brightness up to this depth, then 1 / d^2
    bool autoGain = true; ///< the camera's gain brings the 90th percentile of brightness to 200 (x8 at most)
    double noiseAtFullDefocus = 28; ///< grey levels (0-255), standard deviation
    /// The median blur (standard deviation) at which the noise is full, as a fraction of the picture's width: the
    /// same optics give the same noise at any resolution (1.25 %: 4 pixels across 320).
    double fullDefocusBlurFraction = 0.0125;
};

/// The horizontal field of view (degrees): 2 atan(sensor / 2f).
double horizontalFieldOfViewDegrees(const EndoscopeLens& lens);
/// The circle of confusion's diameter on the sensor (mm) for a point at `depthMm` along the view axis.
double circleOfConfusionMm(const EndoscopeLens& lens, double depthMm);
/// The blur (Gaussian standard deviation, pixels) of a point at `depthMm` in a picture `widthPx` wide.
double blurSigmaPx(const EndoscopeLens& lens, double depthMm, int widthPx);

/// What the probe shows: `sharp` (RGB) with its depth per pixel (mm along the view axis, row-major from the
/// top row; infinity where nothing was drawn) lit by the lamp, blurred by depth and with the defocus noise
/// (drawn from `seed`). `medianBlurPx`, when given, receives the defocus measure the noise follows.
QImage lensImage(const QImage& sharp, const std::vector<float>& depthMm, const EndoscopeLens& lens,
                 std::uint32_t seed, double* medianBlurPx = nullptr);

} // namespace vsim::viz
