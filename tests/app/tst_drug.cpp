// The drug-delivery step from the workstation: on an imported hepatic-tree phantom (1.2 mm voxels), Segment and
// Skeleton & Centerlines, then Drug > Drug Delivery from the root with the phantom's tumour in the background: the
// solved network is added (undoable, with provenance and metrics), the 3D view colours the tree by drug flow with
// its legend, the Drug Delivery dock lists the outlets, and moving the filling player draws virtual tubelets in
// the 3D view and the 2D projection; File > Export Report writes the PDF, the DICOM instance and the metrics.
// Then chemoembolization planning (issue 19): a liver and a tumour label imported, chosen in the dock, Run: the
// perfused territory over the MPR views (the territory palette) with the tip, the lesion and its feeders as
// markers, the coverage grade in the dock and the study. A drug run replaces the one before unless kept (undo
// brings it back). Malformed input and a study without centerlines are
// refused with a message.

#include "DicomFixtures.h"
#include "DrugDeliveryPanel.h"
#include "GuiTestMain.h"
#include "Languages.h"
#include "MainWindow.h"
#include "RunPlayer.h"
#include "SegmentationPointsPanel.h"
#include "NetworkProjectionView.h"
#include "ViewLayout.h"
#include "vsim/dicom/PhantomModel.h"
#include "vsim/interop/NrrdFile.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QTextBrowser>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTableWidget>

#include <algorithm>
#include <fstream>

namespace fs = std::filesystem;
using namespace vsim;

class TestDrug : public QObject
{
    Q_OBJECT

private slots:
    void drugDeliveryFromTheWorkstation()
    {
        dicom::PhantomOptions options;
        options.size = {240, 240, 150};
        options.spacing = {1.2, 1.2, 1.5};
        options.seed = 3;
        const fs::path folder = test::freshFolder("gui-drug", "hepatic");
        test::writePhantomSeries(dicom::PhantomKind::HepaticTree, options, folder);
        const dicom::PhantomModel model = dicom::buildPhantomModel(dicom::PhantomKind::HepaticTree, options);
        gui::MainWindow window;
        window.resize(1400, 900);
        window.show();
        const fs::path bundle = test::freshFolder("gui-drug", "study") / "drug.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QSignalSpy failed(&window.tasks(), &gui::TaskRunner::failed);
        QVERIFY(!window.simulateDrugDelivery({})); // no centerlines yet: says so, adds nothing
        QVERIFY(vsim::test::runVesselSteps(window, folder.string()));
        QVERIFY(!window.simulateDrugDelivery({"1, 2", "", ""})); // malformed tip

        const auto& m = model.measures;
        const QString tumour = QString("%1, %2, %3, %4")
                                   .arg(m.at("tumour_centre_x_mm"))
                                   .arg(m.at("tumour_centre_y_mm"))
                                   .arg(m.at("tumour_centre_z_mm"))
                                   .arg(m.at("tumour_radius_mm"));
        QVERIFY(window.simulateDrugDelivery({"", tumour, ""}));
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 0);
        const study::Artifact run = window.document().study().artifacts().back();
        QCOMPARE(run.kind, study::ArtifactKind::Network);
        QCOMPARE(run.provenance.command, std::string("simulate network"));
        QVERIFY(std::stod(run.attributes.at("conservation_error")) <= 1e-12);
        // Issue 17: the filling over time is kept beside the network as a Run of 101 frames.
        const SolverRun filling = window.document().study().loadRun(run.attributes.at("run_artifact"), false);
        QCOMPARE(filling.keptFrameNumbers.size(), std::size_t(101));
        QCOMPARE(filling.axis.unit, std::string("s"));
        QCOMPARE(window.views()->volumeView()->legendTitle(), QString("Drug flow (ml/min; grey: none)"));
        QCOMPARE(window.views()->volumeView()->volumeStyle(), viz::VolumeView3D::VolumeStyle::MaximumIntensity); // the tree over the MIP
        gui::DrugDeliveryPanel* panel = window.drugDeliveryPanel();
        QVERIFY(panel);
        const int outlets = panel->outletTable()->rowCount();
        qInfo("GUI drug delivery: %d outlets, tumour share %s, last outlet after %s s", outlets,
              run.attributes.at("tumour_fraction").c_str(), run.attributes.at("last_arrival_s").c_str());
        QVERIFY(outlets >= 4);

