// The AAA sac on the patient-like phantom, three seeds: from the guided lumen (one point), the outer contour and the
// thrombus against the phantom's truth labels, and the SVS maximum outer diameter and the sac volume against its
// truth measures (computed from the analytic geometry by the same definitions).

#include "vsim/core/Error.h"
#include "vsim/dicom/AnatomyPhantom.h"
#include "vsim/imaging/AneurysmSac.h"
#include "vsim/imaging/GuidedSegmentation.h"

#include <QElapsedTimer>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace vsim;
using namespace vsim::dicom;
using namespace vsim::imaging;

namespace {

double dice(const LabelVolume& a, std::uint8_t va, const LabelVolume& b, std::uint8_t vb)
{
    std::size_t both = 0, na = 0, nb = 0;
    for (std::size_t v = 0; v < a.geometry().voxelCount(); ++v)
    {
        const bool x = a.data()[v] == va, y = b.data()[v] == vb;
        both += x && y, na += x, nb += y;
    }
    return 2.0 * double(both) / double(std::max<std::size_t>(na + nb, 1));
}

} // namespace

class AneurysmSacTest : public QObject
{
    Q_OBJECT

private slots:
    void sacAgainstTruth()
    {
        for (std::uint64_t seed : {1u, 2u, 3u})
        {
            PhantomOptions options;
            options.style = PhantomStyle::Patient;
            options.size = {256, 256, 300}; // from above the renal arteries to 90 mm below the bifurcation
            options.spacing = {0.7, 0.7, 1.0};
            options.seed = seed;
            const AnatomyPhantom phantom = buildAnatomyPhantom(PhantomKind::Aaa, options);
            const CtVolume ct = renderAnatomyCt(phantom, phantomGeometry(options), seed);
            const LabelVolume truth = renderAnatomyLabels(phantom, phantomGeometry(options));
            const auto& m = phantom.measures;

            SegmentationRequest request;
            request.target = SegmentationTarget::Aorta;
            const VesselSegment& aorta = phantom.arteries.segments.front();
            request.includeMm = {*std::min_element(aorta.points.begin(), aorta.points.end(), [&](auto& a, auto& b) {
                return std::abs(a.z() - m.at("max_outer_diameter_z_mm")) < std::abs(b.z() - m.at("max_outer_diameter_z_mm"));
            })};
            const SegmentationResult lumen = segmentFromPoints(ct, ParameterSet(guidedSegmentationParameters()), request);
            // This crop reaches 90 mm into the pelvis, past vertebral bodies with no aorta in front of them: the
            // automatic aorta point must still fall in the aortic lumen (it fell in a vertebral body before).
            const Eigen::Vector3d found = truth.geometry().patientToIndex(findAbdominalAortaPoint(ct));
            QCOMPARE(int(truth.at(int(std::lround(found.x())), int(std::lround(found.y())), int(std::lround(found.z())))),
                     int(label::kVesselLumen));
            QElapsedTimer timer;
            timer.start();
            const AneurysmSac sac = measureAneurysmSac(ct, lumen.label, 1.8);
            const double seconds = double(timer.elapsed()) / 1000.0;
            const auto& f = sac.figures;
            const double thrombusDice = dice(sac.labels, 4, truth, label::kThrombus);
            // Outer contour: lumen + thrombus + wall (+ calcium in the truth).
            LabelVolume outer(truth.geometry()), truthOuter(truth.geometry());
            for (std::size_t v = 0; v < truth.geometry().voxelCount(); ++v)
            {
                outer.data()[v] = sac.labels.data()[v] == 4 || sac.labels.data()[v] == 5;
                const std::uint8_t t = truth.data()[v];
                truthOuter.data()[v] = t == label::kThrombus || t == label::kWall || t == label::kCalcium;
            }
            qInfo("seed %llu (%.2f s): max outer diameter %.2f mm (truth %.2f) at z %.1f (truth %.1f); sac %.1f ml "
                  "(truth %.1f), neck %.1f mm (truth %.1f); thrombus Dice %.3f, wall + thrombus Dice %.3f; largest "
                  "thrombus %.1f mm (truth %.1f); lumen at the maximum %.1f mm (truth %.1f)",
                  (unsigned long long)seed, seconds, f.at("max_outer_diameter_mm"), m.at("max_outer_diameter_mm"),
                  f.at("max_outer_diameter_z_mm"), m.at("max_outer_diameter_z_mm"), f.at("sac_volume_ml"),
                  m.at("sac_volume_ml"), f.at("neck_diameter_mm"), m.at("neck_diameter_mm"), thrombusDice,
                  dice(outer, 1, truthOuter, 1), f.at("max_thrombus_thickness_mm"), m.at("max_thrombus_thickness_mm"),
                  f.at("lumen_diameter_at_max_mm"), m.at("lumen_diameter_at_max_mm"));
            qInfo("  sac %.1f .. %.1f mm (truth %.1f .. %.1f), length %.1f mm (truth %.1f)", f.at("sac_top_z_mm"),
                  f.at("sac_bottom_z_mm"), m.at("sac_top_z_mm"), m.at("sac_bottom_z_mm"), f.at("sac_length_mm"),
                  m.at("sac_length_mm"));
            QVERIFY(std::abs(f.at("max_outer_diameter_mm") - m.at("max_outer_diameter_mm")) <= 2.0);
            QVERIFY(std::abs(f.at("sac_volume_ml") - m.at("sac_volume_ml")) <= 0.05 * m.at("sac_volume_ml"));
            QVERIFY(thrombusDice >= 0.85);
            // The neck at the lowest renal artery, its length and angulation, the common iliacs.
            for (const char* key : {"neck_length_mm", "neck_angulation_deg", "left_common_iliac_diameter_mm",
                                    "right_common_iliac_diameter_mm"})
                QVERIFY2(f.count(key), key);
            QVERIFY(std::abs(f.at("neck_diameter_mm") - m.at("neck_diameter_mm")) <= 2.0);
            QVERIFY(std::abs(f.at("neck_length_mm") - m.at("neck_length_mm")) <= 5.0);
            QVERIFY(std::abs(f.at("neck_angulation_deg") - m.at("neck_angulation_deg")) <= 5.0);
            for (const char* key : {"left_common_iliac_diameter_mm", "right_common_iliac_diameter_mm"})
                QVERIFY2(std::abs(f.at(key) - m.at(key)) <= 3.0, key);
            const auto figure = [&](const char* key) { return f.count(key) ? f.at(key) : std::nan(""); };
            qInfo("  neck at the lowest renal artery (z %.1f): length %.1f mm (truth %.1f), angulation %.1f deg (truth "
                  "%.1f); common iliac outer diameters left %.1f / right %.1f mm (truth %.1f / %.1f)",
                  figure("lowest_renal_z_mm"), figure("neck_length_mm"), m.at("neck_length_mm"),
                  figure("neck_angulation_deg"), m.at("neck_angulation_deg"), figure("left_common_iliac_diameter_mm"),
                  figure("right_common_iliac_diameter_mm"), m.at("left_common_iliac_diameter_mm"),
                  m.at("right_common_iliac_diameter_mm"));
        }
    }

