// Vessel segmentation against the phantoms' truth labels (20 HU noise, default parameters, automatic seed):
// Dice >= 0.95 for aaa, stenosis and bifurcation, >= 0.90 on the hepatic tree for branches of 1.5 mm diameter
// and more; bad input gets a message that says what to try.

#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <QElapsedTimer>
#include <QtTest>

using namespace vsim;
using namespace vsim::dicom;

namespace {

struct Case
{
    PhantomModel model;
    PhantomOptions options;
    VolumeGeometry geometry;
    CtVolume ct;
    LabelVolume truth;
};

Case makeCase(PhantomKind kind, std::array<int, 3> size, Eigen::Vector3d spacing, double noiseHu = 20.0)
{
    Case c;
    c.options.size = size;
    c.options.spacing = spacing;
    c.options.noiseHu = noiseHu;
    c.options.seed = 11;
    c.model = buildPhantomModel(kind, c.options);
    c.geometry = phantomGeometry(c.options);
    c.ct = renderPhantomCt(c.model, stackOf(c.geometry), c.options);
    c.truth = renderPhantomLabels(c.model, c.geometry);
    return c;
}

imaging::SegmentationResult segment(const Case& c, const std::vector<std::string>& settings = {})
{
    QElapsedTimer timer;
    timer.start();
    ParameterSet parameters(imaging::segmentationParameters());
    for (const std::string& setting : settings)
        parameters.setFromText(setting);
    imaging::SegmentationResult result = imaging::segmentVessels(c.ct, parameters);
    qInfo("segmented in %.2f s: blood %.0f HU, tissue %.0f HU, threshold %.0f HU, %.1f ml, %.0f level-set steps",
          timer.elapsed() / 1000.0,
          result.figures.at("blood_hu"), result.figures.at("tissue_hu"), result.figures.at("threshold_hu"),
          result.figures.at("volume_ml"), result.figures.at("level_set_steps"));
    return result;
}

/// Dice over the voxels outside `ignore`.
double diceOutside(const LabelVolume& a, const LabelVolume& b, const LabelVolume& ignore)
{
    std::size_t inA = 0, inB = 0, both = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
    {
        if (ignore.data()[i])
            continue;
        const bool x = a.data()[i] == 1, y = b.data()[i] == label::kVesselLumen;
        inA += x, inB += y, both += x && y;
    }
    return 2.0 * double(both) / double(inA + inB);
}

} // namespace

