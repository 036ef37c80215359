// Study bundle: every artifact kind survives save/open exactly; provenance is recorded; damage is reported and
// flagged without losing the rest; a newer schema is refused; undo of a removal survives a save.
#include "StudyFixtures.h"
#include "TestOutput.h"
#include "vsim/core/Error.h"
#include "vsim/study/NetworkFile.h"
#include "vsim/study/Study.h"

#include <QtTest>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using vsim::study::Study;

/// A report's bytes: a PDF header and bytes a text read or write would change.
const std::string kReportPdf = std::string("%PDF-1.4\n") + std::string("\0\r\n\xff\x80 binary", 13) + "\n%%EOF\n";

class TestBundle : public QObject
{
    Q_OBJECT

    fs::path freshBundle(const char* name)
    {
        const fs::path bundle = fs::path(vsim::test::outputFolder("study").toStdString()) / name;
        fs::remove_all(bundle);
        return bundle;
    }

    /// A Y of three conical segments with one outlet at a pressure, one through a resistance, and a result field.
    static vsim::VesselNetwork yNetwork()
    {
        vsim::VesselNetwork network;
        for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 20), Eigen::Vector3d(-5, 0, 30),
                                         Eigen::Vector3d(5, 0, 30)})
            network.nodes.push_back({p, {}});
        network.nodes[1].name = "junction";
        for (const auto& [from, to] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{1, 3}})
            network.segments.push_back({from, to, 1.5, 1.2, 20.0, 0.0, {}});
        network.segments[1].resistance = 4e9;
        network.segments[2].pathMm = {{0, 0, 20}, {3, 0, 26}, {5, 0, 30}};
        network.outlets = {{2, vsim::VesselNetwork::Outlet::Type::Pressure, 1333.0, 0.0},
                           {3, vsim::VesselNetwork::Outlet::Type::Resistance, 1000.0, 8e10}};
        network.root = 0;
        network.segmentFields["flow_ml_min"] = {2.0, 1.25, 0.75};
        return network;
    }

    /// A saved study holding one artifact of every kind.
    Study savedStudy(const fs::path& bundle)
    {
        Study study = Study::create(bundle, "Phantom study");
        study.setMetadata("study_description", "CTA abdomen");
        vsim::study::Provenance provenance{"test fixture", {{"multiplier", "3"}}, {"none"}, "", ""};
        study.addImage(vsim::test::patternedVolume(8, 3), "CTA", provenance);
        vsim::LabelVolume label(vsim::test::patternedVolume(8, 3).geometry());
        label.at(2, 3, 4) = 1;
        study.addLabel(label, "Lumen", provenance);
        vsim::TriangleMesh surface;
        surface.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        surface.triangles = {{0, 1, 2}};
        study.addSurface(surface, "Lumen surface", provenance);
        study.addTetMesh(vsim::test::singleTet(), "Wall", provenance);
        study.addSkeleton(vsim::test::twoNodeSkeleton(), "Skeleton", provenance, {"one spur pruned"});
        study.addNetwork(yNetwork(), "Drug flow", provenance);
        study.addReport(kReportPdf, "Report", provenance);
        study.save();
        return study;
    }