        // The filling player: half-way, tracers trail tubelets in both views; at the start there are none.
        QCOMPARE(window.views()->volumeView()->tubeletQuadCount(), 0);
        panel->player()->setFrame(panel->player()->frameCount() / 2);
        QVERIFY(panel->currentTimeS() > 0.0);
        QVERIFY(window.views()->volumeView()->tubeletQuadCount() > 0);
        QVERIFY(panel->projection()->trailCount() > 0);
        window.grab().save(QString::fromStdString((test::freshFolder("gui-drug", "screenshot") / "drug.png").string()));
        panel->player()->setFrame(panel->player()->frameCount() * 19 / 20);
        panel->player()->play(); // the workstation's one time player
        QTRY_VERIFY_WITH_TIMEOUT(panel->player()->frame() == panel->player()->frameCount() - 1, 30000);
        QVERIFY(!panel->player()->isPlaying());

        // The best tip position picked on the tree in the 3D view, then Run from the dock: the tumour gets more.
        const double first = std::stod(run.attributes.at("tumour_fraction"));
        const Eigen::Vector3d best(std::stod(run.attributes.at("best_tip_x_mm")), std::stod(run.attributes.at("best_tip_y_mm")),
                                   std::stod(run.attributes.at("best_tip_z_mm")));
        panel->startPicking(gui::DrugDeliveryPanel::Pick::Tip);
        QVERIFY(window.views()->volumeView()->isPickEnabled());
        emit window.views()->volumeView()->pointPicked(best);
        QVERIFY(!window.views()->volumeView()->isPickEnabled());
        QVERIFY(!panel->request().tip.isEmpty());
        panel->findChild<QPushButton*>("drugRun")->click();
        QVERIFY(vsim::test::waitForTask(window));
        for (const QList<QVariant>& failure : failed)
            qWarning("the run from the picked tip failed: %s", qPrintable(failure.value(1).toString()));
        QCOMPARE(failed.count(), 0);
        const study::Artifact picked = window.document().study().artifacts().back();
        QVERIFY(!window.document().study().hasArtifact(run.id)); // one drug run replaces the one before
        QCOMPARE(QString::fromStdString(picked.provenance.parameters.at("tip")), panel->request().tip);
        qInfo("tumour share from the root %.3f, from the picked best tip %s", first, picked.attributes.at("tumour_fraction").c_str());
        QVERIFY(std::stod(picked.attributes.at("tumour_fraction")) > first);
        // The working C-arm angle for the path to the picked tip, in the dock (the projection is drawn at it).
        qInfo("working angle LAO %s, cranial %s: overlap %s %% (front %s %%), foreshortening %s %% (front %s %%)",
              picked.attributes.at("working_lao_deg").c_str(), picked.attributes.at("working_cranial_deg").c_str(),
              picked.attributes.at("working_overlap_percent").c_str(), picked.attributes.at("frontal_overlap_percent").c_str(),
              picked.attributes.at("working_foreshortening_percent").c_str(),
              picked.attributes.at("frontal_foreshortening_percent").c_str());
        QVERIFY(std::abs(std::stod(picked.attributes.at("working_lao_deg"))) <= 60.0);
        QVERIFY(std::stod(picked.attributes.at("working_overlap_percent")) + std::stod(picked.attributes.at("working_foreshortening_percent")) <=
                std::stod(picked.attributes.at("frontal_overlap_percent")) + std::stod(picked.attributes.at("frontal_foreshortening_percent")));
        QVERIFY(panel->findChild<QTextBrowser*>("drugSummary")->toPlainText().contains("Working angle"));
        panel->findChild<QCheckBox*>("drugDsa")->setChecked(true); // the DSA-like view at that angle
        QVERIFY(panel->projection()->showsDsa());
        panel->findChild<QCheckBox*>("drugDsa")->setChecked(false);

