// Measurement tools from the workstation (issue 20, item 2): a ruler dragged, an angle clicked and an ROI
// dragged on the slice views of the marker phantom become measurement artifacts with the figures their points
// give (ruler and angle to 0.01, the ROI inside the 3000 HU block exactly 3000 HU), drawn (cyan pixels) only
// in the view and slice they were drawn in, undoable, kept when the study is saved and reopened, and listed
// in the report's measurements section once marked; a double-click in the study tree goes to one.
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "MarkerPhantom.h"
#include "PixelChecks.h"
#include "SliceMouse.h"
#include "TestOutput.h"
#include "ViewLayout.h"
#include "vsim/app/StudyReport.h"
#include "vsim/study/Study.h"
#include "vsim/viz/SliceView.h"

#include <QAction>
#include <QTreeWidget>

#include <filesystem>
#include <variant>

using namespace vsim;
using viz::SliceOrientation;

class TestMeasure : public QObject
{
    Q_OBJECT

    std::filesystem::path m_bundle;
    test::Phantom m_phantom = test::markerPhantom();

    QAction* action(gui::MainWindow& window, const char* name) { return window.findChild<QAction*>(name); }

private slots:
    void measureUndoSaveReopenReport()
    {
        m_bundle = std::filesystem::path(test::outputFolder("gui-measure").toStdString()) / "measure.vsim";
        std::filesystem::remove_all(m_bundle);
        {
            study::Study study = study::Study::create(m_bundle, "measure");
            study.addImage(m_phantom.image, "marker CT", {"import volume", {}, {}, "", ""});
            study.save();
        }
        auto* window = new gui::MainWindow();
        window->resize(1200, 900);
        window->show();
        QVERIFY(QTest::qWaitForWindowExposed(window));
        QVERIFY(window->openStudy(QString::fromStdString(m_bundle.string())));
        QVERIFY(test::waitForTask(*window));
        window->views()->jumpTo(m_phantom.marker);
        viz::SliceView* axial = window->views()->sliceView(SliceOrientation::Axial);
        viz::SliceView* coronal = window->views()->sliceView(SliceOrientation::Coronal);
        const study::Study& study = window->document().study();
        const std::size_t before = study.artifacts().size();
        const int cyanBefore = test::cyanPixels(axial->grabFramebuffer());

        // A ruler 30 mm along x and 40 mm along y in the axial plane: 50 mm.
        action(*window, "measureRulerAction")->trigger();
        QCOMPARE(axial->measureTool(), viz::MeasureTool::Ruler);
        const Eigen::Vector3d a = m_phantom.marker + Eigen::Vector3d(-15.0, -20.0, 0.0),
                              b = a + Eigen::Vector3d(30.0, 40.0, 0.0);
        test::sliceDrag(axial, a, b);
        QCOMPARE(study.artifacts().size(), before + 1);
        const study::Artifact ruler = study.artifacts().back();
        QCOMPARE(ruler.kind, study::ArtifactKind::Measurement);
        QVERIFY(std::abs(study.loadMeasurement(ruler.id).lengthMm - 50.0) < 0.01);
        QCOMPARE(ruler.name, std::string("Ruler 1: 50.0 mm"));
        QCOMPARE(axial->cursor(), m_phantom.marker); // the tool has the left button, not the cursor
        QCOMPARE(axial->shownMeasurementCount(), 1);
        QCOMPARE(coronal->shownMeasurementCount(), 0); // drawn in another plane
        const QImage drawn = axial->grabFramebuffer();
        drawn.save(test::outputFolder("gui-measure") + "/ruler.png");
        const int cyan = test::cyanPixels(drawn) - cyanBefore;
        qInfo("the ruler: %d cyan pixels for a line of %.0f pixels", cyan,
              50.0 / (axial->fieldOfView() / axial->height()));
        QVERIFY(cyan > 0.8 * 50.0 / (axial->fieldOfView() / axial->height()));
        axial->stepSlices(2);
        QCOMPARE(axial->shownMeasurementCount(), 0); // 3 mm away from its slice
        axial->stepSlices(-2);

        // An angle of 60 degrees, clicked; an ROI inside the block.
        action(*window, "measureAngleAction")->trigger();
        QCOMPARE(axial->measureTool(), viz::MeasureTool::Angle);
        const Eigen::Vector3d vertex = m_phantom.marker + Eigen::Vector3d(10.0, 10.0, 0.0);
        test::sliceClick(axial, vertex + Eigen::Vector3d(20.0, 0.0, 0.0));
        test::sliceClick(axial, vertex);
        QCOMPARE(study.artifacts().size(), before + 1); // not finished
        test::sliceClick(axial,
                         vertex + 20.0 * Eigen::Vector3d(std::cos(M_PI / 3.0), std::sin(M_PI / 3.0), 0.0));
        QCOMPARE(study.artifacts().size(), before + 2);
        QVERIFY(std::abs(study.loadMeasurement(study.artifacts().back().id).angleDegrees - 60.0) < 0.01);
        action(*window, "measureRoiAction")->trigger();
        test::sliceDrag(axial, m_phantom.marker - Eigen::Vector3d(1.2, 1.2, 0.0),
                        m_phantom.marker + Eigen::Vector3d(1.2, 1.2, 0.0));
        QCOMPARE(study.artifacts().size(), before + 3);
        const ViewMeasurement roi = study.loadMeasurement(study.artifacts().back().id);
        QCOMPARE(roi.meanHu, double(test::kMarkerHu));
        QCOMPARE(roi.sdHu, 0.0);
        action(*window, "measureRoiAction")->trigger(); // a second click puts the tool down
        QCOMPARE(axial->measureTool(), viz::MeasureTool::Off);

        // Undo takes the ROI away (and out of the views), redo brings it back.
        window->document().undoStack()->undo();
        QCOMPARE(study.artifacts().size(), before + 2);
        window->document().undoStack()->redo();
        QCOMPARE(study.artifacts().size(), before + 3);
        QCOMPARE(axial->shownMeasurementCount(), 3);

        // Marked for the report (undoable), then saved.
        auto* tree = window->findChild<QTreeWidget*>("artifactTree");
        for (int i = 0; i < tree->topLevelItemCount(); ++i)
            if (tree->topLevelItem(i)->data(0, Qt::UserRole).toString().toStdString() == ruler.id)
                tree->setCurrentItem(tree->topLevelItem(i));
        QAction* inReport = action(*window, "measurementInReportAction");
        QVERIFY(inReport->isEnabled());
        inReport->trigger();
        QCOMPARE(study.artifact(ruler.id).attributes.at("in_report"), std::string("1"));
        window->document().undoStack()->undo();
        QVERIFY(!study.artifact(ruler.id).attributes.count("in_report")); // as before the mark
        window->document().undoStack()->redo();
        QVERIFY(window->saveStudy());
        QVERIFY(test::waitForTask(*window));
        window->close();

        // Reopened: the three measurements are there and drawn; the report lists the marked ruler only.
        auto* again = new gui::MainWindow();
        again->resize(1200, 900);
        again->show();
        QVERIFY(again->openStudy(QString::fromStdString(m_bundle.string())));
        QVERIFY(test::waitForTask(*again));
        again->views()->jumpTo(m_phantom.marker);
        QCOMPARE(again->views()->sliceView(SliceOrientation::Axial)->shownMeasurementCount(), 3);
        // A double-click on the ruler in the study tree goes to it: the cursor at its middle.
        auto* againTree = again->findChild<QTreeWidget*>("artifactTree");
        for (int i = 0; i < againTree->topLevelItemCount(); ++i)
            if (againTree->topLevelItem(i)->data(0, Qt::UserRole).toString().toStdString() == ruler.id)
                emit againTree->itemDoubleClicked(againTree->topLevelItem(i), 0);
        QVERIFY((again->views()->sliceView(SliceOrientation::Axial)->cursor() - 0.5 * (a + b)).norm() < 1e-9);
        const report::Report report = app::buildStudyReport(again->document().study(), {});
        const auto section = std::find_if(report.sections.begin(), report.sections.end(),
                                          [](const report::Section& s) { return s.id == "measurements"; });
        QVERIFY(section != report.sections.end());
        const auto& table = std::get<report::Table>(section->blocks.front());
        QCOMPARE(table.rows.size(), std::size_t(1));
        QCOMPARE(table.rows[0][0], std::string("Ruler 1"));
        QCOMPARE(table.rows[0][1], std::string("50.0 mm"));
        again->close();
    }
};

VSIM_GUI_TEST_MAIN(TestMeasure)
#include "tst_measure.moc"
