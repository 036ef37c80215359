// The guided segmentation on the patient-like phantoms (their image model is not the segmentation's: PSF, slice
// profile, correlated noise, thrombus, blooming calcium, touching veins and spine), three seeds each, from one
// include point on the truth centerline: the lumen Dice against the truth labels, leaks into the neighbours, the
// competition with an exclude point, a stop plane and the path-length limit, and the refusals.

#include "AnatomyCases.h"
#include "vsim/core/Error.h"
#include "vsim/dicom/AnatomyPhantom.h"
#include "vsim/imaging/GuidedSegmentation.h"

#include <QtTest>

#include <algorithm>
#include <set>

using namespace vsim;
using namespace vsim::dicom;
using namespace vsim::imaging;

namespace {

using Case = test::AnatomyCase;
using test::pointAtZ;
using test::segmentNamed;

Case makeCase(PhantomKind kind, std::array<int, 3> size, Eigen::Vector3d spacing, std::uint64_t seed,
              const Eigen::Vector3d& centreShiftMm = Eigen::Vector3d::Zero())
{
    // The stenosis grid is centred on the femoral artery.
    const Eigen::Vector3d femoral = kind == PhantomKind::Stenosis ? Eigen::Vector3d(22, -14, 0) : Eigen::Vector3d::Zero();
    return test::makeAnatomyCase(kind, size, spacing, seed, centreShiftMm + femoral, true);
}

/// The voxels within (lumen radius + margin) of the named segments' centerlines.
LabelVolume nearSegments(const AnatomyPhantom& phantom, const VolumeGeometry& geometry,
                         const std::set<std::string>& names, double marginMm)
{
    AnatomyPhantom selection;
    AnatomyLayer layer{"selection", {}, 0.0, 1, false};
    layer.solid.type = Solid::Type::Tubes;
    for (const VesselSegment& segment : phantom.arteries.segments)
        if (names.count(segment.name))
            for (std::size_t n = 1; n < segment.points.size(); ++n)
                layer.solid.pieces.push_back({segment.points[n - 1], segment.points[n], segment.radii[n - 1] + marginMm,
                                              segment.radii[n] + marginMm, 0.0, 0.0});
    selection.layers.push_back(layer);
    return renderAnatomyLabels(selection, geometry);
}

struct Overlap
{
    double dice = 0.0, recall = 0.0, precision = 0.0;
};

/// Dice of the label's value-1 voxels against the truth lumen, both within `region` (all voxels when null).
Overlap overlap(const LabelVolume& label, const LabelVolume& truth, const LabelVolume* region = nullptr)
{
    std::size_t both = 0, inLabel = 0, inTruth = 0;
    for (std::size_t v = 0; v < truth.geometry().voxelCount(); ++v)
    {
        if (region && region->data()[v] == 0)
            continue;
        const bool l = label.data()[v] == 1, t = truth.data()[v] == label::kVesselLumen;
        both += l && t, inLabel += l, inTruth += t;
    }
    return {2.0 * double(both) / double(inLabel + inTruth), double(both) / double(inTruth), double(both) / double(inLabel)};
}

/// Fraction of the label's voxels whose truth label is `value`.
double fractionIn(const LabelVolume& label, const LabelVolume& truth, std::uint8_t value)
{
    std::size_t count = 0, total = 0;
    for (std::size_t v = 0; v < truth.geometry().voxelCount(); ++v)
        if (label.data()[v] == 1)
            ++total, count += truth.data()[v] == value;
    return double(count) / double(std::max<std::size_t>(total, 1));
}

} // namespace

