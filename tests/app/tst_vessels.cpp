// The vessel steps from the GUI: segment the imported phantom in the background (label undoable, overlaid in the
// MPRs, lumen surface in the 3D view), then skeleton and centerlines as one undo step, drawn over the surface;
// parameters from the declarations' form; the brush paints and erases with undo, and its result becomes a new
// label artifact; without an image the step says what to do first.
#include "ArtifactCommands.h"
#include "DicomFixtures.h"
#include "GuiTestMain.h"
#include "LabelEditSession.h"
#include "MainWindow.h"
#include "ParameterForm.h"
#include "PixelChecks.h"
#include "SegmentationPointsPanel.h"
#include "StudyDocument.h"
#include "TestOutput.h"
#include "VesselViewPanel.h"
#include "ViewCapture.h"
#include "ViewLayout.h"
#include "vsim/app/SegmentNames.h"
#include "vsim/viz/PlaneImageView.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"
#include "vsim/dicom/AnatomyPhantom.h"
#include "vsim/dicom/CtSeriesWriter.h"
#include "vsim/dicom/SliceStack.h"
#include "vsim/imaging/GuidedSegmentation.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QTableWidget>

namespace fs = std::filesystem;
using namespace vsim;

namespace {

/// The patient-like AAA of the GUI tests: 160 x 160 x 120 voxels of 1.1 x 1.1 x 1.6 mm, seed 2 (seed 3 at these
/// voxels leaks into the vertebral bodies, noted in issue 15).
dicom::PhantomOptions patientAaaOptions()
{
    dicom::PhantomOptions options;
    options.style = dicom::PhantomStyle::Patient;
    options.size = {160, 160, 120};
    options.spacing = {1.1, 1.1, 1.6};
    options.seed = 2;
    return options;
}

/// Writes that phantom's CT as a DICOM series into `folder`; returns the anatomy (truth measures, arteries).
dicom::AnatomyPhantom writePatientAaa(const fs::path& folder)
{
    const dicom::PhantomOptions options = patientAaaOptions();
    dicom::AnatomyPhantom phantom = dicom::buildAnatomyPhantom(dicom::PhantomKind::Aaa, options);
    const VolumeGeometry geometry = dicom::phantomGeometry(options);
    dicom::writeCtSeries(dicom::renderAnatomyCt(phantom, geometry, options.seed), dicom::stackOf(geometry), {}, folder);
    return phantom;
}

} // namespace

