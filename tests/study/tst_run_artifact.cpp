// The Run artifact (issue 17): a run of each frame kind (voxel grid from the template solver on the run driver, tet
// mesh, vessel network) written into the study, reopened with its record and frames exact, its series.pvd and
// frames read back with VTK as ParaView reads them; a damaged frame flags the run; removing a run removes only its
// files (a file someone put in its folder stays), an undo brings it back; Save As carries it.

#include "TestOutput.h"
#include "vsim/core/Error.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/heat/HeatDiffusion.h"
#include "vsim/study/Study.h"

#include <QtTest>
#include <vtkDataObject.h>
#include <vtkDataSet.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace vsim;
using study::Study;

namespace {

fs::path freshBundle(const char* name)
{
    const fs::path bundle = fs::path(test::outputFolder("study").toStdString()) / name;
    fs::remove_all(bundle);
    return bundle;
}

SolverRun heatRun()
{
    ParameterSet parameters(sim::heat::heatParameters());
    parameters.set("cells", 8);
    parameters.set("end_time_s", 30.0);
    sim::heat::HeatDiffusionSolver solver;
    sim::RunControl control;
    control.frameEverySteps = 4, control.keepEvery = 2;
    return sim::runSolver(solver, {}, parameters, control);
}

/// A hand-made run of two frames of another kind, stopped by a guard.
template <class Data>
SolverRun twoFrameRun(const Data& first, const Data& second)
{
    SolverRun run;
    run.axis = {"pressure", "kPa", 16.0};
    run.frames = {{0, 0, 0.0, first}, {3, 30, 12.5, second}};
    run.keptFrameNumbers = {0, 3};
    run.framesTaken = 4, run.steps = 30;
    run.status.recordSolve(100, 3e-3, 1e-6, 100);
    run.status.stoppedBy = RunStatus::StoppedBy::Guard;
    run.status.stopMessage = "inverted element 7";
    run.status.reachedQuantity = "pressure", run.status.reachedUnit = "kPa", run.status.reached = 12.5;
    run.status.target = 16.0;
    run.metrics = run.status.metrics();
    run.metrics["peak_von_mises_kpa"] = 208.25;
    run.metrics["undefined_figure"] = std::nan("");
    run.provenance = {"fem", {{"young_modulus_mpa", "4.23"}}, {{"wall", "tetmesh-3"}}, "2026-11-24T00:00:00Z", 1.5};
    return run;
}

TetMesh tet(double stretch)
{
    TetMesh mesh;
    mesh.points = {{0, 0, 0}, {stretch, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    mesh.tets = {{0, 1, 2, 3}};
    mesh.pointFields["displacement_mm"] = {0.0, stretch - 1.0, 0.0, 0.0};
    mesh.cellFields["von_mises_kpa"] = {100.0 * stretch};
    return mesh;
}

VesselNetwork network(double flow)
{
    VesselNetwork n;
    for (const Eigen::Vector3d& p : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 20), Eigen::Vector3d(-5, 0, 30),
                                     Eigen::Vector3d(5, 0, 30)})
        n.nodes.push_back({p, {}});
    for (const auto& [from, to] : {std::pair{0, 1}, std::pair{1, 2}, std::pair{1, 3}})
        n.segments.push_back({from, to, 1.5, 1.2, 20.0, 0.0, {}});
    n.segments[1].resistance = 4e9;
    n.segments[2].pathMm = {{0, 0, 20}, {3, 0, 26}, {5, 0, 30}};
    n.outlets = {{2, VesselNetwork::Outlet::Type::Pressure, 1333.0, 0.0},
                 {3, VesselNetwork::Outlet::Type::Resistance, 1000.0, 8e10}};
    n.root = 0;
    n.segmentFields["flow_ml_min"] = {flow, 0.6 * flow, 0.4 * flow};
    return n;
}

/// Particles of a blood-flow frame: positions (mm) and their speed and pressure.
ParticleSet particles(double shift)
{
    ParticleSet set;
    for (int i = 0; i < 5; ++i)
        set.positionsMm.push_back(Eigen::Vector3d(0.25 * i + shift, -0.5 * i, 1.0 / 3.0 + i));
    set.fields["speed_m_s"] = {0.1, 0.2, 0.3, 0.4, 0.5 + shift};
    set.fields["pressure_pa"] = {1333.0, 1200.5, 1100.25, 1000.0, -1.0 / 7.0};
    return set;
}

void compareRecords(const SolverRun& read, const SolverRun& written)
{
    QCOMPARE(read.axis.quantity, written.axis.quantity);
    QCOMPARE(read.axis.unit, written.axis.unit);
    QCOMPARE(read.axis.target, written.axis.target);
    QCOMPARE(read.keptFrameNumbers, written.keptFrameNumbers);
    QCOMPARE(read.framesTaken, written.framesTaken);
    QCOMPARE(read.steps, written.steps);
    QCOMPARE(read.status.stoppedBy, written.status.stoppedBy);
    QCOMPARE(read.status.stopMessage, written.status.stopMessage);
    QCOMPARE(read.status.convergenceText(), written.status.convergenceText());
    QCOMPARE(read.status.stopText(), written.status.stopText());
    QCOMPARE(read.provenance.solver, written.provenance.solver);
    QCOMPARE(read.provenance.parameters, written.provenance.parameters);
    QCOMPARE(read.provenance.inputs, written.provenance.inputs);
    QCOMPARE(read.metrics.size(), written.metrics.size());
    for (const auto& [key, value] : written.metrics)
        QVERIFY2(std::isnan(value) ? std::isnan(read.metrics.at(key)) : read.metrics.at(key) == value, key.c_str());
}

} // namespace