class GuidedSegmentationTest : public QObject
{
    Q_OBJECT

private slots:
    /// Target aorta from one point in the aneurysm, then from no point (the automatic abdominal aorta point): the
    /// aorta and common iliac lumen; thrombus, wall, calcium, the IVC, the renal vein and the vertebrae left out.
    void aaaLumenFromOnePoint()
    {
        for (std::uint64_t seed : {1u, 2u, 3u})
        {
            const Case c = makeCase(PhantomKind::Aaa, {256, 256, 200}, {0.7, 0.7, 1.0}, seed);
            SegmentationRequest request;
            request.target = SegmentationTarget::Aorta;
            request.includeMm = {pointAtZ(segmentNamed(c.phantom, "aorta"), c.phantom.measures.at("max_outer_diameter_z_mm"))};
            const SegmentationResult result =
                segmentFromPoints(c.ct, ParameterSet(guidedSegmentationParameters()), request);
            const LabelVolume region = nearSegments(c.phantom, c.ct.geometry(),
                                                    {"aorta", "right common iliac artery", "left common iliac artery"}, 1.5);
            const Overlap o = overlap(result.label, c.truth, &region);
            const double thrombus = fractionIn(result.label, c.truth, label::kThrombus);
            const double bone = fractionIn(result.label, c.truth, label::kBone);
            const double vein = fractionIn(result.label, c.truth, label::kVein);
            qInfo("seed %llu: aorta + iliac lumen Dice %.4f (recall %.3f, precision %.3f); label in thrombus %.4f, "
                  "bone %.4f, veins %.4f; %g leak(s) cut", (unsigned long long)seed, o.dice, o.recall, o.precision,
                  thrombus, bone, vein, result.figures.at("leaks_cut"));
            QVERIFY2(o.dice >= 0.95, "the lumen of the aorta and iliacs");
            QVERIFY(thrombus < 0.01 && bone < 0.005 && vein < 0.005);

            // The same without a point: the abdominal aorta found beside the spine.
            const Eigen::Vector3d found = findAbdominalAortaPoint(c.ct);
            const Eigen::Vector3d index = c.ct.geometry().patientToIndex(found);
            const std::uint8_t there = c.truth.at(int(std::lround(index.x())), int(std::lround(index.y())),
                                                  int(std::lround(index.z())));
            request.includeMm.clear();
            const SegmentationResult automatic =
                segmentFromPoints(c.ct, ParameterSet(guidedSegmentationParameters()), request);
            const Overlap a = overlap(automatic.label, c.truth, &region);
            qInfo("  automatic point (%.1f, %.1f, %.1f) mm in truth label %d: Dice %.4f", found.x(), found.y(),
                  found.z(), int(there), a.dice);
            QVERIFY(there == label::kVesselLumen && automatic.seedFound);
            QVERIFY(a.dice >= 0.95);
        }
    }

    /// The same from the automatic point on coarse voxels (1.1 x 1.1 x 1.6 mm, a low-dose abdominal protocol): before
    /// 2026-11-28 seed 3 took two vertebral bodies (31 % of its label bone, Dice 0.75): its front entered the
    /// cancellous bone through the cortex touching the aorta and crossed it as a "branch" under the core level.
    /// With the core level held in branches over 20 mm2: Dice 0.962 / 0.969 / 0.947, bone 0 %; but 1 mm waves on
    /// 1.6 mm slices alias (a wave between two slices holds few voxels, the next many), and 6 / 8 / 10 false
    /// leaks cut bands out of the aorta (1.2 mm waves cut none here but let the CT pulmonary angiogram's front into
    /// the heart). Since the leak test reads each cross-section averaged over the waves a voxel layer spans:
    /// Dice 0.985 / 0.978 / 0.980, 0 / 1 / 1 leaks cut. Asserted: no bone, Dice 0.97, at most 2 leaks cut.
    void aaaOnCoarseVoxels()
    {
        for (std::uint64_t seed : {1u, 2u, 3u})
        {
            const Case c = makeCase(PhantomKind::Aaa, {160, 160, 120}, {1.1, 1.1, 1.6}, seed);
            SegmentationRequest request;
            request.target = SegmentationTarget::Aorta;
            const SegmentationResult result = segmentFromPoints(c.ct, ParameterSet(guidedSegmentationParameters()), request);
            const Overlap o = overlap(result.label, c.truth);
            const double bone = fractionIn(result.label, c.truth, label::kBone);
            qInfo("seed %llu at 1.1 x 1.1 x 1.6 mm: lumen Dice %.4f (recall %.3f, precision %.3f); label in bone %.4f; "
                  "%g leak(s) cut", (unsigned long long)seed, o.dice, o.recall, o.precision, bone,
                  result.figures.at("leaks_cut"));
            QVERIFY(result.seedFound);
            QVERIFY(o.dice >= 0.97 && bone < 0.005);
            QVERIFY(result.figures.at("leaks_cut") <= 2.0);
        }
    }

