// The virtual endoscope's frame time (issue 20, item 8): the camera flown along a curved vessel (a tube of 4 mm
// radius, 64 sides, on a helix of 30 mm radius and 60 mm pitch, 300 mm of it) at 640 x 480, each frame rendered
// offscreen by VTK with its depth read back, then the lens (EndoscopeOptics.h) applied, in focus and out of focus.
// Needs a display (xvfb-run):
//
//   bench_endoscope [frames=60]
//
// Prints one JSON object: the median milliseconds per frame of the whole (render, read back, lens) and of the lens
// alone, and the frames per second they allow.
#include "vsim/imaging/CurvedReformation.h"
#include "vsim/viz/EndoscopeOptics.h"
#include "vsim/viz/EndoscopeView.h"

#include <QApplication>
#include <QSurfaceFormat>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

using namespace vsim;

namespace {

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double millisecondsSince(std::chrono::steady_clock::time_point start)
{
    return 1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

Eigen::Vector3d helix(double s)
{
    const double turn = 2.0 * std::numbers::pi * s / 220.0; // arc per turn of a 30 mm radius, 60 mm pitch helix
    return {30.0 * std::cos(turn), 30.0 * std::sin(turn), 60.0 * turn / (2.0 * std::numbers::pi)};
}

} // namespace

int main(int argc, char** argv)
{
    QSurfaceFormat format;
    format.setVersion(3, 2);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);
    QApplication application(argc, argv);
    const int frameCount = argc > 1 ? std::stoi(argv[1]) : 60;

    std::vector<Eigen::Vector3d> centre;
    for (double s = 0.0; s <= 300.0; s += 1.0)
        centre.push_back(helix(s));
    const imaging::CenterlineFrames frames = imaging::centerlineFrames(centre, {}, 1.0);
    TriangleMesh tube;
    constexpr int kSides = 64;
    for (std::size_t i = 0; i < frames.points.size(); ++i)
        for (int k = 0; k < kSides; ++k)
        {
            const double a = 2.0 * std::numbers::pi * k / kSides;
            tube.points.push_back(frames.points[i] + 4.0 * (std::cos(a) * frames.normals[i] + std::sin(a) * frames.binormals[i]));
        }
    for (int i = 0; i + 1 < int(frames.points.size()); ++i)
        for (int k = 0; k < kSides; ++k)
        {
            const int a = i * kSides + k, b = i * kSides + (k + 1) % kSides;
            tube.triangles.push_back({a, b, a + kSides});
            tube.triangles.push_back({b, b + kSides, a + kSides});
        }

    viz::EndoscopeView view;
    view.resize(640, 480);
    view.setLumen(tube);
    std::vector<double> whole, lens, blur;
    for (bool focused : {true, false})
    {
        viz::EndoscopeLens optics;
        optics.focusDistanceMm = focused ? 12.0 : 2.5;
        view.setLens(optics);
        for (int f = 0; f < frameCount; ++f)
        {
            const std::size_t i = std::size_t(20 + f * 3) % (frames.points.size() - 40);
            view.setPose(frames.points[i], frames.tangents[i], frames.normals[i]);
            const auto start = std::chrono::steady_clock::now();
            const QImage shown = view.picture();
            whole.push_back(millisecondsSince(start));
            const auto lensStart = std::chrono::steady_clock::now();
            viz::lensImage(view.sharpPicture(), view.depthMm(), optics, unsigned(f));
            lens.push_back(millisecondsSince(lensStart));
            blur.push_back(view.medianBlurPx());
        }
    }
    const double frameMs = median(whole), lensMs = median(lens);
    std::printf("{\"bench\": \"endoscope\", \"width\": 640, \"height\": 480, \"frames\": %d, \"triangles\": %zu, "
                "\"median_frame_ms\": %.1f, \"median_lens_ms\": %.1f, \"median_render_and_readback_ms\": %.1f, "
                "\"frames_per_second\": %.1f, \"median_blur_px\": %.2f}\n",
                int(whole.size()), tube.triangles.size(), frameMs, lensMs, frameMs - lensMs, 1e3 / frameMs, median(blur));
    return 0;
}
