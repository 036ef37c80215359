// The phantoms are the ground truth of every later test: their truth must describe their images. Checked here
// against the truth labels (measured diameters), the truth.json topology and the CT intensities.

#include "TestOutput.h"
#include "vsim/core/ParallelFor.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/dicom/PhantomWriter.h"
#include "vsim/interop/NrrdFile.h"

#include <nlohmann/json.hpp>

#include <QtTest>

#include <cmath>
#include <fstream>
#include <numbers>

using namespace vsim;
using namespace vsim::dicom;

namespace {

PhantomOptions optionsOf(std::array<int, 3> size, Eigen::Vector3d spacing, double noise = 0.0)
{
    PhantomOptions options;
    options.size = size;
    options.spacing = spacing;
    options.noiseHu = noise;
    return options;
}

/// Area (mm^2) of a label in slice k.
double labelArea(const LabelVolume& labels, int k, std::uint8_t value)
{
    const VolumeGeometry& g = labels.geometry();
    std::size_t count = 0;
    for (int j = 0; j < g.dims[1]; ++j)
        for (int i = 0; i < g.dims[0]; ++i)
            count += labels.at(i, j, k) == value;
    return double(count) * g.spacing.x() * g.spacing.y();
}

double equivalentDiameter(double area)
{
    return 2.0 * std::sqrt(area / std::numbers::pi);
}

struct Statistics
{
    double mean = 0, deviation = 0;
    std::size_t count = 0;
};

/// HU statistics of the voxels whose label is `value` and whose 6 neighbours share it (away from edges).
Statistics interiorStatistics(const CtVolume& ct, const LabelVolume& labels, std::uint8_t value)
{
    const VolumeGeometry& g = ct.geometry();
    double sum = 0, squares = 0;
    std::size_t count = 0;
    for (int k = 2; k < g.dims[2] - 2; ++k)
        for (int j = 2; j < g.dims[1] - 2; ++j)
            for (int i = 2; i < g.dims[0] - 2; ++i)
            {
                bool inside = true;
                for (int d = -2; d <= 2 && inside; ++d)
                    inside = labels.at(i + d, j, k) == value && labels.at(i, j + d, k) == value &&
                             labels.at(i, j, k + d) == value;
                if (!inside)
                    continue;
                const double hu = ct.at(i, j, k);
                sum += hu;
                squares += hu * hu;
                ++count;
            }
    Statistics statistics;
    statistics.count = count;
    if (count > 1)
    {
        statistics.mean = sum / count;
        statistics.deviation = std::sqrt(std::max(0.0, squares / count - statistics.mean * statistics.mean));
    }
    return statistics;
}

} // namespace

class Phantom : public QObject
{
    Q_OBJECT

private slots:
    void aneurysmDiameterMatchesTruth()
    {
        const PhantomOptions options = optionsOf({256, 256, 200}, {1.4, 1.4, 2.0});
        const PhantomModel model = buildPhantomModel(PhantomKind::Aaa, options);
        const VolumeGeometry geometry = phantomGeometry(options);
        const LabelVolume labels = renderPhantomLabels(model, geometry);
        double largest = 0;
        for (int k = 0; k < geometry.dims[2]; ++k)
        {
            const double z = geometry.indexToPatient(Eigen::Vector3d(0, 0, k)).z();
            if (std::abs(z - model.measures.at("aneurysm_centre_z_mm")) < 20.0) // the aorta alone in the slice
                largest = std::max(largest, equivalentDiameter(labelArea(labels, k, label::kVesselLumen)));
        }
        qInfo("aaa: largest lumen diameter measured %.2f mm, truth %.2f mm", largest, model.measures.at("max_diameter_mm"));
        QVERIFY(std::abs(largest - 55.0) < 1.4); // one voxel
        QCOMPARE(model.measures.at("max_diameter_mm"), 55.0);
    }

    void stenosisMatchesTruth()
    {
        // Fine voxels (0.25 mm) around the stenosis; the artery runs 8.2 degrees off z, so axial sections are
        // ellipses: area * cos(angle) is the perpendicular cross-section.
        const PhantomOptions options = optionsOf({96, 96, 160}, {0.25, 0.25, 0.25});
        const PhantomModel model = buildPhantomModel(PhantomKind::Stenosis, options);
        const VolumeGeometry geometry = phantomGeometry(options);
        const LabelVolume labels = renderPhantomLabels(model, geometry);
        const double cosine = Eigen::Vector3d(0.15, 0.10, 1.0).normalized().z();
        double smallest = 1e9, ends = 0;
        for (int k = 0; k < geometry.dims[2]; ++k)
        {
            const double diameter = equivalentDiameter(labelArea(labels, k, label::kVesselLumen) * cosine);
            smallest = std::min(smallest, diameter);
            if (k == 0 || k == geometry.dims[2] - 1)
                ends += 0.5 * diameter;
        }
        const double percent = 100.0 * (1.0 - smallest / model.measures.at("reference_diameter_mm"));
        qInfo("stenosis: minimal diameter %.3f mm, reference at the ends %.3f mm, %.1f %%", smallest, ends, percent);
        QVERIFY(std::abs(smallest - model.measures.at("minimal_diameter_mm")) < 0.15);
        QVERIFY(std::abs(ends - 6.0) < 0.15);
        QVERIFY(std::abs(percent - 50.0) < 2.5);
    }