class RunArtifact : public QObject
{
    Q_OBJECT
private slots:
    void everyFrameKindRoundTrips()
    {
        const fs::path bundle = freshBundle("runs.vsim");
        const SolverRun heat = heatRun();
        const SolverRun wall = twoFrameRun(tet(1.0), tet(1.25));
        const SolverRun drug = twoFrameRun(network(2.0), network(3.0));
        const SolverRun blood = twoFrameRun(particles(0.0), particles(0.5));
        std::string heatId, wallId, drugId, bloodId;
        {
            Study study = Study::create(bundle, "Runs");
            const study::Provenance provenance{"simulate heat", {}, {}, "", ""};
            heatId = study.addRun(heat, "Heat (template)", provenance);
            wallId = study.addRun(wall, "Wall stress", provenance);
            drugId = study.addRun(drug, "Drug filling", provenance);
            bloodId = study.addRun(blood, "Blood flow", provenance);
            QCOMPARE(study.loadRunFrame(heatId, 1).number, heat.frames[1].number); // from memory before the save
            study.save();
        }
        QVERIFY(fs::exists(bundle / "runs" / heatId / "run.json"));
        QVERIFY(fs::exists(bundle / "runs" / heatId / "series.pvd"));
        const Study study = Study::open(bundle, study::Access::ReadOnly);
        QVERIFY(study.openWarnings().empty());
        QCOMPARE(study.artifact(heatId).kind, study::ArtifactKind::Run);

        const SolverRun heatRead = study.loadRun(heatId, false);
        QVERIFY(heatRead.frames.empty());
        compareRecords(heatRead, heat);
        for (std::size_t f = 0; f < heat.frames.size(); ++f)
        {
            const RunFrame frame = study.loadRunFrame(heatId, f);
            QCOMPARE(frame.step, heat.frames[f].step);
            QCOMPARE(frame.position, heat.frames[f].position);
            const GridFields& a = std::get<GridFields>(frame.data);
            const GridFields& b = std::get<GridFields>(heat.frames[f].data);
            QCOMPARE(a.geometry.dims, b.geometry.dims);
            QCOMPARE(a.geometry.spacing, b.geometry.spacing);
            const RealVolume& ra = a.fields.at("temperature_rise_k");
            const RealVolume& rb = b.fields.at("temperature_rise_k");
            QVERIFY(std::equal(ra.data(), ra.data() + ra.size(), rb.data()));
        }
        QVERIFY_THROWS_EXCEPTION(Error, study.loadRunFrame(heatId, heat.frames.size()));

        const SolverRun wallRead = study.loadRun(wallId);
        compareRecords(wallRead, wall);
        const TetMesh& mesh = std::get<TetMesh>(wallRead.frames[1].data);
        QCOMPARE(mesh.points, tet(1.25).points);
        QCOMPARE(mesh.cellFields.at("von_mises_kpa"), tet(1.25).cellFields.at("von_mises_kpa"));
        QCOMPARE(mesh.pointFields.at("displacement_mm"), tet(1.25).pointFields.at("displacement_mm"));

        const SolverRun drugRead = study.loadRun(drugId);
        compareRecords(drugRead, drug);
        const VesselNetwork& read = std::get<VesselNetwork>(drugRead.frames[1].data);
        const VesselNetwork expected = network(3.0);
        QCOMPARE(read.nodes.size(), expected.nodes.size());
        for (std::size_t n = 0; n < read.nodes.size(); ++n)
            QCOMPARE(read.nodes[n].positionMm, expected.nodes[n].positionMm);
        QCOMPARE(read.segments.size(), expected.segments.size());
        for (std::size_t s = 0; s < read.segments.size(); ++s)
        {
            QCOMPARE(read.segments[s].from, expected.segments[s].from);
            QCOMPARE(read.segments[s].to, expected.segments[s].to);
            QCOMPARE(read.segments[s].endRadiusMm, expected.segments[s].endRadiusMm);
            QCOMPARE(read.segments[s].resistance, expected.segments[s].resistance);
            QCOMPARE(read.segments[s].pathMm, expected.segments[s].pathMm);
        }
        QCOMPARE(read.segmentFields, expected.segmentFields);
        QCOMPARE(read.root, 0);
        QCOMPARE(read.outlets.size(), std::size_t(2));
        QCOMPARE(read.outlets[1].resistance, 8e10);
        read.validate();

        // Particles are polydata too (.vtp, vertices and no lines): read back as particles, to the last bit.
        const SolverRun bloodRead = study.loadRun(bloodId);
        compareRecords(bloodRead, blood);
        const ParticleSet& flowing = std::get<ParticleSet>(bloodRead.frames[1].data);
        QCOMPARE(flowing.positionsMm, particles(0.5).positionsMm);
        QCOMPARE(flowing.fields, particles(0.5).fields);
    }

