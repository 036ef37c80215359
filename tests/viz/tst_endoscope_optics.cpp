// The virtual endoscope's lens (EndoscopeOptics.h) against the thin-lens formulas: the field of view of a
// focal length, the circle of confusion (zero at the focus distance, the analytic value at twice it and at
// infinity), an edge at a known depth blurred to the Gaussian the formula gives (10-90 % width 2.563 sigma,
// within 10 %), a picture in focus left exactly as it was (lit fully within the lamp's reach), the lamp's 1 /
// d^2 fall-off, and the defocus noise: none in focus, its standard deviation following the median blur, on
// three seeds.
#include "vsim/viz/EndoscopeOptics.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>

using namespace vsim::viz;

namespace {

constexpr int kWidth = 200, kHeight = 120;

/// A grey picture with a vertical edge at the middle (left `dark`, right `bright`), every pixel at `depthMm`.
QImage edgePicture(int dark, int bright)
{
    QImage picture(kWidth, kHeight, QImage::Format_RGB888);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
        {
            const int v = x < kWidth / 2 ? dark : bright;
            picture.setPixelColor(x, y, QColor(v, v, v));
        }
    return picture;
}

std::vector<float> flatDepth(float depthMm)
{
    return std::vector<float>(std::size_t(kWidth) * kHeight, depthMm);
}

/// The 10-90 % rise of the edge along the middle row (pixels), by linear interpolation.
double riseWidth(const QImage& picture, int dark, int bright)
{
    const int y = kHeight / 2;
    auto crossing = [&](double level)
    {
        for (int x = 1; x < kWidth; ++x)
        {
            const double a = picture.pixelColor(x - 1, y).red(), b = picture.pixelColor(x, y).red();
            if (a < level && b >= level)
                return x - 1 + (level - a) / (b - a);
        }
        return std::numeric_limits<double>::quiet_NaN();
    };
    return crossing(dark + 0.9 * (bright - dark)) - crossing(dark + 0.1 * (bright - dark));
}

} // namespace

class TestEndoscopeOptics : public QObject
{
    Q_OBJECT

private slots:
    void thinLensFormulas()
    {
        EndoscopeLens lens;
        lens.focalLengthMm = 2.0;
        lens.sensorWidthMm = 4.0;
        QCOMPARE(horizontalFieldOfViewDegrees(lens), 90.0);
        lens.focalLengthMm = 4.0;
        QVERIFY(std::abs(horizontalFieldOfViewDegrees(lens) -
                         2.0 * std::atan(0.5) * 180.0 / std::numbers::pi) < 1e-12);
        lens.focalLengthMm = 3.0;
        lens.fNumber = 2.5;
        lens.focusDistanceMm = 20.0;
        const double scale = 9.0 / (2.5 * 17.0); // f^2 / (N (d_f - f))
        QCOMPARE(circleOfConfusionMm(lens, 20.0), 0.0);
        QVERIFY(std::abs(circleOfConfusionMm(lens, 40.0) - scale * 0.5) < 1e-12);
        QVERIFY(std::abs(circleOfConfusionMm(lens, 10.0) - scale * 1.0) < 1e-12);
        QVERIFY(std::abs(circleOfConfusionMm(lens, std::numeric_limits<double>::infinity()) - scale) < 1e-12);
        QVERIFY(std::abs(blurSigmaPx(lens, 40.0, 400) - 0.25 * scale * 0.5 * 400 / 4.0) < 1e-12);
    }

    void inFocusPictureUnchanged()
    {
        EndoscopeLens lens;
        lens.focusDistanceMm = 10.0;
        lens.lampReachMm = 12.0;
        const QImage sharp = edgePicture(40, 200);
        double median = -1.0;
        const QImage seen = lensImage(sharp, flatDepth(10.0f), lens, 1, &median);
        QCOMPARE(median, 0.0);
        QCOMPARE(seen, sharp.convertToFormat(QImage::Format_RGB888));
    }