    void hepaticTreeTopology()
    {
        const auto out = std::filesystem::path(test::outputFolder("dicom-phantom").toStdString()) / "hepatic";
        std::filesystem::remove_all(out);
        const PhantomOptions options = optionsOf({96, 96, 64}, {2.0, 2.0, 2.5});
        const PhantomFiles files =
            writePhantom(PhantomKind::HepaticTree, options, phantomSeriesDescription(PhantomKind::HepaticTree), out);
        const auto truth = nlohmann::json::parse(std::ifstream(files.truthJson));
        QCOMPARE(truth["kind"].get<std::string>(), std::string("hepatic-tree"));
        const auto& segments = truth["segments"];
        QVERIFY(segments.size() >= 15);
        int generations = 0, ends = 0, junctions = 0;
        double largest = 0, smallest = 1e9;
        for (const auto& segment : segments)
        {
            generations = std::max(generations, segment["generation"].get<int>() + 1);
            QVERIFY(segment["radius_end_mm"].get<double>() < segment["radius_start_mm"].get<double>()); // conical
            QVERIFY(segment["length_mm"].get<double>() > 0);
            QCOMPARE(segment["centerline_mm"].size(), segment["radii_mm"].size());
            largest = std::max(largest, segment["radius_start_mm"].get<double>());
            smallest = std::min(smallest, segment["radius_end_mm"].get<double>());
        }
        for (const auto& node : truth["nodes"])
            (node["degree"].get<int>() == 1 ? ends : junctions) += 1;
        QVERIFY(generations >= 4);
        QCOMPARE(largest, 3.0);
        QVERIFY(smallest > 0.6 && smallest < 0.8);
        QCOMPARE(junctions, int(segments.size() - 1) / 2); // a binary tree
        QCOMPARE(ends, junctions + 2);
        QVERIFY(truth["measures"].contains("tumour_radius_mm"));
        // The truth labels on disk hold lumen and tumour.
        const LabelVolume labels = interop::readNrrd<std::uint8_t>(files.truthLabels);
        std::array<std::size_t, 4> counts{};
        for (std::size_t i = 0; i < labels.size(); ++i)
            ++counts[std::min<std::size_t>(labels.data()[i], 3)];
        QVERIFY(counts[label::kVesselLumen] > 100);
        QVERIFY(counts[label::kTumour] > 100);
        QVERIFY(labels.geometry().isClose(files.geometry, 1e-9));
    }

    void bifurcationTopology()
    {
        const PhantomModel model = buildPhantomModel(PhantomKind::Bifurcation, optionsOf({64, 64, 64}, {2, 2, 2}));
        QCOMPARE(model.segments.size(), std::size_t(3));
        QCOMPARE(model.segments[1].from, model.segments[0].to);
        QCOMPARE(model.segments[2].from, model.segments[0].to);
        QVERIFY(std::abs(model.measures.at("daughter_diameter_mm") - 8.0 * std::pow(2.0, -1.0 / 3.0)) < 1e-12);
    }

    void intensitiesAreRealistic()
    {
        const PhantomOptions options = optionsOf({160, 160, 100}, {2.0, 2.0, 3.0}, 20.0);
        const PhantomModel model = buildPhantomModel(PhantomKind::Aaa, options);
        const VolumeGeometry geometry = phantomGeometry(options);
        const CtVolume ct = renderPhantomCt(model, stackOf(geometry), options);
        const LabelVolume labels = renderPhantomLabels(model, geometry);
        const Statistics blood = interiorStatistics(ct, labels, label::kVesselLumen);
        const Statistics bone = interiorStatistics(ct, labels, label::kBone);
        qInfo("blood %.1f +- %.1f HU (%zu voxels), bone %.1f +- %.1f HU", blood.mean, blood.deviation, blood.count,
              bone.mean, bone.deviation);
        QVERIFY(blood.count > 1000 && std::abs(blood.mean - hu::kContrastBlood) < 2.0);
        QVERIFY(std::abs(blood.deviation - 20.0) < 1.0);
        QVERIFY(std::abs(bone.mean - hu::kBone) < 3.0 && bone.mean >= 700.0);
        QCOMPARE(int(ct.at(0, 0, 0)) < -950, true); // air in the corner
        double soft = 0;
        int n = 0;
        for (int i = 60; i < 70; ++i) // soft tissue lateral to the aorta, left of the spine
            for (int j = 70; j < 80; ++j)
                soft += ct.at(i + 40, j, 50), ++n;
        QVERIFY(std::abs(soft / n - hu::kSoftTissue) < 10.0);
    }

    void seededAndReproducible()
    {
        PhantomOptions options = optionsOf({48, 48, 24}, {6, 6, 14}, 20.0);
        const PhantomModel model = buildPhantomModel(PhantomKind::Aaa, options);
        const SliceStack stack = stackOf(phantomGeometry(options));
        const CtVolume a = renderPhantomCt(model, stack, options), b = renderPhantomCt(model, stack, options);
        QVERIFY(std::equal(a.data(), a.data() + a.size(), b.data()));
        options.seed = 2;
        const CtVolume c = renderPhantomCt(model, stack, options);
        QVERIFY(!std::equal(a.data(), a.data() + a.size(), c.data()));
    }

    void badOptionsNameTheOption()
    {
        PhantomOptions options;
        options.stenosisPercent = 120;
        try
        {
            buildPhantomModel(PhantomKind::Stenosis, options);
            QFAIL("120 % must be refused");
        }
        catch (const Error& error)
        {
            QCOMPARE(error.contextValue("option"), std::string("stenosis"));
        }
        QVERIFY_THROWS_EXCEPTION(Error, phantomKindFromName("aorta"));
        options = {};
        options.size = {4, 512, 400};
        QVERIFY_THROWS_EXCEPTION(Error, options.validate());
    }
};

QTEST_GUILESS_MAIN(Phantom)
#include "tst_phantom.moc"
