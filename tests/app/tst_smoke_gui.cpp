// Flow > Surgical Smoke in the workstation (issue 21): on a small imported phantom, the menu offers the three
// scenarios; the EVH tunnel is refused without centerlines, with the reason; the thesis's ball drop runs in the
// background, its run is kept in the study with the endoscope's obscuration and played (the smoke density frame by
// frame).

#include "DicomFixtures.h"
#include "GuiTestMain.h"
#include "MainWindow.h"
#include "RunPlayer.h"
#include "TestOutput.h"
#include "ViewLayout.h"
#include "vsim/viz/VolumeView3D.h"

#include <QMenu>
#include <QStatusBar>

#include <cmath>

namespace fs = std::filesystem;
using namespace vsim;

class TestSmokeGui : public QObject
{
    Q_OBJECT
private slots:
    void ballDropRunsAndPlays()
    {
        const fs::path folder = test::freshFolder("gui-smoke", "aaa");
        test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        gui::MainWindow window;
        window.resize(1400, 900);
        window.show();
        QVERIFY(window.newStudy(QString::fromStdString((test::freshFolder("gui-smoke", "study") / "smoke.vsim").string())));
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())) && test::waitForTask(window));

        const QMenu* menu = window.findChild<QMenu*>("smokeMenu");
        QVERIFY(menu);
        QCOMPARE(menu->actions().size(), 5); // three scenarios, a separator, the parameters
        // The form's values are what a run uses: a shorter ball drop.
        window.smokeParameters("ball-drop").set("end_time_s", 2.0);
        QVERIFY(menu->menuAction()->isEnabled());

        QVERIFY(!window.simulateSmoke("evh")); // no centerlines yet
        QVERIFY2(window.statusBar()->currentMessage().contains("failed"), qPrintable(window.statusBar()->currentMessage()));

        QVERIFY(window.simulateSmoke("ball-drop") && test::waitForTask(window, 120000));
        const study::Study& study = window.document().study();
        const std::string runId = study.newestArtifact(study::ArtifactKind::Run, "simulate smoke");
        QVERIFY(!runId.empty());
        QVERIFY(study.artifact(runId).attributes.count("obscuration_curve"));
        // The player opens when the run is kept and reads the frames in the background.
        QTRY_VERIFY_WITH_TIMEOUT(window.runPlayer() && window.runPlayer()->frameCount() >= 10, 60000);
        QCOMPARE(window.runPlayer()->field(), QString("smoke_density_mg_m3"));
        QVERIFY2(std::abs(window.runPlayer()->positions().back() - 2.0) < 1e-6, "the run ends at the form's 2 s");
        QVERIFY(study.artifact(runId).attributes.count("peak_obscured_fraction"));
        // The 3D view volume-renders the density with its legend; closing the run takes it away.
        QTRY_VERIFY_WITH_TIMEOUT(window.views()->volumeView()->hasFieldVolume(), 20000);
        QVERIFY2(window.views()->volumeView()->legendTitle().contains("smoke density (mg/m"),
                 qPrintable(window.views()->volumeView()->legendTitle()));
        window.runPlayer()->setFrame(window.runPlayer()->frameCount() - 1);
        QVERIFY(window.views()->volumeView()->hasFieldVolume());
        window.grab().save(test::outputFolder("gui") + "/smoke-ball-drop-volume.png");
    }
};

VSIM_GUI_TEST_MAIN(TestSmokeGui)
#include "tst_smoke_gui.moc"
