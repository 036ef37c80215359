// The drug split on the hepatic-tree phantom as imaged against its truth geometry (issue 6, must-show 2). The
// full-size CT (512 x 512 x 400 voxels of 0.7 x 0.7 x 1 mm, 20 HU noise, the phantom's default seed) is segmented,
// skeletonized and centerlined with the default parameters, and the network built from the images as the CLI and
// the workstation build it (app::networkFromImages); the same model runs on the truth geometry. Both are injected
// at the root (2 ml/min, Murray outlets) with the phantom's tumour.
// Asserted: every junction's split (each daughter's share of its parent's flow) within 5 % of the truth; each
// outlet's share of the injected flow within 6 % (5 % holds, at 4.96 %: the margin is for floating-point
// differences between machines; other noise seeds reach 5.8-9.4 %, the noise floor of 0.74 mm tips two voxels
// across, imaging README); the tumour share within 5 % of the truth, the best tip's share within 10 %.

#include "TruthNetwork.h"
#include "vsim/app/NetworkPipeline.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselSegmentation.h"
#include "vsim/sim/network/Targeting.h"
#include "vsim/sim/network/WorkingAngle.h"

#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace vsim;

namespace {

Eigen::Vector3d middleOf(const VesselNetwork& network, int segment)
{
    const VesselNetwork::Segment& s = network.segments[std::size_t(segment)];
    return 0.5 * (network.nodes[std::size_t(s.from)].positionMm + network.nodes[std::size_t(s.to)].positionMm);
}

/// The segment of `network` (longer than 3 mm: no skeleton spur) whose middle is nearest to `point`.
int nearestSegment(const VesselNetwork& network, const Eigen::Vector3d& point)
{
    int best = -1;
    double bestDistance = 1e300;
    for (std::size_t s = 0; s < network.segments.size(); ++s)
    {
        const double distance = (middleOf(network, int(s)) - point).norm();
        if (network.segments[s].lengthMm > 3.0 && distance < bestDistance)
            bestDistance = distance, best = int(s);
    }
    return best;
}

double flowOf(const sim::network::NetworkRunResult& run, int segment)
{
    return std::abs(run.network.segmentFields.at("flow_ml_min")[std::size_t(segment)]);
}

struct Deviation
{
    double median = 0.0, worst = 0.0;
};

Deviation summarise(std::vector<double> errors)
{
    for (double& e : errors)
        e = std::abs(e);
    std::sort(errors.begin(), errors.end());
    return {errors[errors.size() / 2], errors.back()};
}

} // namespace

