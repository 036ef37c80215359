// The main window's menus and the About box (MainWindow.cpp holds the document lifecycle).
#include "ArtifactCommands.h"
#include "FileLocations.h"
#include "HelpWindow.h"
#include "Languages.h"
#include "MainWindow.h"
#include "ViewLayout.h"
#include "vsim/app/VersionInfo.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QActionGroup>
#include <QApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QInputDialog>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTreeWidget>
#include <QWhatsThis>

namespace vsim::gui {
namespace {

const char* kStudyFilter = "VascuSim study (study.json)";
const char* kVolumeFilter = "Volumes (*.nii *.nii.gz *.nrrd *.nhdr *.mha *.mhd);;All files (*)";

} // namespace

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New Study..."), QKeySequence::New, this, [this] {
        const QString bundle = QFileDialog::getSaveFileName(this, tr("New study"), startFolder("study"), tr("Study folder (*.vsim)"));
        rememberFolder("study", bundle.isEmpty() ? QString() : QFileInfo(bundle).absolutePath());
        if (!bundle.isEmpty())
            windowForNewDocument()->newStudy(bundle.endsWith(".vsim") ? bundle : bundle + ".vsim");
    });
    file->addAction(tr("&Open Study..."), QKeySequence::Open, this, [this] {
        const QString manifest = QFileDialog::getOpenFileName(this, tr("Open study"), startFolder("study"), tr(kStudyFilter));
        rememberFolder("study", manifest.isEmpty() ? QString() : QFileInfo(QFileInfo(manifest).absolutePath()).absolutePath());
        if (!manifest.isEmpty())
            windowForNewDocument()->openStudy(QFileInfo(manifest).absolutePath());
    });
    m_recentMenu = file->addMenu(tr("Open &Recent"));
    rebuildRecentMenu();
    file->addSeparator();
    m_documentActions << file->addAction(tr("Import &DICOM..."), QKeySequence(tr("Ctrl+D")), this,
                                         &MainWindow::showDicomImportDialog);
    m_documentActions << file->addAction(tr("Query/Retrieve (&PACS)..."), this, &MainWindow::showPacsDialog);
    m_documentActions << file->addAction(tr("Send to PAC&S..."), this, &MainWindow::showPacsSendDialog);
    m_documentActions << file->addAction(tr("&Import Volume..."), QKeySequence(tr("Ctrl+I")), this, [this] {
        const QString volume = QFileDialog::getOpenFileName(this, tr("Import volume"), startFolder("volume"), tr(kVolumeFilter));
        rememberFolder("volume", volume);
        if (!volume.isEmpty())
            importVolume(volume);
    });
    m_documentActions << file->addAction(tr("Import &Label..."), this, [this] {
        const QString mask = QFileDialog::getOpenFileName(
            this, tr("Import label (a mask on the CT's grid)"), startFolder("volume"),
            tr("Volumes (*.nii *.nii.gz *.nrrd *.nhdr *.mha *.mhd);;DICOM SEG or a mask series' slice (*.dcm *.DCM *.IMA);;"
               "All files (*)"));
        rememberFolder("volume", mask);
        if (!mask.isEmpty())
            importLabel(mask);
    });
    file->addSeparator();
    m_documentActions << file->addAction(tr("&Save"), QKeySequence::Save, this, [this] { saveStudy(); });
    m_documentActions << file->addAction(tr("Save &As..."), QKeySequence::SaveAs, this, [this] {
        const QString bundle = QFileDialog::getSaveFileName(this, tr("Save study as"), startFolder("study"), tr("Study folder (*.vsim)"));
        rememberFolder("study", bundle.isEmpty() ? QString() : QFileInfo(bundle).absolutePath());
        if (!bundle.isEmpty())
            saveStudyAs(bundle.endsWith(".vsim") ? bundle : bundle + ".vsim");
    });
    file->addSeparator();
    m_documentActions << file->addAction(tr("Export &Report..."), QKeySequence(tr("Ctrl+R")), this,
                                         &MainWindow::showReportExportDialog);
    file->addSeparator();
    file->addAction(tr("&Close Window"), QKeySequence::Close, this, &QWidget::close);
    file->addAction(tr("&Quit"), QKeySequence::Quit, qApp, &QApplication::closeAllWindows);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    m_undoAction = m_document.undoStack()->createUndoAction(this, tr("&Undo"));
    m_undoAction->setShortcut(QKeySequence::Undo);
    m_redoAction = m_document.undoStack()->createRedoAction(this, tr("&Redo"));
    m_redoAction->setShortcut(QKeySequence::Redo);
    edit->addAction(m_undoAction);
    edit->addAction(m_redoAction);
    edit->addSeparator();
    m_documentActions << edit->addAction(tr("Re&name Artifact..."), QKeySequence(Qt::Key_F2), this, [this] {
        QTreeWidgetItem* item = m_artifactTree->currentItem();
        if (!item)
            return;
        bool accepted = false;
        const QString name = QInputDialog::getText(this, tr("Rename artifact"), tr("Name:"), QLineEdit::Normal,
                                                   item->text(0), &accepted);
        if (accepted && !name.isEmpty())
            m_document.undoStack()->push(new RenameArtifactCommand(
                m_document, item->data(0, Qt::UserRole).toString().toStdString(), name.toStdString()));
    });
    m_documentActions << edit->addAction(tr("&Delete Artifact"), QKeySequence::Delete, this, [this] {
        if (QTreeWidgetItem* item = m_artifactTree->currentItem())
            m_document.undoStack()->push(
                new RemoveArtifactCommand(m_document, item->data(0, Qt::UserRole).toString().toStdString()));
    });

    createVesselMenu();
    createWallMenu();
    createDrugMenu();
    createFlowMenu();
    createMeasureMenu();

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("Window/Level: &CTA"), this, [this] { m_views->applyWindowLevel(viz::kCtaPreset); });
    view->addAction(tr("Window/Level: &Soft Tissue"), this, [this] { m_views->applyWindowLevel(viz::kSoftTissuePreset); });
    view->addAction(tr("Window/Level: &Bone"), this, [this] { m_views->applyWindowLevel(viz::kBonePreset); });
    view->addAction(tr("Window/Level: &Lung"), this, [this] { m_views->applyWindowLevel(viz::kLungPreset); });
    view->addSeparator();
    QAction* reset = view->addAction(tr("&Reset Slice Views"), this, [this] { m_views->resetViews(); });
    reset->setToolTip(tr("Centre the volume and show it whole in the axial, coronal and sagittal views (R in a view)"));
    QAction* linked = view->addAction(tr("&Link Slice Views"));
    linked->setObjectName("linkViewsAction");
    linked->setCheckable(true);
    linked->setChecked(true);
    linked->setToolTip(tr("Linked, the slice views share the cursor and window/level"));
    connect(linked, &QAction::toggled, this, [this](bool on) { m_views->setLinked(on); });
    QAction* crosshair = view->addAction(tr("Show &Crosshair"));
    crosshair->setObjectName("crosshairAction");
    crosshair->setCheckable(true);
    crosshair->setChecked(true);
    connect(crosshair, &QAction::toggled, this, [this](bool on) { m_views->setCrosshairShown(on); });
    QAction* rightZoom = view->addAction(tr("Right Drag &Zooms (Slicer)"));
    rightZoom->setObjectName("rightDragZoomsAction");
    rightZoom->setCheckable(true);
    rightZoom->setToolTip(tr("Right drag in a slice view zooms instead of changing window/level (kept in the settings)"));
    connect(rightZoom, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue("views/rightDragZooms", on);
        for (viz::SliceOrientation orientation : {viz::SliceOrientation::Axial, viz::SliceOrientation::Coronal, viz::SliceOrientation::Sagittal})
            m_views->sliceView(orientation)->setRightDragZooms(on);
    });
    rightZoom->setChecked(QSettings().value("views/rightDragZooms", false).toBool());
    QMenu* slab = view->addMenu(tr("Thick Slab &MIP"));
    auto* slabChoices = new QActionGroup(slab);
    for (double thicknessMm : {0.0, 5.0, 10.0, 20.0, 40.0})
    {
        QAction* choice = slab->addAction(thicknessMm == 0.0 ? tr("Off (thin slice)") : tr("%1 mm").arg(thicknessMm));
        choice->setCheckable(true);
        choice->setChecked(thicknessMm == 0.0);
        choice->setObjectName(QStringLiteral("slab%1Action").arg(int(thicknessMm)));
        slabChoices->addAction(choice);
        connect(choice, &QAction::triggered, this, [this, thicknessMm] { m_views->setSlabThickness(thicknessMm); });
    }
    view->addSeparator();
    createLayoutAndCaptureMenus(view);
    view->addSeparator();
    view->addAction(tr("3D: &Anterior View"), this, [this] { m_views->volumeView()->showAnteriorView(); });
    view->addSeparator();
    createLanguageMenu(view);
    view->addSeparator();
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        view->addAction(dock->toggleViewAction());

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* guide = help->addAction(tr("&User Guide"), this, [this] { showHelp({}); });
    guide->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("&Keyboard and Mouse"), this, [this] { showHelp("keys"); });
    help->addAction(QWhatsThis::createAction(this));
    help->addSeparator();
    help->addAction(tr("&About VascuSim"), this, &MainWindow::showAbout);
}