    /// Target all from one point above an eccentric, calcified 50 % stenosis: through the stenosis (the narrowing
    /// is no leak), calcium and the touching femoral vein left out.
    void stenosisLumenFromOnePoint()
    {
        for (std::uint64_t seed : {1u, 2u, 3u})
        {
            const Case c = makeCase(PhantomKind::Stenosis, {160, 160, 160}, {0.5, 0.5, 0.6}, seed);
            const VesselSegment& artery = segmentNamed(c.phantom, "superficial femoral artery");
            SegmentationRequest request;
            request.target = SegmentationTarget::All;
            request.includeMm = {pointAtZ(artery, kPhantomCentre.z() + 30.0)};
            const SegmentationResult result =
                segmentFromPoints(c.ct, ParameterSet(guidedSegmentationParameters()), request);
            const Overlap o = overlap(result.label, c.truth);
            const double calcium = fractionIn(result.label, c.truth, label::kCalcium);
            const double vein = fractionIn(result.label, c.truth, label::kVein);
            qInfo("seed %llu: lumen Dice %.4f (recall %.3f, precision %.3f); label in calcium %.4f, wall %.4f, vein "
                  "%.4f", (unsigned long long)seed, o.dice, o.recall, o.precision, calcium,
                  fractionIn(result.label, c.truth, label::kWall), vein);
            for (const std::string& warning : result.warnings)
                qInfo("  %s", warning.c_str());
            // The issue asks 0.95: 0.952..0.969 over the seeds with the boundary at the local half level (one
            // window for the whole artery gave 0.943..0.963: its level sat above the edge beside the dark wall).
            QVERIFY2(o.dice >= 0.95, "the lumen through the stenosis");
            QVERIFY(calcium < 0.02 && vein < 0.005);
        }
    }

    /// Target hepatic from a point in the aorta and one in the proper hepatic artery: the tree from the celiac
    /// trunk without the aorta, recall by radius class, and the share of the label in the touching portal vein. The
    /// issue asks Dice >= 0.90 on three seeds: 0.919 / 0.909 / 0.899 with the thin-vessel level (2026-11-27; 0.896 /
    /// 0.882 / 0.877 before it, the tips under 1 mm reached on 5-10 % of their voxels, 52-61 % now); 0.922 / 0.911 /
    /// 0.903 with the boundary at 0.45 of the local contrast, where a blurred tube's edge lies (2026-11-28; recall
    /// had stayed under precision at 0.5). Asserted: the 0.90.
    void hepaticTreeFromTwoPoints()
    {
        for (std::uint64_t seed : {1u, 2u, 3u})
            hepaticTreeOnSeed(seed);
    }

    /// The fronts stop where asked: the path length, a stop plane, and an exclude point that claims the vessel
    /// beyond it.
    void limitsAndCompetition()
    {
        const Case c = makeCase(PhantomKind::Stenosis, {160, 160, 160}, {0.5, 0.5, 0.6}, 1);
        const VesselSegment& artery = segmentNamed(c.phantom, "superficial femoral artery");
        const Eigen::Vector3d start = pointAtZ(artery, kPhantomCentre.z() + 30.0);
        const auto zExtent = [&](const SegmentationResult& r) {
            double low = 1e9, high = -1e9;
            const VolumeGeometry& g = r.label.geometry();
            for (int k = 0; k < g.dims[2]; ++k)
                for (int j = 0; j < g.dims[1]; ++j)
                    for (int i = 0; i < g.dims[0]; ++i)
                        if (r.label.at(i, j, k))
                        {
                            const double z = g.indexToPatient(Eigen::Vector3d(i, j, k)).z();
                            low = std::min(low, z), high = std::max(high, z);
                        }
            return std::pair{low, high};
        };
        const ParameterSet parameters(guidedSegmentationParameters());
        SegmentationRequest request;
        request.includeMm = {start};
        request.maxLengthMm = 20.0;
        auto [low, high] = zExtent(segmentFromPoints(c.ct, parameters, request));
        qInfo("max length 20 mm: z %.1f .. %.1f around %.1f", low, high, start.z());
        QVERIFY(high - start.z() < 21.0 && start.z() - low < 21.0 && high - low > 30.0);

        request.maxLengthMm.reset();
        request.stops = {{start - Eigen::Vector3d(0, 0, 10), Eigen::Vector3d(0, 0, -1)}}; // nothing 10 mm below
        std::tie(low, high) = zExtent(segmentFromPoints(c.ct, parameters, request));
        QVERIFY(low > start.z() - 11.0);

        request.stops.clear();
        request.excludeMm = {pointAtZ(artery, start.z() - 20.0)};
        std::tie(low, high) = zExtent(segmentFromPoints(c.ct, parameters, request));
        qInfo("exclude 20 mm below: the label ends at z %.1f", low);
        QVERIFY(low > start.z() - 12.0);
    }