    /// ParaView's view of the run: series.pvd lists the kept frames at their positions, each a VTK XML file with
    /// the fields.
    void seriesReadsWithVtk()
    {
        const fs::path bundle = freshBundle("runs-pvd.vsim");
        const SolverRun heat = heatRun();
        std::string id;
        {
            Study study = Study::create(bundle, "Runs");
            id = study.addRun(heat, "Heat", {"simulate heat", {}, {}, "", ""});
            study.save();
        }
        const fs::path folder = bundle / "runs" / id;
        auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
        parser->SetFileName((folder / "series.pvd").c_str());
        QVERIFY(parser->Parse() == 1);
        vtkXMLDataElement* collection = parser->GetRootElement()->FindNestedElementWithName("Collection");
        QVERIFY(collection);
        QCOMPARE(std::size_t(collection->GetNumberOfNestedElements()), heat.frames.size());
        for (int e = 0; e < collection->GetNumberOfNestedElements(); ++e)
        {
            vtkXMLDataElement* dataSet = collection->GetNestedElement(e);
            double timestep = -1.0;
            QVERIFY(dataSet->GetScalarAttribute("timestep", timestep));
            QCOMPARE(timestep, heat.frames[std::size_t(e)].position);
            auto reader = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
            reader->SetFileName((folder / dataSet->GetAttribute("file")).c_str());
            reader->Update();
            vtkDataSet* data = vtkDataSet::SafeDownCast(reader->GetOutput());
            QVERIFY(data);
            QCOMPARE(data->GetNumberOfPoints(), vtkIdType(9 * 9 * 9));
            QVERIFY(data->GetPointData()->GetArray("temperature_rise_k"));
        }
    }

    void damagedFrameFlagsTheRun()
    {
        const fs::path bundle = freshBundle("runs-damaged.vsim");
        std::string id;
        {
            Study study = Study::create(bundle, "Runs");
            id = study.addRun(heatRun(), "Heat", {"simulate heat", {}, {}, "", ""});
            study.save();
        }
        const fs::path frame = bundle / "runs" / id / "frames" / "frame_000002.vti";
        QVERIFY(fs::exists(frame));
        {
            std::fstream stream(frame, std::ios::in | std::ios::out | std::ios::binary);
            stream.seekp(-20, std::ios::end);
            stream.put('#');
        }
        const Study study = Study::open(bundle, study::Access::ReadOnly);
        QVERIFY(study.artifact(id).damaged);
        QVERIFY2(study.artifact(id).damage.find("frame_000002.vti") != std::string::npos, study.artifact(id).damage.c_str());
        QVERIFY_THROWS_EXCEPTION(Error, study.loadRunFrame(id, 0));
    }

    void removeUndoAndSaveAs()
    {
        const fs::path bundle = freshBundle("runs-remove.vsim");
        Study study = Study::create(bundle, "Runs");
        const std::string id = study.addRun(heatRun(), "Heat", {"simulate heat", {}, {}, "", ""});
        study.save();
        const fs::path folder = bundle / "runs" / id;
        { std::ofstream(folder / "notes.txt") << "a radiologist's note"; }
        study.removeArtifact(id);
        study.save();
        QVERIFY(!fs::exists(folder / "run.json"));
        QVERIFY(!fs::exists(folder / "series.pvd"));
        QVERIFY(!fs::exists(folder / "frames"));
        QVERIFY(fs::exists(folder / "notes.txt")); // not ours: kept, and its folder with it
        study.restoreArtifact(id);
        study.save();
        QVERIFY(fs::exists(folder / "run.json"));
        QCOMPARE(study.loadRun(id, false).keptFrameNumbers, heatRun().keptFrameNumbers);

        const fs::path copy = freshBundle("runs-copy.vsim");
        study.saveAs(copy);
        const Study reopened = Study::open(copy, study::Access::ReadOnly);
        QVERIFY(reopened.openWarnings().empty());
        QVERIFY(!reopened.artifact(id).damaged);
        QCOMPARE(reopened.loadRun(id).frames.size(), heatRun().frames.size());
        QVERIFY(!fs::exists(copy / "runs" / id / "notes.txt"));
    }

    void runWithoutFramesIsRefused()
    {
        Study study = Study::create(freshBundle("runs-refused.vsim"), "Runs");
        SolverRun streamed = heatRun();
        streamed.frames.clear();
        QVERIFY_THROWS_EXCEPTION(Error, study.addRun(streamed, "Heat", {}));
    }
};

QTEST_GUILESS_MAIN(RunArtifact)
#include "tst_run_artifact.moc"