private slots:
    void everyKindRoundTripsExactly()
    {
        const fs::path bundle = freshBundle("roundtrip.vsim");
        savedStudy(bundle);
        const Study reopened = Study::open(bundle, vsim::study::Access::ReadOnly);
        QVERIFY(reopened.openWarnings().empty());
        QCOMPARE(reopened.name(), std::string("Phantom study"));
        QCOMPARE(reopened.metadata().at("study_description"), std::string("CTA abdomen"));
        QCOMPARE(reopened.artifacts().size(), std::size_t(7));

        const vsim::CtVolume image = reopened.loadImage("image-1");
        QVERIFY(image.geometry().isClose(vsim::test::patternedVolume(8, 3).geometry(), 1e-9));
        QVERIFY(reopened.volumeGeometry("image-1").isClose(image.geometry(), 1e-9)); // header only
        QVERIFY(vsim::test::samePattern(image, 3));
        QCOMPARE(reopened.loadLabel("label-2").at(2, 3, 4), std::uint8_t(1));
        QCOMPARE(reopened.loadSurface("surface-3").triangles.size(), std::size_t(1));
        const vsim::TetMesh wall = reopened.loadTetMesh("tetmesh-4");
        QCOMPARE(wall.cellFields.at("von_mises_kpa"), std::vector<double>{12.5});
        QVERIFY(std::abs(wall.totalVolume() - 8.0 / 6.0) < 1e-12);
        const vsim::SkeletonGraph skeleton = reopened.loadSkeleton("skeleton-5");
        QCOMPARE(skeleton.edges[0].radii, (std::vector<double>{3.0, 2.9, 2.8, 2.7}));

        const vsim::VesselNetwork network = reopened.loadNetwork("network-6"), written = yNetwork();
        QCOMPARE(network.nodes[1].name, std::string("junction"));
        QCOMPARE(network.segments[2].pathMm.size(), std::size_t(3));
        QVERIFY(std::abs(network.segments[1].resistance / written.segments[1].resistance - 1.0) < 1e-12);
        QVERIFY(std::abs(network.outlets[0].pressurePa - 1333.0) < 1e-9);
        QVERIFY(network.outlets[1].type == vsim::VesselNetwork::Outlet::Type::Resistance);
        QVERIFY(std::abs(network.outlets[1].resistance / 8e10 - 1.0) < 1e-12);
        QCOMPARE(network.segmentFields.at("flow_ml_min"), (std::vector<double>{2.0, 1.25, 0.75}));
        QCOMPARE(network.root, 0);

        // A report is kept byte for byte (binary included) as reports/<id>.pdf; anything else is refused.
        QCOMPARE(reopened.loadReport("report-7"), kReportPdf);
        QCOMPARE(reopened.artifact("report-7").file, std::string("reports/report-7.pdf"));
        QVERIFY(fs::exists(bundle / "reports" / "report-7.pdf"));
        Study other = Study::create(freshBundle("notpdf.vsim"), "x");
        QVERIFY_THROWS_EXCEPTION(vsim::Error, other.addReport("not a pdf", "Report", {}));

        const auto& provenance = reopened.artifact("image-1").provenance;
        QCOMPARE(provenance.command, std::string("test fixture"));
        QCOMPARE(provenance.parameters.at("multiplier"), std::string("3"));
        QVERIFY(!provenance.time.empty() && !provenance.softwareVersion.empty());
        QCOMPARE(reopened.artifact("skeleton-5").warnings, std::vector<std::string>{"one spur pruned"});
    }

    // Network files a user wrote: what is wrong is named.
    void badNetworkFilesAreRefusedWithTheReason()
    {
        auto messageOf = [](const std::string& text) {
            try
            {
                vsim::study::networkFromJsonText(text);
            }
            catch (const vsim::Error& error)
            {
                return QString::fromStdString(error.message());
            }
            return QString();
        };
        QVERIFY(messageOf("{}").contains("not a vascusim network file"));
        QVERIFY(messageOf("not json").contains("cannot read the network file"));
        const std::string head = R"({"format": "vascusim-network", "version": 1, "nodes": [{"position_mm": [0, 0, 0]},
            {"position_mm": [0, 0, 10]}], "segments": [)";
        QVERIFY(messageOf(head + R"({"from": 0, "to": 1, "start_radius_mm": 1, "length_mm": 10}]})")
                    .contains("segment 0 of the network file"));
        QVERIFY(messageOf(head + R"({"from": 0, "to": 1, "start_radius_mm": 1, "end_radius_mm": -1, "length_mm": 10}]})")
                    .contains("segment 0 has a radius that is zero or negative"));
        const std::string text = vsim::study::networkToJsonText(yNetwork());
        QCOMPARE(vsim::study::networkFromJsonText(text).segments.size(), std::size_t(3));
    }

    void damagedAndMissingFilesAreFlaggedAndTheRestOpens()
    {
        const fs::path bundle = freshBundle("damaged.vsim");
        savedStudy(bundle);
        { // flip bytes in the middle of the CT
            std::fstream file(bundle / "images/image-1.nrrd", std::ios::in | std::ios::out | std::ios::binary);
            file.seekp(-20, std::ios::end);
            file.write("XXXX", 4);
        }
        fs::remove(bundle / "meshes/tetmesh-4.vtu");
        const Study reopened = Study::open(bundle, vsim::study::Access::ReadOnly);
        QCOMPARE(reopened.openWarnings().size(), std::size_t(2));
        QVERIFY(reopened.artifact("image-1").damaged);
        QVERIFY(reopened.artifact("tetmesh-4").damaged);
        QVERIFY(!reopened.artifact("label-2").damaged);
        QVERIFY_THROWS_EXCEPTION(vsim::Error, reopened.loadImage("image-1"));
        QCOMPARE(reopened.loadLabel("label-2").at(2, 3, 4), std::uint8_t(1));
    }

    void newerSchemaAndNonStudiesAreRefused()
    {
        const fs::path bundle = freshBundle("newer.vsim");
        savedStudy(bundle);
        std::string text;
        {
            std::ifstream in(bundle / "study.json");
            text.assign(std::istreambuf_iterator<char>(in), {});
        }
        const auto position = text.find("\"schema_version\": 2");
        QVERIFY(position != std::string::npos);
        text.replace(position, 19, "\"schema_version\": 99");
        std::ofstream(bundle / "study.json") << text;
        try
        {
            Study::open(bundle);
            QFAIL("a newer schema must be refused");
        }
        catch (const vsim::Error& error)
        {
            QVERIFY(QString::fromStdString(error.message()).contains("newer VascuSim"));
        }
        QVERIFY_THROWS_EXCEPTION(vsim::Error, Study::open(freshBundle("nothing-here.vsim")));
    }

    void removalCanBeUndoneAfterASave()
    {
        const fs::path bundle = freshBundle("undo.vsim");
        Study study = savedStudy(bundle);
        study.removeArtifact("image-1");
        study.save();
        QVERIFY(!fs::exists(bundle / "images/image-1.nrrd")); // unreferenced files are removed at save
        study.restoreArtifact("image-1");
        study.save();
        const Study reopened = Study::open(bundle, vsim::study::Access::ReadOnly);
        QVERIFY(vsim::test::samePattern(reopened.loadImage("image-1"), 3));
    }

    void saveAsCopiesEverythingToTheNewBundle()
    {
        const fs::path first = freshBundle("first.vsim");
        const fs::path second = freshBundle("second.vsim");
        Study study = savedStudy(first);
        study.renameArtifact("image-1", "Arterial phase");
        study.saveAs(second);
        QCOMPARE(study.bundlePath(), second);
        const Study copy = Study::open(second, vsim::study::Access::ReadOnly);
        QVERIFY(copy.openWarnings().empty());
        QCOMPARE(copy.artifact("image-1").name, std::string("Arterial phase"));
        QVERIFY(vsim::test::samePattern(copy.loadImage("image-1"), 3));
        QVERIFY_THROWS_EXCEPTION(vsim::Error, study.saveAs(first)); // not empty
    }
};

QTEST_APPLESS_MAIN(TestBundle)
#include "tst_bundle.moc"