    void refusals()
    {
        const Case c = makeCase(PhantomKind::Stenosis, {96, 96, 40}, {0.5, 0.5, 0.6}, 1);
        const ParameterSet parameters(guidedSegmentationParameters());
        SegmentationRequest request;
        QVERIFY_THROWS_EXCEPTION(Error, segmentFromPoints(c.ct, parameters, request)); // no point
        request.includeMm = {Eigen::Vector3d(0, 0, 5000)};
        QVERIFY_THROWS_EXCEPTION(Error, segmentFromPoints(c.ct, parameters, request)); // outside
        request.includeMm = {kPhantomCentre + Eigen::Vector3d(0, 30, 0)};             // in muscle
        QVERIFY_THROWS_EXCEPTION(Error, segmentFromPoints(c.ct, parameters, request));
        QVERIFY_THROWS_EXCEPTION(Error, segmentationTargetFromName("liver"));
    }

private:
    void hepaticTreeOnSeed(std::uint64_t seed)
    {
        // The grid around the liver hilum and the tree (180 x 180 x 200 mm).
        const Case c = makeCase(PhantomKind::HepaticTree, {256, 256, 200}, {0.7, 0.7, 1.0}, seed, Eigen::Vector3d(-40, -10, 85));
        SegmentationRequest request;
        request.target = SegmentationTarget::Hepatic;
        const VesselSegment& proper = segmentNamed(c.phantom, "proper hepatic artery");
        request.includeMm = {pointAtZ(segmentNamed(c.phantom, "aorta"), kPhantomCentre.z() + 60.0),
                             proper.points[proper.points.size() / 2]};
        const SegmentationResult result = segmentFromPoints(c.ct, ParameterSet(guidedSegmentationParameters()), request);
        const VolumeGeometry& g = c.ct.geometry();
        const LabelVolume aorta = nearSegments(c.phantom, g, {"aorta"}, 2.0);
        std::set<std::string> tree{"celiac trunk", "common hepatic artery", "gastroduodenal artery",
                                   "proper hepatic artery", "right hepatic artery", "left hepatic artery",
                                   "segmental hepatic artery"};
        LabelVolume region = nearSegments(c.phantom, g, tree, 1.0);
        for (std::size_t v = 0; v < g.voxelCount(); ++v)
            region.data()[v] = region.data()[v] && !aorta.data()[v];
        const Overlap o = overlap(result.label, c.truth, &region);
        qInfo("seed %llu: hepatic tree without the aorta: Dice %.3f (recall %.3f, precision %.3f); label in the portal "
              "vein %.4f", (unsigned long long)seed, o.dice, o.recall, o.precision, fractionIn(result.label, c.truth, label::kPortalVein));
        for (const auto& [low, high] : {std::pair{2.0, 9.0}, std::pair{1.0, 2.0}, std::pair{0.0, 1.0}})
        {
            std::set<std::string> names;
            AnatomyPhantom subset = c.phantom;
            subset.arteries.segments.clear();
            for (const VesselSegment& segment : c.phantom.arteries.segments)
            {
                const double mean = 0.5 * (segment.radii.front() + segment.radii.back());
                if (tree.count(segment.name) && mean > low && mean <= high)
                    subset.arteries.segments.push_back(segment);
            }
            for (VesselSegment& segment : subset.arteries.segments)
                names.insert(segment.name = segment.name + " (class)");
            LabelVolume classRegion = nearSegments(subset, g, names, 0.0);
            for (std::size_t v = 0; v < g.voxelCount(); ++v)
                classRegion.data()[v] = classRegion.data()[v] && !aorta.data()[v];
            qInfo("  radius %.0f..%.0f mm: %zu segments, recall %.3f", low, high, subset.arteries.segments.size(),
                  overlap(result.label, c.truth, &classRegion).recall);
        }
        QVERIFY(fractionIn(result.label, c.truth, label::kPortalVein) <= 0.02);
        QVERIFY(o.dice >= 0.90);
    }
};

QTEST_GUILESS_MAIN(GuidedSegmentationTest)
#include "tst_guided_segmentation.moc"
