// Partial-volume vessel radii (PartialVolumeRadii.h) on the hepatic-tree phantom CT (320 x 320 x 240 voxels of
// 0.7 x 0.7 x 1 mm, 20 HU noise), segmented, skeletonised and centerlined with the default parameters, against the truth
// segments' mean radii: the root within 2 %, the mean error within 3 % and every segment within 8 % (measured
// 2026-11-22: 0.1 %, 1.1 %, 4.5 %), and a smaller mean error than the label's cross-sections (8.4 %: the
// threshold shrinks thin vessels). That phantom's image is made with the fit's own edge model; the patient-like
// hepatic tree (PSF, slice profile, correlated noise) checks the tips without that crime.

#include "AnatomyCases.h"
#include "PhantomGrids.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/GuidedSegmentation.h"
#include "vsim/imaging/PartialVolumeRadii.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <QtTest>

#include <set>

using namespace vsim;
using namespace vsim::dicom;

class PartialVolume : public QObject
{
    Q_OBJECT
private slots:
    void hepaticTreeRadii()
    {
        try
        {
            measure();
        }
        catch (const std::exception& error)
        {
            QFAIL(error.what());
        }
    }

    /// Issue 15 must-show 2: the hepatic tips' radii on the patient-like phantom (anatomy, PSF-convolved, correlated
    /// noise: not the fit's edge model), from the guided segmentation (target hepatic, the aorta and the proper
    /// hepatic artery), its skeleton and centerlines. Reported: how many of the truth's segmental arteries the
    /// centerlines reach and measure, and their mean-radius errors. The issue asks 5 %; measured 2026-11-24: 4-5 of
    /// 28 reached, mean error 11.2 / 13.0 / 15.6 % on seeds 1-3 with each tube's own blood and the shell's dominant
    /// level (15.6-22.2 % before; the blurred-tube fit's edge model is not this scanner's: the volume integral
    /// alone reads 5.2 / 3.0 / 7.1 %). Not met. Since the guided segmentation's thin-vessel level (2026-11-27) the
    /// centerlines reach 15-17 of the 28 tips: those of 1 mm and wider read 9-14 % low, those under 1 mm 20-39 % low
    /// (the fit's Phi edge against a convolved tube: its half level lies sigma^2 / (2 r) inside the radius, and the
    /// slice profile dims oblique tips further; the volume integral alone reads all of them 8-9 % off on average).
    /// Held as a guard: the tips of 1 mm and wider within 20 % on average; the thinner ones reported.
    void patientLikeHepaticTips()
    {
        for (std::uint64_t seed : {1u, 2u, 3u})
        {
            const test::AnatomyCase c = test::makeAnatomyCase(PhantomKind::HepaticTree, {256, 256, 200}, {0.7, 0.7, 1.0},
                                                              seed, Eigen::Vector3d(-40, -10, 85), false);
            imaging::SegmentationRequest request;
            request.target = imaging::SegmentationTarget::Hepatic;
            const VesselSegment& proper = test::segmentNamed(c.phantom, "proper hepatic artery");
            request.includeMm = {test::pointAtZ(test::segmentNamed(c.phantom, "aorta"), kPhantomCentre.z() + 60.0),
                                 proper.points[proper.points.size() / 2]};
            const LabelVolume label =
                imaging::segmentFromPoints(c.ct, ParameterSet(imaging::guidedSegmentationParameters()), request).label;
            const auto skeleton = imaging::extractSkeleton(label, 1, ParameterSet(imaging::skeletonParameters()));
            const SkeletonGraph centerlines =
                imaging::extractCenterlines(label, 1, skeleton.graph, ParameterSet(imaging::centerlineParameters()));
            const std::vector<imaging::PartialVolumeRadius> radii = imaging::partialVolumeRadii(c.ct, centerlines);
            std::set<const VesselSegment*> tips, reached;
            for (const VesselSegment& segment : c.phantom.arteries.segments)
                if (segment.name == "segmental hepatic artery")
                    tips.insert(&segment);
            double sum = 0.0, worst = 0.0, sumWide = 0.0;
            int measured = 0, wide = 0;
            for (std::size_t e = 0; e < centerlines.edges.size(); ++e)
            {
                const VesselSegment* truth = &test::nearestTruthSegment(
                    c.phantom.arteries, centerlines.nodes[std::size_t(centerlines.edges[e].from)].position,
                    centerlines.nodes[std::size_t(centerlines.edges[e].to)].position);
                if (!tips.count(truth) || !radii[e].measured || reached.count(truth))
                    continue;
                reached.insert(truth);
                const double expected = 0.5 * (truth->radii.front() + truth->radii.back());
                const double signedError = radii[e].meanRadiusMm / expected - 1.0, error = std::abs(signedError);
                qInfo("  tip: measured %.2f mm over %.1f mm of centerline, truth mean %.2f mm (%+.1f %%)",
                      radii[e].meanRadiusMm, radii[e].usedLengthMm, expected, 100.0 * signedError);
                sum += error, worst = std::max(worst, error), ++measured;
                if (expected >= 1.0)
                    sumWide += error, ++wide;
            }
            qInfo("seed %llu: %d of %zu segmental hepatic arteries reached and measured; mean-radius error mean %.1f %%, "
                  "worst %.1f %% (issue: within 5 %%)",
                  (unsigned long long)seed, measured, tips.size(), measured ? 100.0 * sum / measured : 0.0,
                  100.0 * worst);
            qInfo("  tips of 1 mm and wider: %d, mean-radius error %.1f %%; under 1 mm: %d, %.1f %%", wide,
                  wide ? 100.0 * sumWide / wide : 0.0, measured - wide,
                  measured > wide ? 100.0 * (sum - sumWide) / (measured - wide) : 0.0);
            QVERIFY(wide >= 1);
            QVERIFY(sumWide / wide <= 0.20);
        }
    }

private:
    void measure()
    {
        PhantomOptions options; // 0.7 mm in-plane, 1 mm slices; a body with air around it, as the segmentation expects
        options.size = {320, 320, 240};
        options.seed = 5;
        const PhantomModel model = buildPhantomModel(PhantomKind::HepaticTree, options);
        const VolumeGeometry grid = phantomGeometry(options);
        const CtVolume ct = renderPhantomCt(model, stackOf(grid), options);
        const LabelVolume label = imaging::segmentVessels(ct, ParameterSet(imaging::segmentationParameters())).label;
        const auto skeleton = imaging::extractSkeleton(label, 1, ParameterSet(imaging::skeletonParameters()));
        const SkeletonGraph centerlines =
            imaging::extractCenterlines(label, 1, skeleton.graph, ParameterSet(imaging::centerlineParameters()));
        const std::vector<imaging::PartialVolumeRadius> radii = imaging::partialVolumeRadii(ct, centerlines);
        const imaging::VesselMeasurements sections =
            imaging::measureVessels(label, centerlines, ParameterSet(imaging::measurementParameters()));
        double worst = 0.0, sumPartial = 0.0, sumSections = 0.0, rootError = 1.0;
        int measured = 0;
        for (std::size_t e = 0; e < centerlines.edges.size(); ++e)
        {
            if (!radii[e].measured)
                continue;
            const VesselSegment* truth =
                &test::nearestTruthSegment(model, centerlines.nodes[std::size_t(centerlines.edges[e].from)].position,
                                           centerlines.nodes[std::size_t(centerlines.edges[e].to)].position);
            const double expected = 0.5 * (truth->radii.front() + truth->radii.back());
            const double error = std::abs(radii[e].meanRadiusMm / expected - 1.0);
            worst = std::max(worst, error);
            sumPartial += error;
            sumSections += std::abs(0.5 * sections.segments[e].referenceDiameterMm / expected - 1.0);
            if (truth->parent < 0)
                rootError = error;
            ++measured;
        }
        qInfo("hepatic tree, %d segments measured: partial-volume radii mean error %.1f %%, worst %.1f %%, root %.1f %%; "
              "label cross-sections mean error %.1f %%",
              measured, 100.0 * sumPartial / measured, 100.0 * worst, 100.0 * rootError, 100.0 * sumSections / measured);
        QVERIFY(measured >= 25);
        QVERIFY(rootError <= 0.02);
        QVERIFY(sumPartial / measured <= 0.03);
        QVERIFY(worst <= 0.08);
        QVERIFY(sumPartial < sumSections);
    }
};

QTEST_GUILESS_MAIN(PartialVolume)
#include "tst_partial_volume.moc"
