// Centerlines against the phantoms' truth centerlines: mean distance <= 0.5 mm, largest <= 1.5 mm, from the truth
// label and from a segmentation of a noisy phantom; the centerlines of a segmented hepatic tree (vessels two to
// three voxels across) stay within half a voxel of the truth lumen (a path around the label ran 1.7 mm outside); the B-spline smoothing brings a noisy polyline closer to the
// curve it samples.

#include "PhantomGrids.h"
#include "SegmentedPhantom.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace vsim;
using namespace vsim::dicom;

namespace {

double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const Eigen::Vector3d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    return (p - (a + t * ab)).norm();
}

/// Distance from p to the nearest truth centerline.
double distanceToTruth(const PhantomModel& model, const Eigen::Vector3d& p)
{
    double best = 1e300;
    for (const VesselSegment& segment : model.segments)
        for (std::size_t s = 1; s < segment.points.size(); ++s)
            best = std::min(best, distanceToSegment(p, segment.points[s - 1], segment.points[s]));
    return best;
}

void checkAgainstTruth(const SkeletonGraph& centerlines, const PhantomModel& model, const char* what)
{
    double sum = 0, largest = 0;
    std::size_t count = 0;
    for (const SkeletonGraph::Edge& edge : centerlines.edges)
        for (const Eigen::Vector3d& point : edge.points)
        {
            const double d = distanceToTruth(model, point);
            sum += d, largest = std::max(largest, d), ++count;
        }
    qInfo("%s: %zu centerlines, %zu points, mean distance to the truth %.3f mm, largest %.3f mm", what,
          centerlines.edges.size(), count, sum / count, largest);
    centerlines.validate();
    QVERIFY(sum / count <= 0.5);
    QVERIFY(largest <= 1.5);
}

/// How far (mm) p lies outside the nearest truth lumen: its distance to a truth centerline less the radius there
/// (negative inside).
double outsideTruthLumen(const PhantomModel& model, const Eigen::Vector3d& p)
{
    double best = 1e300;
    for (const VesselSegment& segment : model.segments)
        for (std::size_t s = 1; s < segment.points.size(); ++s)
        {
            const Eigen::Vector3d a = segment.points[s - 1], ab = segment.points[s] - a;
            const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            const double radius = segment.radii[s - 1] + t * (segment.radii[s] - segment.radii[s - 1]);
            best = std::min(best, (p - (a + t * ab)).norm() - radius);
        }
    return best;
}

SkeletonGraph centerlinesOf(const LabelVolume& label)
{
    const auto skeleton = imaging::extractSkeleton(label, 1, ParameterSet(imaging::skeletonParameters()));
    return imaging::extractCenterlines(label, 1, skeleton.graph, ParameterSet(imaging::centerlineParameters()));
}

} // namespace

class Centerlines : public QObject
{
    Q_OBJECT

private slots:
    void hepaticTreeTruthLabel()
    {
        PhantomModel model = buildPhantomModel(PhantomKind::HepaticTree, {});
        model.tissues.clear();
        const LabelVolume truth = renderPhantomLabels(model, test::gridAroundVessels(model, 0.35, 4.0));
        checkAgainstTruth(centerlinesOf(truth), model, "hepatic tree truth label");
    }

    void bifurcationFromSegmentation()
    {
        const test::SegmentedPhantom phantom =
            test::segmentPhantom(PhantomKind::Bifurcation, {192, 192, 120}, {1.0, 1.0, 1.0}, 5);
        const PhantomModel& model = phantom.model;
        const LabelVolume& label = phantom.label;
        checkAgainstTruth(centerlinesOf(label), model, "bifurcation segmented");
    }

    // A thin vessel's label is two or three voxels across, all of them next to the wall: the minimal paths must
    // still run through it rather than around it.
    void hepaticTreeStaysInTheLumen()
    {
        const test::SegmentedPhantom phantom =
            test::segmentPhantom(PhantomKind::HepaticTree, {320, 320, 240}, {0.7, 0.7, 1.0}, 5);
        const SkeletonGraph centerlines = centerlinesOf(phantom.label);
        double outside = -1e300;
        std::size_t count = 0;
        for (const SkeletonGraph::Edge& edge : centerlines.edges)
            for (const Eigen::Vector3d& point : edge.points)
                outside = std::max(outside, outsideTruthLumen(phantom.model, point)), ++count;
        qInfo("hepatic tree segmented (0.7 x 0.7 x 1 mm, 20 HU): %zu centerlines, %zu points, the farthest %.3f mm "
              "%s the truth lumen's wall", centerlines.edges.size(), count, std::abs(outside), outside > 0 ? "outside" : "inside");
        QVERIFY(outside <= 0.35);
    }

    // Two separate tubes: the skeleton has both, the centerlines refuse with what to try.
    void disconnectedLabelSaysWhatToTry()
    {
        VolumeGeometry geometry;
        geometry.dims = {60, 40, 50};
        geometry.spacing = {0.5, 0.5, 0.5};
        LabelVolume label(geometry);
        for (int k = 3; k < 47; ++k)
            for (int j = 0; j < 40; ++j)
                for (int i = 0; i < 60; ++i)
                    for (int centre : {15, 45})
                        if ((i - centre) * (i - centre) + (j - 20) * (j - 20) <= 25)
                            label.at(i, j, k) = 1;
        const imaging::SkeletonResult skeleton = imaging::extractSkeleton(label, 1, ParameterSet(imaging::skeletonParameters()));
        QCOMPARE(skeleton.graph.edges.size(), std::size_t(2));
        try
        {
            imaging::extractCenterlines(label, 1, skeleton.graph, ParameterSet(imaging::centerlineParameters()));
            QFAIL("a disconnected label was accepted");
        }
        catch (const Error& error)
        {
            QVERIFY2(std::string(error.what()).find("disconnected") != std::string::npos, error.what());
            QVERIFY2(std::string(error.what()).find("brush") != std::string::npos, error.what());
        }
    }

    void bsplineSmoothsNoise()
    {
        // A quarter circle of radius 20 mm sampled every 0.7 mm with 0.3 mm noise.
        std::mt19937 random(3);
        std::normal_distribution<double> noise(0.0, 0.3);
        std::vector<Eigen::Vector3d> noisy;
        for (double angle = 0; angle <= M_PI / 2; angle += 0.7 / 20.0)
            noisy.push_back(Eigen::Vector3d(20 * std::cos(angle) + noise(random), 20 * std::sin(angle) + noise(random), noise(random)));
        auto meanError = [](const std::vector<Eigen::Vector3d>& points) {
            double sum = 0;
            for (const auto& p : points)
                sum += std::abs(std::hypot(std::hypot(p.x(), p.y()), p.z()) - 20.0);
            return sum / points.size();
        };
        const auto smooth = imaging::smoothWithBSpline(noisy, 4.0, 0.5);
        qInfo("noisy arc: mean error %.3f mm raw, %.3f mm smoothed", meanError(noisy), meanError(smooth));
        QVERIFY(meanError(smooth) < 0.5 * meanError(noisy));
        QVERIFY((smooth.front() - noisy.front()).norm() < 1e-9 && (smooth.back() - noisy.back()).norm() < 1e-9);
    }
};

QTEST_GUILESS_MAIN(Centerlines)
#include "tst_centerlines.moc"