void MainWindow::createLanguageMenu(QMenu* view)
{
    QMenu* languages = view->addMenu(tr("&Language"));
    languages->setObjectName("languageMenu");
    auto* choices = new QActionGroup(languages);
    QStringList codes{QString(), "en"};
    codes << translatedLanguages();
    for (const QString& code : codes)
    {
        QAction* choice = languages->addAction(code.isEmpty() ? tr("System Language") : nativeLanguageName(code));
        choice->setObjectName("language_" + (code.isEmpty() ? QStringLiteral("system") : code));
        choice->setCheckable(true);
        choice->setChecked(code == chosenLanguage());
        choices->addAction(choice);
        connect(choice, &QAction::triggered, this, [this, code] {
            setChosenLanguage(code);
            statusBar()->showMessage(tr("The language changes when VascuSim starts next."), 8000);
        });
    }
}

HelpWindow* MainWindow::showHelp(const QString& section)
{
    if (!m_help)
        m_help = new HelpWindow(this);
    m_help->show();
    m_help->raise();
    if (!section.isEmpty())
        m_help->showSection(section);
    return m_help;
}

void MainWindow::rebuildRecentMenu()
{
    m_recentMenu->clear();
    const QStringList recent = QSettings().value("recentStudies").toStringList();
    for (const QString& bundle : recent)
        m_recentMenu->addAction(bundle, this, [this, bundle] { windowForNewDocument()->openStudy(bundle); });
    m_recentMenu->setEnabled(!recent.isEmpty());
}

void MainWindow::showAbout()
{
    QString versions;
    for (const auto& [component, version] : app::libraryVersions())
        versions += QStringLiteral("<tr><td>%1</td><td>%2</td></tr>")
                        .arg(QString::fromStdString(component).toHtmlEscaped(), QString::fromStdString(version).toHtmlEscaped());
    QMessageBox::about(this, tr("About VascuSim"),
                       tr("<h3>VascuSim</h3><p>Patient-specific physics for vascular procedure planning.</p>"
                          "<p>Results support planning and need clinical judgement.</p><table>%1</table>")
                           .arg(versions));
}

} // namespace vsim::gui
