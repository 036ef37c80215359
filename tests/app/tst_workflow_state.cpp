// The workflow checklist's states (app/common WorkflowState.h) on a study built step by step with known
// provenance: not run, done, stale when an input (or an input's input) has been replaced since, and an edit of a
// label that does not make itself stale. And the default file names that survive other systems (FileLocations.h).
#include "FileLocations.h"
#include "StudyFixtures.h"
#include "TestOutput.h"
#include "vsim/app/WorkflowState.h"
#include "vsim/study/Study.h"

#include <QtTest>

#include <filesystem>

using namespace vsim;
using app::StepState;
using app::WorkflowStep;

namespace {

study::Provenance made(const std::string& command, std::vector<std::string> inputs)
{
    study::Provenance provenance;
    provenance.command = command;
    provenance.inputs = std::move(inputs);
    return provenance;
}

} // namespace

class TestWorkflowState : public QObject
{
    Q_OBJECT

private slots:
    void statesFollowTheProvenance()
    {
        const std::filesystem::path bundle = std::filesystem::path(test::outputFolder("workflow-state").toStdString()) / "steps.vsim";
        std::filesystem::remove_all(bundle); // this suite's own output from an earlier run
        study::Study study = study::Study::create(bundle, "steps");
        for (WorkflowStep step : app::kWorkflowSteps)
            QCOMPARE(app::stepStatus(study, step).state, StepState::NotRun);

        const CtVolume image = test::patternedVolume(8, 3);
        LabelVolume label(image.geometry());
        const std::string ct = study.addImage(image, "CTA", made("import dicom", {"/data/series"}));
        const std::string lumen = study.addLabel(label, "Lumen", made("segment", {ct}));
        QCOMPARE(app::stepStatus(study, WorkflowStep::Import).state, StepState::Done);
        QCOMPARE(app::stepStatus(study, WorkflowStep::Segment).state, StepState::Done);
        QCOMPARE(app::stepStatus(study, WorkflowStep::Segment).artifactId, lumen);

        // A brush edit takes the lumen as input: the edit is the step's result and is current.
        const std::string edited = study.addLabel(label, "Lumen (edited)", made("edit-label", {lumen}));
        QCOMPARE(app::stepStatus(study, WorkflowStep::Segment).artifactId, edited);
        QCOMPARE(app::stepStatus(study, WorkflowStep::Segment).state, StepState::Done);
        QCOMPARE(app::supersededBy(study, lumen), edited);

        // Centerlines of the edit, and a wall mesh of those: done; a new segmentation then makes both stale (the
        // mesh through its input's input), naming what was replaced and by what.
        const std::string centerlines = study.addLabel(label, "Centerlines (stand-in)", made("centerline", {edited}));
        const std::string mesh = study.addLabel(label, "Wall mesh (stand-in)", made("mesh wall", {centerlines}));
        QCOMPARE(app::stepStatus(study, WorkflowStep::Centerlines).state, StepState::Done);
        QCOMPARE(app::stepStatus(study, WorkflowStep::WallMesh).state, StepState::Done);
        const std::string again = study.addLabel(label, "Lumen again", made("segment", {ct}));
        const app::StepStatus stale = app::stepStatus(study, WorkflowStep::Centerlines);
        QCOMPARE(stale.state, StepState::Stale);
        QCOMPARE(stale.supersededInput, lumen);
        QCOMPARE(stale.supersededBy, again);
        QCOMPARE(app::stepStatus(study, WorkflowStep::WallMesh).state, StepState::Stale);
        QCOMPARE(app::stepStatus(study, WorkflowStep::Segment).state, StepState::Done);
        QCOMPARE(app::stepStatus(study, WorkflowStep::WallStress).state, StepState::NotRun);

        // Running the steps again makes them current; a report of a run goes stale when a newer run is made.
        const std::string centerlines2 = study.addLabel(label, "Centerlines 2", made("centerline", {again}));
        QCOMPARE(app::stepStatus(study, WorkflowStep::Centerlines).state, StepState::Done);
        QCOMPARE(app::stepStatus(study, WorkflowStep::WallMesh).state, StepState::Stale);
        const std::string run = study.addLabel(label, "Flow run (stand-in)", made("simulate sph", {centerlines2}));
        study.addReport("%PDF-1.4 stand-in", "Report", made("report", {run}));
        QCOMPARE(app::stepStatus(study, WorkflowStep::Report).state, StepState::Done);
        study.addLabel(label, "Flow run 2", made("simulate sph", {centerlines2}));
        QCOMPARE(app::stepStatus(study, WorkflowStep::Report).state, StepState::Stale);
        QCOMPARE(app::stepStatus(study, WorkflowStep::Flow).state, StepState::Done);
        Q_UNUSED(mesh);
    }

    void portableDefaultNames()
    {
        QCOMPARE(gui::portableFileName("Demo: AAA report 2026-11-29"), QString("Demo- AAA report 2026-11-29"));
        QCOMPARE(gui::portableFileName("a/b\\c*d?e\"f<g>h|i"), QString("a-b-c-d-e-f-g-h-i"));
        QCOMPARE(gui::portableFileName(" ..hidden. "), QString("hidden"));
        QCOMPARE(gui::portableFileName(":::"), QString("-"));
        QCOMPARE(gui::portableFileName(""), QString("untitled"));
        QCOMPARE(gui::portableFileName(QString::fromUtf8("张三 报告")), QString::fromUtf8("张三 报告"));
    }
};

QTEST_GUILESS_MAIN(TestWorkflowState)
#include "tst_workflow_state.moc"