class TestVessels : public QObject
{
    Q_OBJECT

private slots:
    void segmentSkeletonCenterlines()
    {
        const fs::path folder = test::freshFolder("gui-vessels", "aaa");
        const auto phantom = test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        gui::MainWindow window;
        window.resize(1200, 900);
        window.show();
        const fs::path bundle = test::freshFolder("gui-vessels", "study") / "vessels.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(vsim::test::waitForTask(window));

        QVERIFY(window.segmentVessels());
        QVERIFY(vsim::test::waitForTask(window));
        const study::Study& study = window.document().study();
        QCOMPARE(study.artifacts().size(), std::size_t(2));
        const study::Artifact& label = study.artifacts().back();
        QCOMPARE(label.kind, study::ArtifactKind::Label);
        QCOMPARE(label.provenance.command, std::string("segment"));
        const LabelVolume truth = dicom::renderPhantomLabels(phantom.model, phantom.geometry);
        const double dice = imaging::diceCoefficient(study.loadLabel(label.id), 1, truth, dicom::label::kVesselLumen);
        qInfo("GUI segmentation of the 3.5 mm aaa: Dice %.3f", dice);
        QVERIFY(dice > 0.85); // 3.5 mm voxels: the small renal branches are a few voxels wide
        for (auto orientation : {viz::SliceOrientation::Axial, viz::SliceOrientation::Coronal, viz::SliceOrientation::Sagittal})
            QVERIFY(window.views()->sliceView(orientation)->hasLabel());

        QVERIFY(window.extractSkeletonAndCenterlines());
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(4));
        QCOMPARE(window.document().study().artifacts().back().name, std::string("Centerlines"));
        const auto& artifacts = window.document().study().artifacts();
        const std::size_t drawn = window.document().study().loadSkeleton(artifacts[2].id).edges.size() +
                                  window.document().study().loadSkeleton(artifacts[3].id).edges.size();
        QCOMPARE(window.views()->volumeView()->lineCount(), int(drawn)); // skeleton and centerlines over the surface
        // The measurement table: the maximum-diameter row first (the aaa's 55 mm, coarse 3.5 mm voxels here), and
        // a click takes the MPR cursor into the aneurysm.
        QTableWidget* table = window.measurementTable();
        QVERIFY(table->rowCount() >= 2);
        const double maximum = table->item(0, 7)->text().toDouble();
        qInfo("measurement table: %d rows, maximum diameter %.2f mm", table->rowCount(), maximum);
        QVERIFY(std::abs(maximum - 55.0) < 4.0);
        // Segment rows carry their anatomical name (or "unnamed (nodes a-b)"); naming one is one undo step.
        QVERIFY(!table->item(1, 0)->text().isEmpty() && table->item(1, 0)->toolTip().contains("double-click"));
        const std::string centerlinesId = artifacts[3].id;
        const SkeletonGraph centerlines = window.document().study().loadSkeleton(centerlinesId);
        const std::vector<std::string> automatic = app::segmentNames(window.document().study(), centerlinesId, centerlines);
        window.document().undoStack()->push(new gui::RenameSegmentCommand(window.document(), centerlinesId, 0, "graft limb"));
        QCOMPARE(app::segmentNames(window.document().study(), centerlinesId, centerlines)[0], std::string("graft limb"));
        window.document().undoStack()->undo();
        QCOMPARE(app::segmentNames(window.document().study(), centerlinesId, centerlines), automatic);
        emit table->cellClicked(0, 0);
        const Eigen::Vector3d cursor = window.views()->sliceView(viz::SliceOrientation::Axial)->cursor();
        QVERIFY(std::abs(cursor.z() - phantom.model.measures.at("aneurysm_centre_z_mm")) < 25.0);
        // What people see: the label overlay tints the coronal MPR red, the centerlines show green through the
        // translucent lumen surface (window.grab() does not re-render the OpenGL views: grab each one).
        const QString output = test::outputFolder("gui");
        const QImage coronal = window.views()->sliceView(viz::SliceOrientation::Coronal)->grabFramebuffer();
        const QImage scene = window.views()->volumeView()->grabFramebuffer();
        coronal.save(output + "/vessels-coronal-overlay.png");
        scene.save(output + "/vessels-3d-centerlines.png");
        const auto countPixels = [](const QImage& image, auto test) {
            int count = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x)
                    count += test(QColor(image.pixel(x, y)));
            return count;
        };
        const int tinted = countPixels(coronal, [](const QColor& c) { return c.red() > c.green() + 60; });
        const int green = countPixels(scene, [](const QColor& c) { return c.green() > c.red() + 30 && c.green() > 100; });
        qInfo("overlay: %d red-tinted pixels in the coronal MPR; %d centerline pixels in the 3D view", tinted, green);
        QVERIFY(tinted > 500);
        window.views()->volumeView()->clearLines();
        const int greenWithoutLines = countPixels(window.views()->volumeView()->grabFramebuffer(), [](const QColor& c) {
            return c.green() > c.red() + 30 && c.green() > 100;
        });
        QVERIFY2(green > 20 && greenWithoutLines < 5, qPrintable(QString("%1 / %2").arg(green).arg(greenWithoutLines)));
        window.grab().save(QString::fromStdString((fs::path(test::outputFolder("gui").toStdString()) / "vessels.png").string()));
        window.document().undoStack()->undo(); // skeleton and centerlines go together
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(2));
        window.document().undoStack()->undo();
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(1));
    }

    void parametersBrushAndUndo()
    {
        const fs::path folder = test::freshFolder("gui-vessels", "brush");
        test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        gui::MainWindow window;
        window.resize(1200, 900);
        window.show();
        const fs::path bundle = test::freshFolder("gui-vessels", "brush-study") / "brush.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(vsim::test::waitForTask(window));

        // The form shows the declarations; an edited value reaches the step and its provenance.
        gui::ParameterForm form(window.segmentationParameters());
        auto* refine = form.findChild<QDoubleSpinBox*>("refine_sigma_mm");
        QVERIFY(refine);
        QCOMPARE(refine->suffix(), QString(" mm"));
        QVERIFY(!refine->toolTip().isEmpty());
        refine->setValue(0.5);
        QCOMPARE(form.values().get("refine_sigma_mm"), 0.5);
        form.resetToDefaults();
        QCOMPARE(form.values().get("refine_sigma_mm"), 0.35);
        window.segmentationParameters().set("refine_sigma_mm", 0.0);
        QVERIFY(window.segmentVessels());
        QVERIFY(vsim::test::waitForTask(window));
        const study::Artifact segmented = window.document().study().artifacts().back();
        QCOMPARE(segmented.provenance.parameters.at("refine_sigma_mm"), std::string("0"));
        const LabelVolume original = window.document().study().loadLabel(segmented.id);
        const auto voxels = [](const LabelVolume& label) { return std::count(label.data(), label.data() + label.size(), 1); };

        // A paint stroke dragged across the axial view: one undo step that undoes exactly.
        QVERIFY(window.startLabelEditing(viz::BrushMode::Paint, 6.0));
        gui::LabelEditSession* session = window.labelEditSession();
        QVERIFY(session);
        viz::SliceView* axial = window.views()->sliceView(viz::SliceOrientation::Axial);
        axial->setCursor(dicom::kPhantomCentre + Eigen::Vector3d(70.0, 0.0, 0.0)); // tissue beside the aorta
        const QPointF middle = axial->widgetAt(axial->cursor()); // the crosshair, where the image stays put
        const int undoBefore = window.document().undoStack()->count();
        auto mouse = [&](QEvent::Type type, QPointF at, Qt::MouseButtons buttons) {
            QMouseEvent event(type, at, axial->mapToGlobal(at), Qt::LeftButton, buttons, Qt::NoModifier);
            QApplication::sendEvent(axial, &event);
        };
        mouse(QEvent::MouseButtonPress, middle, Qt::LeftButton);
        mouse(QEvent::MouseMove, middle + QPointF(20, 0), Qt::LeftButton);
        mouse(QEvent::MouseButtonRelease, middle + QPointF(20, 0), Qt::NoButton);
        const std::size_t painted = session->paintedVoxels();
        qInfo("brush stroke: %zu voxels painted", painted);
        QVERIFY(painted > 0);
        QCOMPARE(window.document().undoStack()->count(), undoBefore + 1);
        QCOMPARE(voxels(session->label()), voxels(original) + long(painted));
        QCOMPARE(axial->cursor(), dicom::kPhantomCentre + Eigen::Vector3d(70.0, 0.0, 0.0)); // the brush does not move it
        window.document().undoStack()->undo();
        QCOMPARE(session->paintedVoxels(), std::size_t(0));
        QVERIFY(std::equal(original.data(), original.data() + original.size(), session->label().data()));
        window.document().undoStack()->redo();
        QCOMPARE(session->paintedVoxels(), painted);

        // Applying adds a new label artifact that records the edits; undo takes it away again.
        const std::size_t before = window.document().study().artifacts().size();
        QVERIFY(window.applyLabelEdits());
        QVERIFY(vsim::test::waitForTask(window)); // the surface of the edited label
        QVERIFY(!window.labelEditSession());
        const study::Artifact edited = window.document().study().artifacts().back();
        QCOMPARE(edited.name, std::string("Vessel lumen (edited)"));
        QCOMPARE(edited.provenance.command, std::string("edit-label"));
        QCOMPARE(edited.provenance.inputs.front(), segmented.id);
        QCOMPARE(edited.provenance.parameters.at("painted_voxels"), std::to_string(painted));
        QCOMPARE(voxels(window.document().study().loadLabel(edited.id)), voxels(original) + long(painted));
        window.document().undoStack()->undo();
        QCOMPARE(window.document().study().artifacts().size(), before);

        // Erasing inside the aorta removes lumen voxels; nothing to apply without edits.
        QVERIFY(window.startLabelEditing(viz::BrushMode::Erase, 3.0));
        QVERIFY(!window.applyLabelEdits());
        axial->setCursor(dicom::kPhantomCentre + Eigen::Vector3d(0.0, -5.0, 100.0));
        mouse(QEvent::MouseButtonPress, axial->widgetAt(axial->cursor()), Qt::LeftButton);
        mouse(QEvent::MouseButtonRelease, axial->widgetAt(axial->cursor()), Qt::NoButton);
        QVERIFY(window.labelEditSession()->erasedVoxels() > 0);
        // Remove Island at the cursor: the painted blob beside the aorta (not connected to it) goes in one undo step.
        const std::size_t erased = window.labelEditSession()->erasedVoxels();
        const long lumenVoxels = voxels(window.labelEditSession()->label());
        // The blob is painted with the 3D sphere brush: a ball of 10 mm (4189 mm3) through the 8 mm slices, within
        // 25 % on these 98 mm3 voxels.
        window.labelEditSession()->dab(dicom::kPhantomCentre + Eigen::Vector3d(70.0, 0.0, 0.0), Eigen::Vector3d::UnitZ(),
                                       10.0, 1, true);
        window.document().undoStack()->push(window.labelEditSession()->finishStroke());
        const long withBlob = voxels(window.labelEditSession()->label());
        const double blobMm3 = double(withBlob - lumenVoxels) * original.geometry().spacing.prod();
        qInfo("sphere brush r = 10 mm: %.0f mm3 (4/3 pi r3 = 4189)", blobMm3);
        QVERIFY(std::abs(blobMm3 / 4188.8 - 1.0) < 0.25);
        axial->setCursor(dicom::kPhantomCentre + Eigen::Vector3d(70.0, 0.0, 0.0));
        QVERIFY(window.removeIslandAtCursor());
        QCOMPARE(voxels(window.labelEditSession()->label()), lumenVoxels);
        QCOMPARE(window.labelEditSession()->erasedVoxels(), erased + std::size_t(withBlob - lumenVoxels));
        window.document().undoStack()->undo();
        QCOMPARE(voxels(window.labelEditSession()->label()), withBlob);
        axial->setCursor(dicom::kPhantomCentre + Eigen::Vector3d(140.0, 140.0, 0.0)); // air: nothing near
        QVERIFY(!window.removeIslandAtCursor());
        window.discardLabelEdits();
        QVERIFY(!window.labelEditSession());
        QCOMPARE(window.document().study().artifacts().size(), before);
    }

    void seedFromTheCursor()
    {
        const fs::path folder = test::freshFolder("gui-vessels", "seeded");
        test::writePhantomSeries(dicom::PhantomKind::Aaa, test::smallPhantomOptions(), folder);
        gui::MainWindow window;
        const fs::path bundle = test::freshFolder("gui-vessels", "seeded-study") / "seeded.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(vsim::test::waitForTask(window));
        // The cursor on the aorta above the aneurysm, as a click in an MPR view puts it.
        const Eigen::Vector3d aorta = dicom::kPhantomCentre + Eigen::Vector3d(0, -5, 100);
        window.views()->sliceView(viz::SliceOrientation::Axial)->setCursor(aorta);
        QVERIFY(window.segmentVessels(window.views()->sliceView(viz::SliceOrientation::Axial)->cursor()));
        QVERIFY(vsim::test::waitForTask(window));
        const study::Artifact& label = window.document().study().artifacts().back();
        QCOMPARE(label.provenance.parameters.at("seed_found_automatically"), std::string("no"));
        // A seed in the spine is refused with a message and adds nothing.
        QSignalSpy failed(&window.tasks(), &gui::TaskRunner::failed);
        QVERIFY(window.segmentVessels(dicom::kPhantomCentre + Eigen::Vector3d(0, 45, 0)));
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(failed.count(), 1);
        QVERIFY(failed.front().at(1).toString().contains("not in a contrast-filled vessel"));
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(2));
    }

    /// Vessels > AAA Sac on a patient-like AAA (aortic lumen from the guided segmentation): the sac label is added
    /// (undoable) and the dock's first row is the SVS outer diameter, its definition in the tooltip, within 3 mm of
    /// the phantom's truth at these 1.1 mm voxels; a click takes the cursor to its section; along the vessel the
    /// cross-section's outer-wall caliper matches the SVS diameter.
    void aaaSacInTheDock()
    {
        const fs::path folder = test::freshFolder("gui-vessels", "patient-aaa");
        const dicom::AnatomyPhantom phantom = writePatientAaa(folder);
        gui::MainWindow window;
        window.resize(1200, 900);
        window.show();
        const fs::path bundle = test::freshFolder("gui-vessels", "sac-study") / "sac.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(vsim::test::waitForTask(window));
        study::Study& study = window.document().study();
        imaging::SegmentationRequest request;
        request.target = imaging::SegmentationTarget::Aorta;
        const imaging::SegmentationResult lumen = imaging::segmentFromPoints(
            study.loadImage(study.artifacts().front().id), ParameterSet(imaging::guidedSegmentationParameters()), request);
        study::Provenance provenance;
        provenance.command = "segment";
        provenance.parameters = {{"target", "aorta"}};
        study.addLabel(lumen.label, "Aortic lumen", provenance);

        QVERIFY(window.measureSac());
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(study.artifacts().back().provenance.command, std::string("sac"));
        QTableWidget* table = window.measurementTable(); // filled once the scene has the sac label's pieces
        QTRY_VERIFY_WITH_TIMEOUT(table->rowCount() >= 1 && table->item(0, 0)->text().contains("SVS"), 60000);
        const QString first = table->item(0, 0)->text();
        qInfo("dock: %s (truth %.1f mm)", qPrintable(first), phantom.measures.at("max_outer_diameter_mm"));
        QVERIFY(first.contains("outer wall to outer wall (SVS)") && table->item(0, 0)->toolTip().contains("SVS 2018"));
        const double outer = study.artifacts().back().provenance.parameters.count("max_outer_diameter_mm")
                                 ? std::stod(study.artifacts().back().provenance.parameters.at("max_outer_diameter_mm"))
                                 : 0.0;
        QVERIFY(std::abs(outer - phantom.measures.at("max_outer_diameter_mm")) <= 3.0);
        emit table->cellClicked(0, 0);
        const Eigen::Vector3d cursor = window.views()->sliceView(viz::SliceOrientation::Axial)->cursor();
        QVERIFY(std::abs(cursor.z() - phantom.measures.at("max_outer_diameter_z_mm")) < 5.0);

        // Along the vessel, the cross-section draws the sac's outer-wall caliper: its widest over the centerlines'
        // segments is the sac's SVS diameter within two voxels (the labels' staircase against the sac's contours).
        QVERIFY(window.extractSkeletonAndCenterlines() && vsim::test::waitForTask(window));
        QVERIFY(window.showVesselView());
        gui::VesselViewPanel* panel = window.views()->vesselPanel();
        double widestArc = 0.0, widest = 0.0;
        int widestSegment = -1;
        const QComboBox* segments = panel->findChild<QComboBox*>("vesselSegment");
        for (int index = 0; index < segments->count(); ++index)
        {
            if (segments->itemData(index).toList().size() != 1)
                continue; // the paths across junctions: their planes there cut the sac obliquely
            panel->setPath(segments->itemData(index).toList());
            // Perpendicular to the aorta: sections of the long segments 10 mm or more from their ends (a plane at a
            // junction cuts the sac obliquely).
            const double length = panel->frames().lengthMm();
            for (double arc = 10.0; length >= 40.0 && arc <= length - 10.0; arc += 1.0)
                if (const auto caliper = panel->outerCaliperAt(arc); caliper && caliper->lengthMm > widest)
                    widest = caliper->lengthMm, widestArc = arc, widestSegment = panel->segment();
        }
        panel->setSegment(widestSegment);
        qInfo("vessel view: the outer-wall caliper's widest %.1f mm (the sac's SVS diameter %.1f mm)", widest, outer);
        QVERIFY(std::abs(widest - outer) <= 2.0 * 1.1);
        panel->setArc(widestArc);
        QVERIFY(panel->crossSectionView()->caption().contains("outer wall"));
        const QImage section = panel->crossSectionView()->grabFramebuffer();
        const QRect middle(section.width() / 4, section.height() / 4, section.width() / 2, section.height() / 2);
        QVERIFY(vsim::test::yellowPixels(section, middle) > 40); // the caliper line across the sac
        gui::captureWindow(panel).save(vsim::test::outputFolder("gui-vessels") + "/vessel-view-sac.png");

        window.document().undoStack()->undo(); // the centerlines, the skeleton, then the sac
        window.document().undoStack()->undo();
        window.document().undoStack()->undo();
        QCOMPARE(study.artifacts().back().provenance.command, std::string("segment"));
    }

    /// Vessels > Segment from Points on a patient-like AAA: an include point placed with a click in the axial view
    /// (a ring drawn on every MPR through it), Segment, then the point dragged along the aorta: the re-run replaces
    /// the label in one undo step, within the 5 s; the label is the library's from that point, 95 % of it in
    /// the truth lumen; the request comes back from a reopened study.
    void segmentFromPointsWithMarkers()
    {
        const fs::path folder = test::freshFolder("gui-vessels", "points-aaa");
        const dicom::AnatomyPhantom phantom = writePatientAaa(folder);
        const LabelVolume truth = dicom::renderAnatomyLabels(phantom, dicom::phantomGeometry(patientAaaOptions()));
        gui::MainWindow window;
        window.resize(1200, 900);
        window.show();
        const fs::path bundle = test::freshFolder("gui-vessels", "points-study") / "points.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(window.importDicom(QString::fromStdString(folder.string())));
        QVERIFY(vsim::test::waitForTask(window));
        study::Study& study = window.document().study();
        const Eigen::Vector3d aorta = imaging::findAbdominalAortaPoint(study.loadImage(study.artifacts().front().id));

        window.showSegmentationPoints();
        gui::SegmentationPointsPanel* panel = window.segmentationPointsPanel();
        QVERIFY(panel->isVisible());
        viz::SliceView* axial = window.views()->sliceView(viz::SliceOrientation::Axial);
        axial->setCursor(aorta);
        panel->setPlacing(gui::SegmentationPointsPanel::Placing::Include);
        QVERIFY(axial->placing());
        const auto click = [&](viz::SliceView* view, QEvent::Type type, QPointF at, Qt::MouseButtons buttons) {
            QMouseEvent event(type, at, view->mapToGlobal(at), Qt::LeftButton, buttons, Qt::NoModifier);
            QApplication::sendEvent(view, &event);
        };
        const QPointF atAorta = axial->widgetAt(aorta); // the cursor leaves the image in place: not the middle
        click(axial, QEvent::MouseButtonPress, atAorta, Qt::LeftButton);
        click(axial, QEvent::MouseButtonRelease, atAorta, Qt::NoButton);
        QCOMPARE(panel->request().includeMm.size(), std::size_t(1));
        QVERIFY((panel->request().includeMm.front() - aorta).norm() < 1.0);
        QCOMPARE(axial->cursor(), aorta); // placing does not move the cursor
        QVERIFY(!axial->placing());       // one click, one point
        for (auto orientation : {viz::SliceOrientation::Axial, viz::SliceOrientation::Coronal, viz::SliceOrientation::Sagittal})
            QCOMPARE(window.views()->sliceView(orientation)->markers().size(), std::size_t(1));
        QCOMPARE(panel->pointTable()->item(0, 0)->text(), QString("+1"));

        const std::size_t artifacts = study.artifacts().size();
        QVERIFY(window.segmentFromPoints(panel->request()));
        QVERIFY(vsim::test::waitForTask(window));
        QCOMPARE(study.artifacts().size(), artifacts + 1);
        const study::Artifact first = study.artifacts().back();
        QCOMPARE(first.name, std::string("Vessel lumen (aorta)"));
        // The same label as the library makes from that point; nearly all of it in the truth lumen (the branches
        // are followed 20 mm only, so the Dice against the whole truth lumen is the imaging test's business).
        const LabelVolume made = study.loadLabel(first.id);
        imaging::SegmentationRequest direct;
        direct.target = imaging::SegmentationTarget::Aorta;
        direct.includeMm = panel->request().includeMm;
        const LabelVolume library = imaging::segmentFromPoints(study.loadImage(study.artifacts().front().id),
                                                               ParameterSet(imaging::guidedSegmentationParameters()),
                                                               direct)
                                        .label;
        QVERIFY(std::equal(made.data(), made.data() + made.size(), library.data()));
        std::size_t inLumen = 0, labelled = 0;
        for (std::size_t v = 0; v < made.size(); ++v)
            if (made.data()[v] == 1)
                ++labelled, inLumen += truth.data()[v] == dicom::label::kVesselLumen;
        const double precision = double(inLumen) / double(std::max<std::size_t>(labelled, 1));
        qInfo("GUI guided segmentation from one placed point (patient-like AAA seed 2, 1.1 mm): %zu voxels, %.3f of "
              "them in the truth lumen", labelled, precision);
        QVERIFY(labelled > 10000 && precision > 0.95);

        // Drag the point 20 mm up the aorta in the coronal view: the re-run replaces the label in one undo step.
        viz::SliceView* coronal = window.views()->sliceView(viz::SliceOrientation::Coronal);
        coronal->setCursor(aorta);
        const Eigen::Vector3d moved = aorta + Eigen::Vector3d(0.0, 0.0, 20.0);
        QElapsedTimer timer;
        timer.start();
        click(coronal, QEvent::MouseButtonPress, coronal->widgetAt(aorta), Qt::LeftButton);
        click(coronal, QEvent::MouseMove, coronal->widgetAt(moved), Qt::LeftButton);
        click(coronal, QEvent::MouseButtonRelease, coronal->widgetAt(moved), Qt::NoButton);
        QVERIFY((panel->request().includeMm.front() - moved).norm() < 1.0);
        QVERIFY(vsim::test::waitForTask(window));
        const double rerunS = timer.elapsed() / 1000.0;
        qInfo("re-run after moving the point: %.2f s (issue: <= 5 s)", rerunS);
        QVERIFY(rerunS <= 5.0);
        QCOMPARE(study.artifacts().size(), artifacts + 1);
        QVERIFY(!study.hasArtifact(first.id));
        const study::Artifact second = study.artifacts().back();
        QVERIFY(second.provenance.parameters.at("include_points_mm").find(numberText(moved.z())) != std::string::npos);
        window.document().undoStack()->undo();
        QVERIFY(study.hasArtifact(first.id) && !study.hasArtifact(second.id));
        window.document().undoStack()->redo();
        QVERIFY(study.hasArtifact(second.id) && !study.hasArtifact(first.id));

        // Reopened, the dock shows the points the label was made with.
        QVERIFY(window.saveStudy());
        QVERIFY(vsim::test::waitForTask(window));
        gui::MainWindow reopened;
        QVERIFY(reopened.openStudy(QString::fromStdString(bundle.string())));
        QVERIFY(vsim::test::waitForTask(reopened));
        reopened.showSegmentationPoints();
        QCOMPARE(reopened.segmentationPointsPanel()->request().includeMm.size(), std::size_t(1));
        QVERIFY((reopened.segmentationPointsPanel()->request().includeMm.front() - moved).norm() < 0.01);
        QCOMPARE(reopened.segmentationPointsPanel()->request().target, imaging::SegmentationTarget::Aorta);

        // A stop plane clicked in the axial view 30 mm below the aorta point: the axial plane there, its normal
        // turned away from the include point (inferior), listed as |1 and drawn in every view; the label then ends
        // at it.
        const Eigen::Vector3d stopAt = aorta - Eigen::Vector3d(0.0, 0.0, 30.0);
        axial->setCursor(stopAt);
        panel->setPlacing(gui::SegmentationPointsPanel::Placing::Stop);
        click(axial, QEvent::MouseButtonPress, axial->widgetAt(stopAt), Qt::LeftButton);
        click(axial, QEvent::MouseButtonRelease, axial->widgetAt(stopAt), Qt::NoButton);
        const imaging::SegmentationRequest stopped = panel->request();
        QCOMPARE(stopped.stops.size(), std::size_t(1));
        QVERIFY((stopped.stops.front().pointMm - stopAt).norm() < 1.0);
        QVERIFY((stopped.stops.front().normal - Eigen::Vector3d(0.0, 0.0, -1.0)).norm() < 1e-9);
        QCOMPARE(panel->pointTable()->item(1, 0)->text(), QString("|1"));
        QCOMPARE(axial->markers().size(), std::size_t(2));
        QVERIFY(window.segmentFromPoints(stopped));
        QVERIFY(vsim::test::waitForTask(window));
        const LabelVolume ended = study.loadLabel(study.artifacts().back().id);
        double lowest = 1e9;
        for (int k = 0; k < ended.geometry().dims[2]; ++k)
            for (int j = 0; j < ended.geometry().dims[1]; ++j)
                for (int i = 0; i < ended.geometry().dims[0]; ++i)
                    if (ended.at(i, j, k))
                        lowest = std::min(lowest, ended.geometry().indexToPatient(Eigen::Vector3d(i, j, k)).z());
        const double planeZ = stopped.stops.front().pointMm.z(); // on the shown slice
        qInfo("stop plane at z %.1f mm: the label's lowest voxel at z %.1f mm", planeZ, lowest);
        QVERIFY(lowest >= planeZ - 0.01 && lowest < planeZ + 3.0);
    }

    void withoutImageSaysWhatToDo()
    {
        gui::MainWindow window;
        const fs::path bundle = test::freshFolder("gui-vessels", "empty") / "empty.vsim";
        QVERIFY(window.newStudy(QString::fromStdString(bundle.string())));
        QVERIFY(!window.segmentVessels());
        QVERIFY(!window.extractSkeletonAndCenterlines());
        QCOMPARE(window.document().study().artifacts().size(), std::size_t(0));
    }
};

VSIM_GUI_TEST_MAIN(TestVessels)
#include "tst_vessels.moc"