        // File > Export Report in the background, the tree's snapshot rendered on the GUI thread: the PDF with the
        // chemoembolization section, the DICOM instance and the metrics beside it.
        const fs::path reports = test::freshFolder("gui-drug", "report");
        const QString pdf = QString::fromStdString((reports / "drug.pdf").string());
        QVERIFY(window.exportReport({pdf, report::PageSize::Letter, false, true, true}));
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 0);
        QFile written(pdf);
        QVERIFY(written.open(QIODevice::ReadOnly));
        const QByteArray bytes = written.readAll();
        QVERIFY(bytes.startsWith("%PDF"));
        QVERIFY2(bytes.size() > 50000, "the PDF holds the tree's snapshot"); // text alone is about 40 kB
        QVERIFY(fs::exists(reports / "drug.dcm"));
        QVERIFY(fs::exists(reports / "drug-metrics.csv") && fs::exists(reports / "drug-metrics.json"));
        std::ifstream metrics(reports / "drug-metrics.json");
        const std::string text((std::istreambuf_iterator<char>(metrics)), std::istreambuf_iterator<char>());
        QVERIFY(text.find("\"tumour_fraction\"") != std::string::npos);
        const study::Artifact kept = window.document().study().artifacts().back(); // the report is in the study too
        QCOMPARE(kept.kind, study::ArtifactKind::Report);
        QCOMPARE(window.document().study().loadReport(kept.id), std::string(bytes.constData(), std::size_t(bytes.size())));
        QVERIFY(std::find(kept.provenance.inputs.begin(), kept.provenance.inputs.end(), picked.id) != kept.provenance.inputs.end());
        window.document().undoStack()->undo();
        QVERIFY(!window.document().study().hasArtifact(kept.id));

        // The liver (here the box around the tree, 10 mm beyond its nodes) and the tumour (the phantom's sphere) as
        // labels on the CT's grid, imported; chosen in the dock; Run from the root.
        const VolumeGeometry grid = dicom::phantomGeometry(options);
        Eigen::Vector3d lower = model.nodes.front().position, upper = lower;
        for (const dicom::VesselNode& node : model.nodes)
            lower = lower.cwiseMin(node.position), upper = upper.cwiseMax(node.position);
        const Eigen::Vector3d centre(m.at("tumour_centre_x_mm"), m.at("tumour_centre_y_mm"), m.at("tumour_centre_z_mm"));
        LabelVolume liverLabel(grid), tumourLabel(grid);
        for (int k = 0; k < grid.dims[2]; ++k)
            for (int j = 0; j < grid.dims[1]; ++j)
                for (int i = 0; i < grid.dims[0]; ++i)
                {
                    const Eigen::Vector3d p = grid.indexToPatient(Eigen::Vector3d(i, j, k));
                    liverLabel.at(i, j, k) = (p.array() >= lower.array() - 10.0).all() && (p.array() <= upper.array() + 10.0).all();
                    tumourLabel.at(i, j, k) = (p - centre).norm() <= m.at("tumour_radius_mm");
                }
        // Drug > Liver from Points: refused without points, then grown from an include point in the tissue.
        QVERIFY(!window.growLiverFromPoints());
        QVERIFY(!window.growTumourFromPoints());
        window.showSegmentationPoints();
        window.segmentationPointsPanel()->addPoint(grid.indexToPatient(Eigen::Vector3d(120, 120, 75)), true);
        QVERIFY(window.growLiverFromPoints());
        QVERIFY(vsim::test::waitForTask(window));
        const study::Artifact grownLiver = window.document().study().artifacts().back();
        QCOMPARE(grownLiver.kind, study::ArtifactKind::Label);
        QCOMPARE(grownLiver.provenance.command, std::string("segment-organ"));
        qInfo("liver from points: %s", grownLiver.name.c_str());
        window.document().undoStack()->undo();
        QVERIFY(!window.document().study().hasArtifact(grownLiver.id));
        const fs::path labels = test::freshFolder("gui-drug", "labels");
        interop::writeNrrd(liverLabel, labels / "liver.nrrd", true);
        interop::writeNrrd(tumourLabel, labels / "tumour.nrrd", true);
        for (const char* name : {"liver.nrrd", "tumour.nrrd"})
        {
            QVERIFY(window.importLabel(QString::fromStdString((labels / name).string())));
            QVERIFY(vsim::test::waitForTask(window));
        }
        const auto& artifacts = window.document().study().artifacts();
        const std::string liverId = artifacts[artifacts.size() - 2].id, tumourId = artifacts.back().id;
        panel->setLabelChoices({{QString::fromStdString(liverId), "liver"}, {QString::fromStdString(tumourId), "tumour"}});
        auto* liverBox = panel->findChild<QComboBox*>("drugLiverLabel");
        auto* tumourBox = panel->findChild<QComboBox*>("drugTumourLabel");
        liverBox->setCurrentIndex(liverBox->findData(QString::fromStdString(liverId)));
        tumourBox->setCurrentIndex(tumourBox->findData(QString::fromStdString(tumourId)));
        // Drug > Tumour from Points: refused before a liver label is chosen (above, it is), then a lesion grown within
        // it from one point at the tumour's centre; its overlap with the phantom's tumour sphere reported.
        {
            imaging::SegmentationRequest points;
            points.includeMm = {centre};
            window.segmentationPointsPanel()->setRequest(points);
            QVERIFY(window.growTumourFromPoints());
            QVERIFY(vsim::test::waitForTask(window));
            const study::Artifact grownTumour = window.document().study().artifacts().back();
            QCOMPARE(grownTumour.provenance.parameters.at("organ"), std::string("tumour"));
            QCOMPARE(grownTumour.provenance.inputs.back(), liverId);
            const LabelVolume lesion = window.document().study().loadLabel(grownTumour.id);
            double both = 0, label = 0, truth = 0;
            for (std::size_t n = 0; n < grid.voxelCount(); ++n)
                both += lesion.data()[n] && tumourLabel.data()[n], label += lesion.data()[n] != 0, truth += tumourLabel.data()[n] != 0;
            qInfo("tumour from one point: %s, Dice %.3f against the phantom's tumour sphere", grownTumour.name.c_str(),
                  2.0 * both / (label + truth));
            QVERIFY(2.0 * both / (label + truth) >= 0.7);
            window.document().undoStack()->undo();
            QVERIFY(!window.document().study().hasArtifact(grownTumour.id));
        }
        panel->findChild<QLineEdit*>("drugTip")->clear(); // from the root
        panel->findChild<QCheckBox*>("drugKeep")->setChecked(true); // the picked run stays beside it
        panel->findChild<QPushButton*>("drugRun")->click();
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 0);
        const study::Artifact planned = window.document().study().artifacts().back();
        QVERIFY(window.document().study().hasArtifact(picked.id));
        QVERIFY(!panel->keepsRun()); // cleared by the run
        QCOMPARE(planned.provenance.parameters.at("liver_label"), liverId);
        qInfo("chemoembolization from the root: grade %s, territory %s ml, %s feeder(s), lesion %s mm; best tip grade %s",
              planned.attributes.at("coverage_grade").c_str(), planned.attributes.at("perfused_volume_ml").c_str(),
              planned.attributes.at("feeders").c_str(), planned.attributes.at("lesion_1_diameter_mm").c_str(),
              planned.attributes.at("best_tip_grade").c_str());
        QCOMPARE(std::stod(planned.attributes.at("coverage_grade")), 1.0); // A from the root
        QVERIFY(std::stod(planned.attributes.at("feeders")) >= 1.0);
        viz::SliceView* axial = window.views()->sliceView(viz::SliceOrientation::Axial);
        QVERIFY(axial->hasLabel());
        QCOMPARE(axial->labelPalette(), viz::SliceView::LabelPalette::Territory);
        const auto& markers = axial->markers();
        QVERIFY(std::count_if(markers.begin(), markers.end(), [](const viz::SliceMarker& k) { return k.text.rfind("feeder", 0) == 0; }) >= 1);
        QVERIFY(panel->findChild<QTextBrowser*>("drugSummary")->toPlainText().contains("Coverage grade A"));
        window.grab().save(QString::fromStdString((test::freshFolder("gui-drug", "territory") / "territory.png").string()));
        // The German and Chinese guides' territory picture: the study saved, copied (its lock stays with this
        // window) and opened in a window of each language, which shows the newest drug run with its territory.
        QVERIFY(window.saveStudy());
        QVERIFY(vsim::test::waitForTask(window));
        const fs::path copy = test::freshFolder("gui-drug", "study-copy") / "drug.vsim";
        fs::copy(bundle, copy, fs::copy_options::recursive);
        for (const QString language : {"de", "zh_CN"})
        {
            QVERIFY(gui::installLanguage(language));
            {
                gui::MainWindow translated;
                translated.resize(1400, 900);
                translated.show();
                QVERIFY(QTest::qWaitForWindowExposed(&translated));
                QVERIFY(translated.openStudy(QString::fromStdString(copy.string())));
                QVERIFY(vsim::test::waitForTask(translated));
                QVERIFY(translated.grab().save(QString::fromStdString(
                    (test::freshFolder("gui-drug", "territory-" + language) / "territory.png").string())));
                QCOMPARE(translated.views()->sliceView(viz::SliceOrientation::Axial)->labelPalette(),
                         viz::SliceView::LabelPalette::Territory);
            }
            gui::installLanguage("en");
        }

        // Feeders corrected by hand: the first one found unticked in the dock's table, a segment that is none typed
        // in; the next run lists them so, records the edits and replaces the run it corrects.
        QTableWidget* feederTable = panel->feederTable();
        QCOMPARE(feederTable->rowCount(), int(std::stod(planned.attributes.at("feeders"))));
        const int removedFeeder = feederTable->item(0, 0)->data(Qt::UserRole).toInt();
        feederTable->item(0, 0)->setCheckState(Qt::Unchecked);
        QCOMPARE(panel->findChild<QLineEdit*>("drugFeedersRemoved")->text(), QString::number(removedFeeder));
        int addedFeeder = 0;
        for (int row = 0; row < feederTable->rowCount(); ++row)
            if (feederTable->item(row, 0)->data(Qt::UserRole).toInt() == addedFeeder)
                ++addedFeeder, row = -1;
        panel->findChild<QLineEdit*>("drugFeedersAdded")->setText(QString::number(addedFeeder));
        panel->findChild<QPushButton*>("drugRun")->click();
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 0);
        const study::Artifact corrected = window.document().study().artifacts().back();
        QVERIFY(!window.document().study().hasArtifact(planned.id)); // replaced
        QCOMPARE(corrected.provenance.parameters.at("feeders_removed"), std::to_string(removedFeeder));
        QCOMPARE(std::stod(corrected.attributes.at("feeders_added_by_hand")), 1.0);
        QCOMPARE(std::stod(corrected.attributes.at("feeders_removed_by_hand")), 1.0);
        bool listedByHand = false;
        for (int row = 0; row < feederTable->rowCount(); ++row)
        {
            const int segment = feederTable->item(row, 0)->data(Qt::UserRole).toInt();
            QVERIFY(segment != removedFeeder);
            listedByHand = listedByHand || (segment == addedFeeder && feederTable->item(row, 3)->text() == "added by hand");
        }
        QVERIFY(listedByHand);
        window.document().undoStack()->undo(); // the corrected run; the planned one comes back
        QVERIFY(window.document().study().hasArtifact(planned.id));
        window.document().undoStack()->undo(); // the planned run
        window.document().undoStack()->undo(); // the tumour label
        window.document().undoStack()->undo(); // the liver label

        const std::size_t before = window.document().study().artifacts().size();
        window.document().undoStack()->undo(); // the picked run goes, the one it replaced comes back
        QCOMPARE(window.document().study().artifacts().size(), before);
        QVERIFY(window.document().study().hasArtifact(run.id) && !window.document().study().hasArtifact(picked.id));
        window.document().undoStack()->undo(); // the network and its filling run go together
        QCOMPARE(window.document().study().artifacts().size(), before - 2);
    }
};

VSIM_GUI_TEST_MAIN(TestDrug)
#include "tst_drug.moc"
