// Full size (label bench): the default 512 x 512 x 400 aaa phantom (20 HU noise) through segmentation (default
// parameters, automatic seed), skeleton, centerlines and measurements. Prints the times, Dice, topology, the
// maximum diameter and the process's peak memory as JSON; segment + skeleton + centerline must take <= 60 s.

#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <sys/resource.h>

#include <QElapsedTimer>
#include <QtTest>

using namespace vsim;
using namespace vsim::dicom;

class SegmentationFullSize : public QObject
{
    Q_OBJECT

private slots:
    void aaa()
    {
        const PhantomOptions options; // 512 x 512 x 400, 0.7 x 0.7 x 1.0 mm, 20 HU, seed 1
        const PhantomModel model = buildPhantomModel(PhantomKind::Aaa, options);
        const VolumeGeometry geometry = phantomGeometry(options);
        const CtVolume ct = renderPhantomCt(model, stackOf(geometry), options);
        const LabelVolume truth = renderPhantomLabels(model, geometry);
        QElapsedTimer timer;
        timer.start();
        const imaging::SegmentationResult result =
            imaging::segmentVessels(ct, ParameterSet(imaging::segmentationParameters()));
        const double segmentSeconds = timer.restart() / 1000.0;
        const imaging::SkeletonResult skeleton =
            imaging::extractSkeleton(result.label, 1, ParameterSet(imaging::skeletonParameters()));
        const double skeletonSeconds = timer.restart() / 1000.0;
        const SkeletonGraph centerlines = imaging::extractCenterlines(result.label, 1, skeleton.graph,
                                                                      ParameterSet(imaging::centerlineParameters()));
        const double centerlineSeconds = timer.restart() / 1000.0;
        const imaging::VesselMeasurements measured =
            imaging::measureVessels(result.label, centerlines, ParameterSet(imaging::measurementParameters()));
        const double measureSeconds = timer.restart() / 1000.0;
        const double dice = imaging::diceCoefficient(result.label, 1, truth, label::kVesselLumen);
        rusage usage{};
        getrusage(RUSAGE_SELF, &usage);
        const double pipeline = segmentSeconds + skeletonSeconds + centerlineSeconds;
        std::printf("{\"case\": \"pipeline_aaa_512x512x400\", \"segment_s\": %.2f, \"skeleton_s\": %.2f, "
                    "\"centerline_s\": %.2f, \"measure_s\": %.2f, \"segment_skeleton_centerline_s\": %.2f, "
                    "\"dice\": %.4f, \"endpoints\": %zu, \"junctions\": %zu, \"edges\": %zu, \"crowded\": %zu, "
                    "\"max_diameter_mm\": %.3f, \"truth_max_diameter_mm\": %.1f, \"peak_rss_mib\": %.0f}\n",
                    segmentSeconds, skeletonSeconds, centerlineSeconds, measureSeconds, pipeline, dice,
                    skeleton.graph.endpoints().size(), skeleton.graph.junctions().size(), skeleton.graph.edges.size(),
                    skeleton.crowdedAfterVdsm, measured.maxDiameterMm, model.measures.at("max_diameter_mm"),
                    usage.ru_maxrss / 1024.0);
        QVERIFY(dice >= 0.95);
        QCOMPARE(skeleton.crowdedAfterVdsm, std::size_t(0));
        QVERIFY(std::abs(measured.maxDiameterMm - model.measures.at("max_diameter_mm")) <= 1.0);
        QVERIFY(pipeline <= 60.0);
    }

    void hepaticTreeTopology()
    {
        const PhantomOptions options; // default size and spacing: the tips (0.70 mm radius) are 2 voxels wide
        const PhantomModel model = buildPhantomModel(PhantomKind::HepaticTree, options);
        const VolumeGeometry geometry = phantomGeometry(options);
        const CtVolume ct = renderPhantomCt(model, stackOf(geometry), options);
        QElapsedTimer timer;
        timer.start();
        const LabelVolume label = imaging::segmentVessels(ct, ParameterSet(imaging::segmentationParameters())).label;
        const imaging::SkeletonResult skeleton = imaging::extractSkeleton(label, 1, ParameterSet(imaging::skeletonParameters()));
        std::printf("{\"case\": \"hepatic_tree_512x512x400_topology\", \"seconds\": %.2f, \"endpoints\": %zu, "
                    "\"junctions\": %zu, \"edges\": %zu, \"crowded_after_thinning\": %zu, \"crowded\": %zu, "
                    "\"truth\": [17, 15, 31]}\n",
                    timer.elapsed() / 1000.0, skeleton.graph.endpoints().size(), skeleton.graph.junctions().size(),
                    skeleton.graph.edges.size(), skeleton.crowdedAfterThinning, skeleton.crowdedAfterVdsm);
        QCOMPARE(skeleton.graph.endpoints().size(), std::size_t(17));
        QCOMPARE(skeleton.crowdedAfterVdsm, std::size_t(0));
        QCOMPARE(skeleton.graph.junctions().size(), std::size_t(15));
        QCOMPARE(skeleton.graph.edges.size(), std::size_t(31));
    }
};

QTEST_GUILESS_MAIN(SegmentationFullSize)
#include "tst_segmentation_fullsize.moc"
