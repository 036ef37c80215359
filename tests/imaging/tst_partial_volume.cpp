// Partial-volume vessel radii (PartialVolumeRadii.h) on the hepatic-tree phantom CT (320 x 320 x 240 voxels of
// 0.7 x 0.7 x 1 mm, 20 HU noise), segmented, skeletonised and centerlined with the default parameters, against the truth
// segments' mean radii. That phantom's image draws a vessel's edge as Phi(signed distance / sigma), which the fit
// assumed until 2026-11-27 (0.1 % root, 1.1 % mean, 4.5 % worst: an inverse crime). The fit now assumes what a
// scanner does to a tube, a disc convolved with the blur (BlurredDisc.h); Phi of the distance holds more contrast
// across a thin tube (about pi (r^2 + sigma^2) per unit length where a blurred disc holds pi r^2), so the fit reads
// the analytic phantom's thin segments wide: measured 2026-11-27 root 0.8 %, mean 6.8 %, worst 13.2 %. Asserted: the
// root within 2 %, the mean within 8 %, every segment within 15 %, and a smaller mean error than the label's
// cross-sections (10.5 %). The patient-like hepatic tree (occupancy on sub-voxels, PSF, slice profile, correlated
// noise: no estimator's model) checks the tips against the 5 %.

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
    /// centerlines reach and measure, and their mean-radius errors. The issue asks 5 %. History: 2026-11-24, 4-5 of
    /// 28 reached, 11-16 % off; 2026-11-27 with the thin-vessel level 15-17 reached, those of 1 mm and wider 9-14 %
    /// low, those under 1 mm 20-39 % low (the fit's Phi edge: its half level lies sigma^2 / (2 r) inside a blurred
    /// disc's radius). With the blurred-disc model (BlurredDisc.h) the mean error over the tips was 5.2 / 4.9 / 5.8 %
    /// on seeds 1-3 against the matched segment's own mean radius. But where the segmentation misses one of a
    /// segment's two children, the centerline edge runs on into the other: the edge then covers two truth segments
    /// (up to 45 % of it on the child), and its radius is a fit over both. Since 2026-11-28 each edge is compared with
    /// the truth along the edge itself (every 0.25 mm of its centerline, the radius of the nearest truth artery):
    /// 3.7 / 3.4 / 5.3 %; 3.0 / 3.4 / 4.4 % with the segmentation's small-vessel boundary at 0.45 of the local contrast
    /// (LocalHalfLevel.cpp). Asserted: at least 12 tips measured, their mean error within the 5 %, and within
    /// 8 % for those of 1 mm and wider.
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
                const double segmentMean = 0.5 * (truth->radii.front() + truth->radii.back());
                const auto [expected, onTruth] = truthAlong(c.phantom.arteries, *truth, centerlines.edges[e].points);
                const double signedError = radii[e].meanRadiusMm / expected - 1.0, error = std::abs(signedError);
                qInfo("  tip: measured %.2f mm over %.1f mm of centerline, truth along the edge %.2f mm (%+.1f %%); "
                      "%.0f %% of the edge on the matched segment (%.2f -> %.2f mm over %.1f mm, mean %.2f mm: "
                      "%+.1f %%), axis |z| %.2f",
                      radii[e].meanRadiusMm, radii[e].usedLengthMm, expected, 100.0 * signedError, 100.0 * onTruth,
                      truth->radii.front(), truth->radii.back(), truth->lengthMm(), segmentMean,
                      100.0 * (radii[e].meanRadiusMm / segmentMean - 1.0),
                      std::abs((truth->points.back() - truth->points.front()).normalized().z()));
                sum += error, worst = std::max(worst, error), ++measured;
                if (segmentMean >= 1.0)
                    sumWide += error, ++wide;
            }
            qInfo("seed %llu: %d of %zu segmental hepatic arteries reached and measured; mean-radius error mean %.1f %%, "
                  "worst %.1f %% (issue: within 5 %%)",
                  (unsigned long long)seed, measured, tips.size(), measured ? 100.0 * sum / measured : 0.0,
                  100.0 * worst);
            qInfo("  tips of 1 mm and wider: %d, mean-radius error %.1f %%; under 1 mm: %d, %.1f %%", wide,
                  wide ? 100.0 * sumWide / wide : 0.0, measured - wide,
                  measured > wide ? 100.0 * (sum - sumWide) / (measured - wide) : 0.0);
            QVERIFY(measured >= 12 && wide >= 1);
            QVERIFY(sum / measured <= 0.05);
            QVERIFY(sumWide / wide <= 0.08);
        }
    }

private:
    /// The mean truth radius (mm) along a measured edge (its points every 0.25 mm of arc, 0.5 mm clear of its ends),
    /// each point taking the radius of the truth artery whose axis is nearest; and the fraction of those points whose
    /// nearest artery is `matched`.
    static std::pair<double, double> truthAlong(const PhantomModel& arteries, const VesselSegment& matched,
                                                const std::vector<Eigen::Vector3d>& points)
    {
        std::vector<double> arc{0.0};
        for (std::size_t i = 1; i < points.size(); ++i)
            arc.push_back(arc.back() + (points[i] - points[i - 1]).norm());
        double sum = 0.0;
        int count = 0, onMatched = 0;
        for (double s = 0.5; s <= arc.back() - 0.5; s += 0.25)
        {
            std::size_t i = 1;
            while (i + 1 < points.size() && arc[i] < s)
                ++i;
            const double t = arc[i] > arc[i - 1] ? (s - arc[i - 1]) / (arc[i] - arc[i - 1]) : 0.0;
            const Eigen::Vector3d p = points[i - 1] + std::clamp(t, 0.0, 1.0) * (points[i] - points[i - 1]);
            const VesselSegment* nearest = nullptr;
            double best = 1e300, radius = 0.0;
            for (const VesselSegment& segment : arteries.segments)
                if (const auto [d, r] = nearestOnAxis(segment, p); d < best)
                    best = d, radius = r, nearest = &segment;
            sum += radius, ++count, onMatched += nearest == &matched ? 1 : 0;
        }
        return {count ? sum / count : 0.0, count ? double(onMatched) / count : 0.0};
    }

    /// The distance (mm) from p to a truth segment's axis polyline, and the segment's radius (mm) at the nearest
    /// point, interpolated between its samples.
    static std::pair<double, double> nearestOnAxis(const VesselSegment& segment, const Eigen::Vector3d& p)
    {
        double best = 1e300, radius = segment.radii.front();
        for (std::size_t i = 1; i < segment.points.size(); ++i)
        {
            const Eigen::Vector3d a = segment.points[i - 1], d = segment.points[i] - a;
            const double t = d.squaredNorm() > 0.0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
            const double distance = (a + t * d - p).norm();
            if (distance < best)
                best = distance, radius = segment.radii[i - 1] + t * (segment.radii[i] - segment.radii[i - 1]);
        }
        return {best, radius};
    }

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
        QVERIFY(sumPartial / measured <= 0.08);
        QVERIFY(worst <= 0.15);
        QVERIFY(sumPartial < sumSections);
    }
};

QTEST_GUILESS_MAIN(PartialVolume)
#include "tst_partial_volume.moc"