    void lampFallsOffAsInverseSquare()
    {
        EndoscopeLens lens;
        lens.focusDistanceMm = 24.0;
        lens.lampReachMm = 12.0;
        lens.autoGain = false;
        const QImage seen = lensImage(edgePicture(200, 200), flatDepth(24.0f), lens, 1);
        QCOMPARE(seen.pixelColor(10, 10).red(), 50); // 200 x (12 / 24)^2
        const QImage nothing =
            lensImage(edgePicture(200, 200), flatDepth(std::numeric_limits<float>::infinity()), lens, 1);
        QCOMPARE(nothing.pixelColor(10, 10).red(), 0); // no wall hit: dark
        lens.autoGain = true;
        lens.noiseAtFullDefocus = 0.0; // 60 mm is out of focus; the grain is tested below
        // the gain lifts the dim wall to 200, up to 8 times
        QCOMPARE(lensImage(edgePicture(200, 200), flatDepth(24.0f), lens, 1).pixelColor(10, 10).red(), 200);
        QCOMPARE(lensImage(edgePicture(200, 200), flatDepth(60.0f), lens, 1).pixelColor(10, 10).red(),
                 64); // 8 x 8
    }

    void edgeBlurredByTheCircleOfConfusion_data()
    {
        QTest::addColumn<double>("focusMm");
        QTest::newRow("1.4 px") << 8.6;
        QTest::newRow("3 px") << 7.0;
        QTest::newRow("6 px") << 5.2;
    }

    void edgeBlurredByTheCircleOfConfusion()
    {
        QFETCH(double, focusMm);
        EndoscopeLens lens;
        lens.focalLengthMm = 2.0;
        lens.fNumber = 1.4;
        lens.focusDistanceMm = focusMm;
        lens.lampReachMm = 100.0; // fully lit
        lens.noiseAtFullDefocus = 0.0;
        const double depth = 12.0;
        const double sigma = blurSigmaPx(lens, depth, kWidth);
        const QImage seen = lensImage(edgePicture(20, 220), flatDepth(float(depth)), lens, 1);
        const double rise = riseWidth(seen, 20, 220);
        qInfo("focus %.1f mm: sigma %.2f px, 10-90 %% rise %.2f px (Gaussian %.2f px)", focusMm, sigma, rise,
              2.563 * sigma);
        QVERIFY(std::abs(rise / (2.563 * sigma) - 1.0) < 0.10);
    }

    void noiseFollowsTheDefocus_data()
    {
        QTest::addColumn<unsigned>("seed");
        for (unsigned seed : {1u, 2u, 3u})
            QTest::newRow(qPrintable(QString("seed %1").arg(seed))) << seed;
    }

    void noiseFollowsTheDefocus()
    {
        QFETCH(unsigned, seed);
        EndoscopeLens lens;
        lens.focalLengthMm = 2.0;
        lens.fNumber = 2.0;
        lens.lampReachMm = 100.0;
        lens.noiseAtFullDefocus = 30.0;
        lens.fullDefocusBlurFraction = 4.0 / kWidth; // full at 4 px
        const QImage grey = edgePicture(128, 128);
        for (double focus : {12.0, 10.0, 8.0, 4.0})
        {
            lens.focusDistanceMm = focus;
            double median = 0.0;
            const QImage seen = lensImage(grey, flatDepth(12.0f), lens, seed, &median);
            double sum = 0.0, squares = 0.0;
            for (int y = 0; y < kHeight; ++y)
                for (int x = 0; x < kWidth; ++x)
                {
                    const double v = seen.pixelColor(x, y).green() - 128.0;
                    sum += v, squares += v * v;
                }
            const double n = double(kWidth) * kHeight, sd = std::sqrt(squares / n - (sum / n) * (sum / n));
            const double expected = 30.0 * std::min(1.0, median / 4.0);
            qInfo("focus %.0f mm: median blur %.2f px, noise sd %.2f (expected %.2f)", focus, median, sd,
                  expected);
            QVERIFY(std::abs(median - blurSigmaPx(lens, 12.0, kWidth)) < 1e-6);
            QVERIFY(std::abs(sd - expected) < 0.05 * expected + 0.3);
        }
    }
};

QTEST_GUILESS_MAIN(TestEndoscopeOptics)
#include "tst_endoscope_optics.moc"