class HepaticSplit : public QObject
{
    Q_OBJECT

private slots:
    void imagedAgainstTruth()
    {
        try
        {
            compare();
        }
        catch (const std::exception& error)
        {
            QFAIL(error.what());
        }
    }

private:
    void compare()
    {
        const dicom::PhantomOptions options;
        const dicom::PhantomModel model = dicom::buildPhantomModel(dicom::PhantomKind::HepaticTree, options);
        const CtVolume ct =
            dicom::renderPhantomCt(model, dicom::stackOf(dicom::phantomGeometry(options)), options);
        const LabelVolume label = imaging::segmentVessels(ct, ParameterSet(imaging::segmentationParameters())).label;
        const auto skeleton = imaging::extractSkeleton(label, 1, ParameterSet(imaging::skeletonParameters()));
        const SkeletonGraph centerlines =
            imaging::extractCenterlines(label, 1, skeleton.graph, ParameterSet(imaging::centerlineParameters()));
        std::vector<std::string> warnings;
        const VesselNetwork imaged = app::networkFromImages(centerlines, label, &ct, warnings);
        const VesselNetwork truth = test::truthNetwork(model);

        const auto& m = model.measures;
        const sim::network::TumourSphere tumour{
            {m.at("tumour_centre_x_mm"), m.at("tumour_centre_y_mm"), m.at("tumour_centre_z_mm")},
            m.at("tumour_radius_mm")};
        auto run = [&](const VesselNetwork& network) {
            sim::network::NetworkRunSetup setup;
            setup.network = network;
            setup.tipPointMm = truth.nodes[std::size_t(truth.root)].positionMm;
            setup.tumour = tumour.region();
            return sim::network::runNetwork(setup);
        };
        const sim::network::NetworkRunResult truthRun = run(truth), imagedRun = run(imaged);

        // Each truth segment's imaged counterpart; junction splits and outlet shares.
        const VesselNetwork& t = truthRun.network;
        std::vector<int> counterpart;
        for (std::size_t s = 0; s < t.segments.size(); ++s)
            counterpart.push_back(nearestSegment(imagedRun.network, middleOf(t, int(s))));
        const double injected = truthRun.metrics.at("injection_rate_ml_min");
        std::vector<double> splitErrors, outletErrors;
        const auto incident = t.incidentSegments();
        for (std::size_t parent = 0; parent < t.segments.size(); ++parent)
        {
            std::vector<int> daughters;
            for (int s : incident[std::size_t(t.segments[parent].to)])
                if (std::size_t(s) != parent)
                    daughters.push_back(s);
            for (int d : daughters)
                splitErrors.push_back((flowOf(imagedRun, counterpart[std::size_t(d)]) /
                                       flowOf(imagedRun, counterpart[parent])) /
                                          (flowOf(truthRun, d) / flowOf(truthRun, int(parent))) -
                                      1.0);
            if (daughters.empty())
                outletErrors.push_back(flowOf(imagedRun, counterpart[parent]) / injected /
                                           (flowOf(truthRun, int(parent)) / injected) -
                                       1.0);
        }
        const Deviation splits = summarise(splitErrors), outlets = summarise(outletErrors);
        const double tumourTruth = truthRun.metrics.at("tumour_fraction");
        const double tumourImaged = imagedRun.metrics.at("tumour_fraction");
        const double bestTruth = truthRun.metrics.at("best_tip_fraction");
        const double bestImaged = imagedRun.metrics.at("best_tip_fraction");
        qInfo("hepatic tree (512 x 512 x 400, 20 HU), imaged against truth: %zu junction splits, median %.2f %%, worst "
              "%.2f %%; %zu outlet shares, median %.2f %%, worst %.2f %%; tumour share %.2f %% (truth %.2f %%); best "
              "tip %.1f %% (truth %.1f %%)",
              splitErrors.size(), 100 * splits.median, 100 * splits.worst, outletErrors.size(), 100 * outlets.median,
              100 * outlets.worst, 100 * tumourImaged, 100 * tumourTruth, 100 * bestImaged, 100 * bestTruth);
        QCOMPARE(outletErrors.size(), std::size_t(16));
        QCOMPARE(splitErrors.size(), std::size_t(30));
        QVERIFY(splits.worst <= 0.05);
        QVERIFY(outlets.worst <= 0.06);
        QVERIFY(std::abs(tumourImaged / tumourTruth - 1.0) <= 0.05);
        QVERIFY(std::abs(bestImaged / bestTruth - 1.0) <= 0.10);

        // The working C-arm angle (issue 19): found on the imaged network for the three best tips of the truth's
        // ranking, judged on the truth tree against a brute-force search there (every degree over the C-arm's range):
        // the objective is a share of the path (foreshortening + overlap), and ours is within 5 % of the path of the
        // search's best (2026-11-28: 0.11 and 0.55 % of the path; 3.4 and 26 % of the best's own small value).
        for (std::size_t k = 0; k < 3 && k < truthRun.ranking.size(); ++k)
        {
            const int truthTip = truthRun.ranking[k].node;
            if (truthTip == t.root)
                continue;
            const Eigen::Vector3d& where = t.nodes[std::size_t(truthTip)].positionMm;
            int imagedTip = 0;
            for (std::size_t n = 1; n < imagedRun.network.nodes.size(); ++n)
                if ((imagedRun.network.nodes[n].positionMm - where).norm() <
                    (imagedRun.network.nodes[std::size_t(imagedTip)].positionMm - where).norm())
                    imagedTip = int(n);
            const sim::network::WorkingAngle found = sim::network::workingAngle(imagedRun.network, imagedTip);
            const sim::network::AngleScene scene = sim::network::angleScene(t, truthTip);
            const double ours = sim::network::viewQuality(scene, sim::network::detectorDirection(found.angles)).objective();
            double best = 1e300;
            sim::network::CArmAngles bestAngles;
            for (double lao = -sim::network::kLaoRangeDeg; lao <= sim::network::kLaoRangeDeg; lao += 1.0)
                for (double cranial = -sim::network::kCranialRangeDeg; cranial <= sim::network::kCranialRangeDeg; cranial += 1.0)
                    if (const double q = sim::network::viewQuality(scene, sim::network::detectorDirection({lao, cranial})).objective();
                        q < best)
                        best = q, bestAngles = {lao, cranial};
            qInfo("tip %d (imaged node %d): working angle LAO %.2f, cranial %.2f, objective on the truth %.4f; brute "
                  "force on the truth: LAO %.0f, cranial %.0f, %.4f; frontal %.4f",
                  truthTip, imagedTip, found.angles.laoDeg, found.angles.cranialDeg, ours, bestAngles.laoDeg,
                  bestAngles.cranialDeg, best, found.frontal.objective());
            QVERIFY(ours - best <= 0.05);
        }
    }
};

QTEST_GUILESS_MAIN(HepaticSplit)
#include "tst_hepatic_split.moc"