class Segmentation : public QObject
{
    Q_OBJECT

private slots:
    void largeVesselPhantoms_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<int>("columns");
        QTest::addColumn<int>("slices");
        QTest::addColumn<double>("inPlane");
        QTest::addColumn<double>("sliceSpacing");
        QTest::newRow("aaa") << int(PhantomKind::Aaa) << 256 << 200 << 1.4 << 2.0;
        QTest::newRow("stenosis") << int(PhantomKind::Stenosis) << 256 << 100 << 0.7 << 1.0;
        QTest::newRow("bifurcation") << int(PhantomKind::Bifurcation) << 192 << 120 << 1.0 << 1.0;
    }

    void largeVesselPhantoms()
    {
        QFETCH(int, kind);
        QFETCH(int, columns);
        QFETCH(int, slices);
        QFETCH(double, inPlane);
        QFETCH(double, sliceSpacing);
        const Case c = makeCase(PhantomKind(kind), {columns, columns, slices}, {inPlane, inPlane, sliceSpacing});
        const imaging::SegmentationResult result = segment(c);
        QVERIFY(result.seedFound);
        const double dice = imaging::diceCoefficient(result.label, 1, c.truth, label::kVesselLumen);
        qInfo("%s: Dice %.4f", QTest::currentDataTag(), dice);
        QVERIFY2(dice >= 0.95, qPrintable(QString("Dice %1").arg(dice)));
    }

    void hepaticTree()
    {
        const Case c = makeCase(PhantomKind::HepaticTree, {320, 320, 160}, {1.1, 1.1, 1.2});
        const imaging::SegmentationResult result = segment(c);
        // Branches under 1.5 mm diameter (and a voxel around them) are left out of the comparison.
        PhantomModel thin = c.model;
        thin.tissues.clear();
        thin.segments.erase(std::remove_if(thin.segments.begin(), thin.segments.end(),
                                           [](const VesselSegment& s) { return 2.0 * s.radii.back() >= 1.5; }),
                            thin.segments.end());
        LabelVolume ignore = renderPhantomLabels(thin, c.geometry);
        LabelVolume grown(c.geometry);
        const auto& d = c.geometry.dims;
        for (int k = 0; k < d[2]; ++k)
            for (int j = 0; j < d[1]; ++j)
                for (int i = 0; i < d[0]; ++i)
                    for (int n = -1; n <= 1 && ignore.at(i, j, k); ++n)
                        for (auto [a, b, e] : {std::array<int, 3>{n, 0, 0}, {0, n, 0}, {0, 0, n}})
                            if (c.geometry.contains(i + a, j + b, k + e))
                                grown.at(i + a, j + b, k + e) = 1;
        const double dice = diceOutside(result.label, c.truth, grown);
        qInfo("hepatic tree: Dice %.4f on branches of 1.5 mm and more (all: %.4f)", dice,
              imaging::diceCoefficient(result.label, 1, c.truth, label::kVesselLumen));
        QVERIFY(dice >= 0.90);
    }

    // Layer 3 alone (no denoising, no Gaussian refinement) on a noisy CT: the level set must pull the ragged
    // region-growing boundary back towards the truth.
    void levelSetSmoothsANoisyBoundary()
    {
        const Case c = makeCase(PhantomKind::Bifurcation, {192, 192, 120}, {1.0, 1.0, 1.0}, 80.0);
        const std::vector<std::string> raw{"smoothing_sigma_mm=0", "refine_sigma_mm=0", "vesselness_threshold=0"};
        std::vector<std::string> without = raw, with = raw;
        without.push_back("level_set_iterations=0");
        const imaging::SegmentationResult a = segment(c, without), b = segment(c, with);
        const double diceWithout = imaging::diceCoefficient(a.label, 1, c.truth, label::kVesselLumen);
        const double diceWith = imaging::diceCoefficient(b.label, 1, c.truth, label::kVesselLumen);
        qInfo("80 HU noise, no smoothing: Dice %.4f without the level set, %.4f with it (%.0f steps)", diceWithout,
              diceWith, b.figures.at("level_set_steps"));
        QCOMPARE(a.figures.at("level_set_steps"), 0.0);
        QVERIFY(diceWith >= diceWithout + 0.005);
    }

    void badInputSaysWhatToTry()
    {
        const Case c = makeCase(PhantomKind::Stenosis, {96, 96, 32}, {2.0, 2.0, 2.0});
        const ParameterSet parameters(imaging::segmentationParameters());
        // A seed in soft tissue.
        try
        {
            imaging::segmentVessels(c.ct, parameters, Eigen::Vector3d(kPhantomCentre + Eigen::Vector3d(40, 0, 0)));
            QFAIL("a seed outside any vessel must be refused");
        }
        catch (const Error& error)
        {
            QVERIFY2(std::string(error.what()).find("not in a contrast-filled vessel") != std::string::npos, error.what());
        }
        // No contrast: the blood at soft-tissue HU.
        PhantomModel plain = c.model;
        plain.bloodHu = hu::kSoftTissue;
        const CtVolume unenhanced = renderPhantomCt(plain, stackOf(c.geometry), c.options);
        QVERIFY_THROWS_EXCEPTION(Error, imaging::segmentVessels(unenhanced, parameters));
        // Not HU: stored values without the rescale (0..4095).
        CtVolume raw = c.ct.clone();
        for (std::size_t i = 0; i < raw.size(); ++i)
            raw.data()[i] = std::int16_t(raw.data()[i] + 1024);
        try
        {
            imaging::segmentVessels(raw, parameters);
            QFAIL("unscaled data must be refused");
        }
        catch (const Error& error)
        {
            QVERIFY2(std::string(error.what()).find("not CT Hounsfield units") != std::string::npos, error.what());
        }
    }
};

QTEST_GUILESS_MAIN(Segmentation)
#include "tst_segmentation.moc"
