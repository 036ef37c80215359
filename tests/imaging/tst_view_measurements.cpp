// The figures of measurements drawn on views (imaging/ViewMeasurements.h), against truths written here: a ruler's
// length and an angle from known points; an elliptical ROI on CTs with Gaussian noise of known level and SD
// (several seeds): its mean within 4 standard errors, its SD within 10 %, its area pi a b; an ROI across two
// regions averages them by area; bad input is refused. And the measurement's round trip through a saved study.
#include "StudyFixtures.h"
#include "TestOutput.h"
#include "vsim/imaging/ViewMeasurements.h"
#include "vsim/study/Study.h"

#include <QtTest>

#include <filesystem>
#include <random>

using namespace vsim;

namespace {

CtVolume noisyCt(double levelHu, double sdHu, unsigned seed, double rightHalfHu)
{
    VolumeGeometry geometry;
    geometry.dims = {80, 80, 20};
    geometry.spacing = {0.7, 0.7, 2.0};
    geometry.origin = {-28.0, -28.0, -20.0};
    CtVolume ct(geometry);
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, sdHu);
    for (int k = 0; k < 20; ++k)
        for (int j = 0; j < 80; ++j)
            for (int i = 0; i < 80; ++i)
                ct.at(i, j, k) = std::int16_t(std::lround((i >= 40 ? rightHalfHu : levelHu) + noise(random)));
    return ct;
}

ViewMeasurement axialRoi(const Eigen::Vector3d& centre, double a, double b)
{
    ViewMeasurement roi;
    roi.kind = ViewMeasurement::Kind::Roi;
    roi.planeRight = {1, 0, 0};
    roi.planeUp = {0, -1, 0};
    roi.pointsMm = {centre - a * roi.planeRight - b * roi.planeUp, centre + a * roi.planeRight + b * roi.planeUp};
    return roi;
}

} // namespace

class TestViewMeasurements : public QObject
{
    Q_OBJECT

private slots:
    void rulerAndAngle()
    {
        const CtVolume none;
        ViewMeasurement ruler;
        ruler.pointsMm = {{1.0, 2.0, 3.0}, {4.0, 6.0, 15.0}};
        imaging::measure(ruler, none);
        QCOMPARE(ruler.lengthMm, 13.0); // 3-4-12 -> 13
        QCOMPARE(measurementText(ruler), std::string("13.0 mm"));

        ViewMeasurement angle;
        angle.kind = ViewMeasurement::Kind::Angle;
        for (const auto& [far, truth] : std::vector<std::pair<Eigen::Vector3d, double>>{
                 {{0.0, 10.0, 5.0}, 90.0}, {{10.0, 10.0, 5.0}, 45.0}, {{-10.0, 0.0, 5.0}, 180.0}, {{20.0, 0.0, 5.0}, 0.0}})
        {
            angle.pointsMm = {{10.0, 0.0, 5.0}, {0.0, 0.0, 5.0}, far};
            imaging::measure(angle, none);
            QVERIFY2(std::abs(angle.angleDegrees - truth) < 1e-9, qPrintable(QString::number(angle.angleDegrees)));
        }
        angle.pointsMm = {{1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, {2.0, 2.0, 2.0}};
        QVERIFY_THROWS_EXCEPTION(Error, imaging::measure(angle, none));
        ruler.pointsMm.pop_back();
        QVERIFY_THROWS_EXCEPTION(Error, imaging::measure(ruler, none));
    }

    void roiStatisticsAgainstTheNoise()
    {
        for (unsigned seed : {1u, 2u, 3u, 4u})
        {
            const CtVolume ct = noisyCt(100.0, 20.0, seed, 100.0);
            ViewMeasurement roi = axialRoi({-5.0, 3.0, -1.0}, 12.0, 8.0);
            imaging::measure(roi, ct);
            const double standardError = 20.0 / std::sqrt(double(roi.samples));
            qInfo("seed %u: %lld samples, mean %.2f HU, SD %.2f HU, area %.1f mm2", seed, roi.samples, roi.meanHu, roi.sdHu, roi.areaMm2);
            QVERIFY(std::abs(roi.meanHu - 100.0) < 4.0 * standardError);
            QVERIFY(std::abs(roi.sdHu - 20.0) < 2.0);
            QVERIFY(std::abs(roi.areaMm2 - M_PI * 12.0 * 8.0) < 1e-9);
            // One sample per 0.7 x 0.7 mm: the count is the area over 0.49 mm2 within 5 %.
            QVERIFY(std::abs(roi.samples * 0.49 / roi.areaMm2 - 1.0) < 0.05);
        }
        // Centred on the boundary between 0 and 200 HU: half of each.
        const CtVolume halves = noisyCt(0.0, 1.0, 5, 200.0);
        ViewMeasurement across = axialRoi({-0.35, 0.0, -1.0}, 10.0, 10.0); // x = -0.35 mm lies between the columns
        imaging::measure(across, halves);
        QVERIFY2(std::abs(across.meanHu - 100.0) < 6.0, qPrintable(QString::number(across.meanHu)));
        ViewMeasurement outside = axialRoi({500.0, 0.0, 0.0}, 5.0, 5.0);
        QVERIFY_THROWS_EXCEPTION(Error, imaging::measure(outside, halves));
    }

    void keptInTheStudy()
    {
        const std::filesystem::path bundle = std::filesystem::path(test::outputFolder("view-measurements").toStdString()) / "m.vsim";
        std::filesystem::remove_all(bundle);
        ViewMeasurement roi = axialRoi({1.0, 2.0, 3.0}, 4.0, 5.0);
        imaging::measure(roi, noisyCt(50.0, 5.0, 7, 50.0));
        std::string id;
        {
            study::Study study = study::Study::create(bundle, "m");
            id = study.addMeasurement(roi, "ROI 1", {"measure", {}, {}, "", ""});
            study.save();
        }
        const study::Study reopened = study::Study::open(bundle, study::Access::ReadOnly);
        QCOMPARE(reopened.artifact(id).kind, study::ArtifactKind::Measurement);
        const ViewMeasurement read = reopened.loadMeasurement(id);
        QCOMPARE(read.kind, ViewMeasurement::Kind::Roi);
        QCOMPARE(read.pointsMm.size(), std::size_t(2));
        QVERIFY((read.pointsMm[1] - roi.pointsMm[1]).norm() < 1e-12);
        QCOMPARE(read.meanHu, roi.meanHu);
        QCOMPARE(read.samples, roi.samples);
        QCOMPARE(measurementText(read), measurementText(roi));
    }
};

QTEST_GUILESS_MAIN(TestViewMeasurements)
#include "tst_view_measurements.moc"
