// Unit-width skeletons: no crowded voxel after VDSM, and the graph's endpoints, junctions and edges equal the
// phantoms' truth topology (bifurcation; hepatic tree with 31 segments), from the truth labels and from a
// segmentation of a noisy phantom.

#include "PhantomGrids.h"
#include "SegmentedPhantom.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <QElapsedTimer>
#include <QtTest>

using namespace vsim;
using namespace vsim::dicom;

namespace {


void checkTopology(const imaging::SkeletonResult& result, const PhantomModel& model, const char* what)
{
    int truthEnds = 0, truthJunctions = 0;
    std::vector<int> degree(model.nodes.size(), 0);
    for (const VesselSegment& segment : model.segments)
        ++degree[segment.from], ++degree[segment.to];
    for (int d : degree)
        (d == 1 ? truthEnds : truthJunctions) += 1;
    const SkeletonGraph& graph = result.graph;
    qInfo("%s: thinned %zu voxels, crowded %zu -> %zu after VDSM, %zu spurs pruned; %zu endpoints, %zu junctions, "
          "%zu edges (truth %d, %d, %zu)",
          what, result.thinnedVoxels, result.crowdedAfterThinning, result.crowdedAfterVdsm, result.prunedBranches,
          graph.endpoints().size(), graph.junctions().size(), graph.edges.size(), truthEnds, truthJunctions,
          model.segments.size());
    graph.validate();
    QCOMPARE(result.crowdedAfterVdsm, std::size_t(0));
    QCOMPARE(imaging::countCrowdedVoxels(result.skeleton), std::size_t(0));
    QCOMPARE(int(graph.endpoints().size()), truthEnds);
    QCOMPARE(int(graph.junctions().size()), truthJunctions);
    QCOMPARE(graph.edges.size(), model.segments.size());
}

} // namespace

class Skeleton : public QObject
{
    Q_OBJECT

private slots:
    void bifurcationTruthLabel()
    {
        PhantomOptions options;
        const PhantomModel model = buildPhantomModel(PhantomKind::Bifurcation, options);
        const VolumeGeometry geometry = test::gridAroundVessels(model, 0.8, 6.0);
        const LabelVolume truth = renderPhantomLabels(model, geometry);
        QElapsedTimer timer;
        timer.start();
        const auto result = imaging::extractSkeleton(truth, label::kVesselLumen, ParameterSet(imaging::skeletonParameters()));
        qInfo("skeleton in %.2f s", timer.elapsed() / 1000.0);
        checkTopology(result, model, "bifurcation truth");
    }

    void hepaticTreeTruthLabel()
    {
        PhantomOptions options;
        PhantomModel model = buildPhantomModel(PhantomKind::HepaticTree, options);
        model.tissues.clear();
        const VolumeGeometry geometry = test::gridAroundVessels(model, 0.35, 4.0);
        const LabelVolume truth = renderPhantomLabels(model, geometry);
        QElapsedTimer timer;
        timer.start();
        const auto result = imaging::extractSkeleton(truth, label::kVesselLumen, ParameterSet(imaging::skeletonParameters()));
        qInfo("skeleton of %d x %d x %d in %.2f s", geometry.dims[0], geometry.dims[1], geometry.dims[2],
              timer.elapsed() / 1000.0);
        checkTopology(result, model, "hepatic tree truth");
    }

    void bifurcationFromSegmentation()
    {
        const test::SegmentedPhantom phantom =
            test::segmentPhantom(PhantomKind::Bifurcation, {192, 192, 120}, {1.0, 1.0, 1.0}, 5);
        const PhantomModel& model = phantom.model;
        const LabelVolume& label = phantom.label;
        const auto result = imaging::extractSkeleton(label, 1, ParameterSet(imaging::skeletonParameters()));
        checkTopology(result, model, "bifurcation segmented");
    }

    void vdsmLeavesNoCrowdedPoints()
    {
        // A solid 3 x 3 x 20 bar: thinning keeps a line; a T of 2-voxel-thick bars leaves a crowded junction
        // that VDSM must resolve to a single centre with one path per exit.
        VolumeGeometry geometry;
        geometry.dims = {21, 21, 5};
        LabelVolume label(geometry);
        for (int i = 2; i < 19; ++i)
            for (int t = 0; t < 2; ++t)
            {
                label.at(i, 10 + t, 2) = 1; // bar along x
                label.at(10 + t, i > 10 ? i : 10, 2) = 1; // bar along +y from the middle
            }
        QVERIFY(imaging::countCrowdedVoxels(label) > 0);
        LabelVolume skeleton = label;
        imaging::removeCrowdedPoints(skeleton, &label);
        QCOMPARE(imaging::countCrowdedVoxels(skeleton), std::size_t(0));
    }
};

QTEST_GUILESS_MAIN(Skeleton)
#include "tst_skeleton.moc"
