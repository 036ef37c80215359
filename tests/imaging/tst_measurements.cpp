// Measurements along the centerlines against the phantoms' truth (20 HU noise, default parameters, automatic
// seed): AAA maximum diameter within 1 mm, stenosis within 5 percentage points, segment lengths and radii
// within 10 % (hepatic tree, from its truth label).

#include "PhantomGrids.h"
#include "SegmentedPhantom.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <QtTest>

using namespace vsim;
using namespace vsim::dicom;

namespace {

struct Pipeline
{
    LabelVolume label;
    SkeletonGraph centerlines;
    imaging::VesselMeasurements measurements;
};

Pipeline measure(const LabelVolume& label)
{
    Pipeline pipeline;
    pipeline.label = label;
    const auto skeleton = imaging::extractSkeleton(label, 1, ParameterSet(imaging::skeletonParameters()));
    pipeline.centerlines =
        imaging::extractCenterlines(label, 1, skeleton.graph, ParameterSet(imaging::centerlineParameters()));
    pipeline.measurements =
        imaging::measureVessels(label, pipeline.centerlines, ParameterSet(imaging::measurementParameters()));
    return pipeline;
}

Pipeline fromPhantom(PhantomKind kind, std::array<int, 3> size, Eigen::Vector3d spacing, PhantomModel* model)
{
    test::SegmentedPhantom phantom = test::segmentPhantom(kind, size, spacing, 21);
    *model = std::move(phantom.model);
    return measure(phantom.label);
}

} // namespace

class Measurements : public QObject
{
    Q_OBJECT

private slots:
    void aaaMaximumDiameter()
    {
        PhantomModel model;
        const Pipeline p = fromPhantom(PhantomKind::Aaa, {256, 256, 200}, {1.4, 1.4, 2.0}, &model);
        qInfo("aaa: maximum diameter %.2f mm (truth %.2f mm; largest caliper %.2f mm) over %zu centerlines",
              p.measurements.maxDiameterMm, model.measures.at("max_diameter_mm"), p.measurements.maxCaliperMm,
              p.measurements.segments.size());
        QVERIFY(std::abs(p.measurements.maxDiameterMm - model.measures.at("max_diameter_mm")) <= 1.0);
    }

    void stenosisPercent()
    {
        PhantomModel model;
        const Pipeline p = fromPhantom(PhantomKind::Stenosis, {256, 256, 100}, {0.7, 0.7, 1.0}, &model);
        QVERIFY(p.measurements.worstStenosisSegment >= 0);
        const auto& worst = p.measurements.segments[std::size_t(p.measurements.worstStenosisSegment)];
        qInfo("stenosis: %.1f %% diameter (truth %.1f %%), %.1f %% area; reference %.2f mm, minimal %.2f mm",
              worst.diameterStenosisPercent, model.measures.at("stenosis_percent"), worst.areaStenosisPercent,
              worst.referenceDiameterMm, worst.minimalDiameterMm);
        QVERIFY(std::abs(worst.diameterStenosisPercent - model.measures.at("stenosis_percent")) <= 5.0);
        QVERIFY(std::abs(worst.referenceDiameterMm - model.measures.at("reference_diameter_mm")) <= 0.6);
    }

    void hepaticLengthsAndRadii()
    {
        PhantomModel model = buildPhantomModel(PhantomKind::HepaticTree, {});
        model.tissues.clear();
        const Pipeline p = measure(renderPhantomLabels(model, test::gridAroundVessels(model, 0.35, 4.0)));
        // Match each measured segment to the truth segment whose end nodes are nearest to its ends.
        int matched = 0;
        double worstLength = 0, worstRadius = 0;
        for (const auto& segment : p.measurements.segments)
        {
            const Eigen::Vector3d a = p.centerlines.nodes[std::size_t(segment.from)].position;
            const Eigen::Vector3d b = p.centerlines.nodes[std::size_t(segment.to)].position;
            const VesselSegment* best = &test::nearestTruthSegment(model, a, b);
            const double lengthError = std::abs(segment.lengthMm - best->lengthMm()) / best->lengthMm();
            const double truthRadius = 0.5 * (best->radii.front() + best->radii.back());
            const double radiusError = std::abs(0.5 * segment.referenceDiameterMm - truthRadius) / truthRadius;
            worstLength = std::max(worstLength, lengthError);
            worstRadius = std::max(worstRadius, radiusError);
            ++matched;
        }
        qInfo("hepatic tree: %d segments, worst length error %.1f %%, worst radius error %.1f %%", matched,
              100 * worstLength, 100 * worstRadius);
        QCOMPARE(matched, 31);
        QVERIFY(worstLength <= 0.10);
        QVERIFY(worstRadius <= 0.10);
    }
};

QTEST_GUILESS_MAIN(Measurements)
#include "tst_measurements.moc"