    void refusesALabelWithoutAnAorta()
    {
        VolumeGeometry g;
        g.dims = {32, 32, 16};
        CtVolume ct(g);
        LabelVolume lumen(g);
        std::fill(ct.data(), ct.data() + g.voxelCount(), std::int16_t(40));
        std::fill(lumen.data(), lumen.data() + g.voxelCount(), std::uint8_t(0));
        lumen.at(5, 5, 5) = 1;
        QVERIFY_THROWS_EXCEPTION(Error, measureAneurysmSac(ct, lumen, 1.8));
    }

    /// No fat around the aorta (uniform 40 HU tissue, as the analytic phantoms have): no outer edge within 60 mm,
    /// so no contour and no figures (a 120 mm "diameter" was reported before).
    void refusesAnImageWithoutAnOuterEdge()
    {
        VolumeGeometry g;
        g.dims = {200, 200, 20};
        g.spacing = {0.8, 0.8, 2.0};
        CtVolume ct(g);
        LabelVolume lumen(g);
        for (int k = 0; k < g.dims[2]; ++k)
            for (int j = 0; j < g.dims[1]; ++j)
                for (int i = 0; i < g.dims[0]; ++i)
                {
                    const bool inside = std::hypot((i - 100) * 0.8, (j - 100) * 0.8) <= 12.0;
                    ct.at(i, j, k) = std::int16_t(inside ? 300 : 40);
                    lumen.at(i, j, k) = inside ? 1 : 0;
                }
        try
        {
            measureAneurysmSac(ct, lumen, 1.8);
            QFAIL("an aorta in uniform tissue has no outer contour to measure");
        }
        catch (const Error& error)
        {
            QVERIFY(std::string(error.what()).find("outer wall could not be traced") != std::string::npos);
        }
    }
};

QTEST_GUILESS_MAIN(AneurysmSacTest)
#include "tst_aneurysm_sac.moc"
