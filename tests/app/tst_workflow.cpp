// The workflow dock as a checklist (issue 20, item 5): a single click runs a step; each step shows not run, done,
// or stale once an input changed since (a colour disc and a word; the tooltip names what was replaced); a click
// while a step runs is refused. The window opens at a sensible first size, not Qt's 640 x 480, and comes back at
// the size the user left. The user guide opens with both cases, its pictures and the key table. Small patient-like
// AAA phantom.
#include "DicomFixtures.h"
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "HelpWindow.h"
#include "WorkflowChecklist.h"

#include <QRegularExpression>
#include <QTextBrowser>

#include <QListWidget>

namespace fs = std::filesystem;
using namespace vsim;
using app::StepState;
using app::WorkflowStep;

namespace {

void clickStep(gui::WorkflowChecklist* list, WorkflowStep step)
{
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(list->itemOf(step)).center());
}

/// The colour at the centre of a step's state disc.
QColor discColour(gui::WorkflowChecklist* list, WorkflowStep step)
{
    return list->itemOf(step)->icon().pixmap(14, 14).toImage().pixelColor(7, 7);
}

} // namespace

class TestWorkflow : public QObject
{
    Q_OBJECT

private slots:
    void firstSizeAndRestoredGeometry()
    {
        {
            gui::MainWindow window;
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            qInfo("first window: %d x %d on a %d x %d screen", window.width(), window.height(),
                  window.screen()->availableGeometry().width(), window.screen()->availableGeometry().height());
            QVERIFY(window.width() >= 1200 && window.height() >= 800);
            QVERIFY(window.width() <= window.screen()->availableGeometry().width());
            window.resize(1300, 850);
            window.close();
        }
        gui::MainWindow again;
        again.show();
        QVERIFY(QTest::qWaitForWindowExposed(&again));
        QCOMPARE(again.size(), QSize(1300, 850));
    }

    // Help > User Guide: both cases walked through, every picture found, the keys the slice views take listed.
    void userGuide()
    {
        gui::MainWindow window;
        window.show();
        gui::HelpWindow* help = window.showHelp("keys");
        QVERIFY(help && help->isVisible());
        QTextDocument* guide = help->browser()->document();
        const QString text = guide->toPlainText();
        for (const char* expected : {"AAA review", "Chemoembolization planning", "Measurements", "Page Up", "Ctrl + wheel",
                                     "Middle drag", "Home / End", "W 1500 L -600", "stale", "Focus on Centre", "Deutsch"})
            QVERIFY2(text.contains(expected), expected);
        const QRegularExpression image("<img src=\"([^\"]+)\"");
        const QString html = guide->toHtml();
        int pictures = 0;
        for (auto match = image.globalMatch(html); match.hasNext(); ++pictures)
        {
            const QString source = match.next().captured(1);
            const QVariant resource = guide->resource(QTextDocument::ImageResource, QUrl(source));
            QVERIFY2(resource.isValid() && !resource.value<QImage>().isNull(), qPrintable(source));
        }
        qInfo("user guide: %lld characters, %d pictures", qlonglong(text.size()), pictures);
        QVERIFY(pictures >= 9);
    }

    void singleClicksAndStates()
    {
        const fs::path folder = test::freshFolder("gui-workflow", "aaa");
        test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        gui::MainWindow window;
        window.show();
        auto* list = window.findChild<gui::WorkflowChecklist*>("workflow");
        QVERIFY(list);
        for (WorkflowStep step : app::kWorkflowSteps)
            QCOMPARE(list->state(step), StepState::NotRun);
        const fs::path bundle = test::freshFolder("gui-workflow", "study") / "workflow.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(test::waitForTask(window));
        QCOMPARE(list->state(WorkflowStep::Import), StepState::Done);
        QCOMPARE(list->state(WorkflowStep::Segment), StepState::NotRun);
        QCOMPARE(list->itemOf(WorkflowStep::Centerlines)->text(), QString("Skeleton & Centerlines"));

        clickStep(list, WorkflowStep::Segment); // one click, no double-click
        clickStep(list, WorkflowStep::Centerlines); // refused while the segmentation runs
        QVERIFY(test::waitForTask(window));
        QCOMPARE(list->state(WorkflowStep::Segment), StepState::Done);
        QCOMPARE(list->state(WorkflowStep::Centerlines), StepState::NotRun);
        const QColor done = discColour(list, WorkflowStep::Segment);
        QVERIFY2(done.green() > done.red() + 60, qPrintable(done.name()));

        clickStep(list, WorkflowStep::Centerlines);
        QVERIFY(test::waitForTask(window));
        QCOMPARE(list->state(WorkflowStep::Centerlines), StepState::Done);
        QVERIFY(list->itemOf(WorkflowStep::Centerlines)->text().endsWith("(done)"));

        // Segmenting again replaces the label the centerlines were made from: they are stale.
        clickStep(list, WorkflowStep::Segment);
        QVERIFY(test::waitForTask(window));
        QCOMPARE(list->state(WorkflowStep::Centerlines), StepState::Stale);
        QVERIFY(list->itemOf(WorkflowStep::Centerlines)->text().endsWith("(stale)"));
        QVERIFY(list->itemOf(WorkflowStep::Centerlines)->toolTip().contains("replaced since"));
        const QColor stale = discColour(list, WorkflowStep::Centerlines);
        QVERIFY2(stale.red() > stale.blue() + 100 && stale.green() > stale.blue(), qPrintable(stale.name()));
        clickStep(list, WorkflowStep::Centerlines);
        QVERIFY(test::waitForTask(window));
        QCOMPARE(list->state(WorkflowStep::Centerlines), StepState::Done);
        QCOMPARE(list->state(WorkflowStep::WallMesh), StepState::NotRun);
    }
};

VSIM_GUI_TEST_MAIN(TestWorkflow)
#include "tst_workflow.moc"
