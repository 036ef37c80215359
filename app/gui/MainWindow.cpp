#include "MainWindow.h"

#include "ArtifactCommands.h"
#include "LabelEditSession.h"
#include "ViewLayout.h"
#include "vsim/study/StudyLock.h"
#include "vsim/core/StoredText.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QGuiApplication>
#include <QScreen>
#include <QStyle>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalBlocker>
#include <QStatusBar>
#include <QTreeWidget>

#include <memory>

namespace vsim::gui {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    setAttribute(Qt::WA_DeleteOnClose);
    m_views = new ViewLayout(this);
    setCentralWidget(m_views);
    createDocks();
    createMeasurementDock();
    createSegmentationPointsDock();
    createStatusBar();
    createMenus();
    connect(&m_document, &StudyDocument::artifactsChanged, this, [this] {
        refreshArtifactTree();
        refreshTitle();
        // An undo may have taken away the label being edited; the views show what the study holds now.
        if (m_labelEdit && m_document.hasStudy() && !m_document.study().hasArtifact(m_labelEdit->sourceId()))
            discardLabelEdits();
        refreshScene();
    });
    connect(&m_document, &StudyDocument::studyReplaced, this, [this] {
        stopInteractiveWall();
        discardLabelEdits();
        showLabelOverlay({});
        restoreScene();
    });
    connect(m_document.undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::refreshTitle);
    connect(&m_tasks, &TaskRunner::started, this, [this](const QString& title) {
        setBusy(true);
        m_statusText->setText(title);
    });
    connect(&m_tasks, &TaskRunner::progressChanged, this, [this](double fraction, const QString& stage) {
        m_progress->setValue(static_cast<int>(fraction * 1000));
        if (!stage.isEmpty())
            m_statusText->setText(stage);
    });
    connect(&m_tasks, &TaskRunner::failed, this, &MainWindow::showError);
    connect(&m_tasks, &TaskRunner::cancelled, this, [this](const QString& title) {
        statusBar()->showMessage(tr("%1: cancelled, nothing changed").arg(title), 5000);
    });
    connect(&m_tasks, &TaskRunner::succeeded, this, [this](const QString& title) {
        statusBar()->showMessage(tr("%1: done").arg(title), 5000);
    });
    connect(&m_tasks, &TaskRunner::idle, this, [this] { setBusy(false); });
    // As the user left it; the first time 1400 x 900 (or 90 % of a smaller screen), centred, never Qt's 640 x 480.
    QSettings settings;
    if (!restoreGeometry(settings.value("mainWindow/geometry").toByteArray()))
    {
        const QRect available = QGuiApplication::primaryScreen() ? QGuiApplication::primaryScreen()->availableGeometry()
                                                                 : QRect(0, 0, 1600, 1000);
        const QSize first(std::min(1400, int(0.9 * available.width())), std::min(900, int(0.9 * available.height())));
        setGeometry(QStyle::alignedRect(Qt::LeftToRight, Qt::AlignCenter, first, available));
    }
    restoreState(settings.value("mainWindow/state").toByteArray());
    setBusy(false);
    refreshTitle();
}

MainWindow::~MainWindow()
{
    m_tasks.cancel();
    m_tasks.waitForFinished();
    // The members go before QWidget's destructor closes the window and hides the docks; a child's signal must not
    // reach this window's slots in between (closing the Run Player dock released the played run after the window's
    // own shared pointer to it was gone: a use-after-free that AddressSanitizer caught in tst_gui_particles).
    for (QObject* child : findChildren<QObject*>())
        child->disconnect(this);
}

void MainWindow::createDocks()
{
    m_artifactTree = new QTreeWidget(this);
    m_artifactTree->setObjectName("artifactTree");
    m_artifactTree->setHeaderLabels({tr("Artifact"), tr("Kind"), tr("Status")});
    m_artifactTree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    connect(m_artifactTree, &QTreeWidget::itemDoubleClicked, this, [this](QTreeWidgetItem* item) {
        const std::string id = item->data(0, Qt::UserRole).toString().toStdString();
        if (!m_document.hasStudy())
            return;
        if (m_document.study().artifact(id).kind == study::ArtifactKind::Image)
            showImageArtifact(id);
        else if (m_document.study().artifact(id).kind == study::ArtifactKind::Measurement)
        {
            // Go to the measurement: its slice in every view, centred when off screen.
            const ViewMeasurement measurement = m_document.study().loadMeasurement(id);
            Eigen::Vector3d centre = Eigen::Vector3d::Zero();
            for (const Eigen::Vector3d& point : measurement.pointsMm)
                centre += point / double(measurement.pointsMm.size());
            setArtifactShown(id, true);
            m_views->jumpTo(centre);
        }
        else if (isShowable(m_document.study().artifact(id)))
            showOnly(id);
        if (m_document.study().artifact(id).kind == study::ArtifactKind::Report)
            openReportArtifact(id);
        if (m_document.study().artifact(id).kind == study::ArtifactKind::Run)
            openRunPlayer(id);
    });
    connect(m_artifactTree, &QTreeWidget::itemChanged, this, [this](QTreeWidgetItem* item, int column) {
        if (column == 0 && item->flags().testFlag(Qt::ItemIsUserCheckable))
            setArtifactShown(item->data(0, Qt::UserRole).toString().toStdString(), item->checkState(0) == Qt::Checked);
    });
    auto* artifactDock = new QDockWidget(tr("Study"), this);
    artifactDock->setObjectName("studyDock");
    artifactDock->setWidget(m_artifactTree);
    addDockWidget(Qt::LeftDockWidgetArea, artifactDock);

    // The workflow of ARCHITECTURE.md as a checklist: a click runs a step.
    m_workflow = new WorkflowChecklist(this);
    connect(m_workflow, &WorkflowChecklist::stepClicked, this, &MainWindow::runWorkflowStep);
    auto* workflowDock = new QDockWidget(tr("Workflow"), this);
    workflowDock->setObjectName("workflowDock");
    workflowDock->setWidget(m_workflow);
    addDockWidget(Qt::LeftDockWidgetArea, workflowDock);
}

bool MainWindow::runWorkflowStep(app::WorkflowStep step)
{
    if (!m_document.hasStudy() || m_tasks.isBusy())
    {
        statusBar()->showMessage(m_document.hasStudy() ? tr("A step is running: wait for it or cancel it")
                                                       : tr("Open or create a study first (File menu)"),
                                 5000);
        return false;
    }
    switch (step)
    {
    case app::WorkflowStep::Import: showDicomImportDialog(); return true;
    case app::WorkflowStep::Segment: return segmentVessels();
    case app::WorkflowStep::Centerlines: return extractSkeletonAndCenterlines();
    case app::WorkflowStep::WallMesh: return buildWallMesh();
    case app::WorkflowStep::WallStress: return simulateWall("physiological");
    case app::WorkflowStep::Flow: return simulateBloodFlow();
    case app::WorkflowStep::Drug: return simulateDrugDelivery(m_drugPanel ? m_drugPanel->request() : m_drugRequest);
    case app::WorkflowStep::Smoke: return simulateSmoke("liver-ablation");
    case app::WorkflowStep::Report: showReportExportDialog(); return true;
    }
    return false;
}

void MainWindow::createStatusBar()
{
    m_statusText = new QLabel(this);
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1000);
    m_progress->setMaximumWidth(240);
    m_cancel = new QPushButton(tr("Cancel"), this);
    m_cancel->setObjectName("cancelButton");
    connect(m_cancel, &QPushButton::clicked, &m_tasks, &TaskRunner::cancel);
    statusBar()->addWidget(m_statusText, 1);
    statusBar()->addPermanentWidget(m_progress);
    statusBar()->addPermanentWidget(m_cancel);
}

void MainWindow::setBusy(bool busy)
{
    m_progress->setVisible(busy);
    m_cancel->setVisible(busy);
    if (!busy)
    {
        m_progress->setValue(0);
        m_statusText->clear();
    }
    for (QAction* action : m_documentActions)
        action->setEnabled(!busy && m_document.hasStudy());
    if (m_undoAction)
    {
        m_undoAction->setEnabled(!busy && m_document.undoStack()->canUndo());
        m_redoAction->setEnabled(!busy && m_document.undoStack()->canRedo());
    }
}

void MainWindow::refreshTitle()
{
    m_workflow->refresh(m_document.hasStudy() ? &m_document.study() : nullptr);
    const QString name = m_document.hasStudy() ? QString::fromStdString(m_document.study().name()) : tr("No study");
    const bool readOnly = m_document.hasStudy() && m_document.study().isReadOnly();
    setWindowTitle(readOnly ? tr("%1 (read-only) - VascuSim").arg(name) : tr("%1[*] - VascuSim").arg(name));
    setWindowModified(m_document.isModified());
    refreshPatientOverlay();
}

void MainWindow::refreshPatientOverlay()
{
    // The slice views' top-left corner, as on a reading workstation: patient (name, ID), study (date,
    // description), series (the newest image's name). Shown on screen only, never logged.
    QStringList lines;
    if (m_document.hasStudy())
    {
        const auto& metadata = m_document.study().metadata();
        const auto value = [&](const char* key) {
            const auto found = metadata.find(key);
            return found == metadata.end() ? QString() : QString::fromStdString(found->second).trimmed();
        };
        QString patient = value("patient_name").replace('^', ' ').simplified();
        if (!value("patient_id").isEmpty())
            patient += (patient.isEmpty() ? "" : "  ") + tr("ID %1").arg(value("patient_id"));
        lines << patient << (value("study_date") + "  " + value("study_description")).trimmed();
        if (const std::string image = newestArtifact(study::ArtifactKind::Image); !image.empty())
            lines << QString::fromStdString(storedTextForPeople(m_document.study().artifact(image).name));
    }
    lines.removeAll(QString());
    m_views->setPatientText(lines.join('\n'));
}

QString MainWindow::artifactKindText(study::ArtifactKind kind)
{
    switch (kind)
    {
    case study::ArtifactKind::Image: return tr("image");
    case study::ArtifactKind::Label: return tr("label");
    case study::ArtifactKind::Surface: return tr("surface");
    case study::ArtifactKind::TetMesh: return tr("volume mesh");
    case study::ArtifactKind::Skeleton: return tr("skeleton");
    case study::ArtifactKind::Network: return tr("network");
    case study::ArtifactKind::Report: return tr("report");
    case study::ArtifactKind::Run: return tr("run");
    case study::ArtifactKind::Measurement: return tr("measurement");
    }
    return QString::fromStdString(study::kindName(kind));
}

void MainWindow::refreshArtifactTree()
{
    const QSignalBlocker quiet(m_artifactTree); // the check boxes are set here, not by the user
    m_artifactTree->clear();
    if (!m_document.hasStudy())
        return;
    for (const study::Artifact& artifact : m_document.study().artifacts())
    {
        auto* item = new QTreeWidgetItem(m_artifactTree);
        item->setText(0, QString::fromStdString(storedTextForPeople(artifact.name)));
        if (isShowable(artifact))
            item->setCheckState(0, isArtifactShown(artifact.id) ? Qt::Checked : Qt::Unchecked);
        item->setText(1, artifactKindText(artifact.kind));
        item->setData(0, Qt::UserRole, QString::fromStdString(artifact.id));
        if (artifact.damaged)
        {
            item->setText(2, tr("damaged"));
            item->setToolTip(2, QString::fromStdString(artifact.damage));
        }
        else if (!artifact.warnings.empty())
        {
            item->setText(2, tr("%n warning(s)", nullptr, static_cast<int>(artifact.warnings.size())));
            QStringList warnings;
            for (const std::string& warning : artifact.warnings)
                warnings << QString::fromStdString(storedTextForPeople(warning));
            item->setToolTip(2, warnings.join('\n'));
        }
        item->setToolTip(0, tr("%1, made by \"%2\" on %3")
                                .arg(QString::fromStdString(artifact.id))
                                .arg(QString::fromStdString(artifact.provenance.command))
                                .arg(QString::fromStdString(artifact.provenance.time)));
    }
}

void MainWindow::showError(const QString& title, const QString& message)
{
    auto* box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open(); // non-blocking: the window stays usable
    statusBar()->showMessage(tr("%1 failed").arg(title), 10000);
}

MainWindow* MainWindow::windowForNewDocument()
{
    if (!m_document.hasStudy())
        return this;
    auto* window = new MainWindow();
    window->show();
    return window;
}

study::Access MainWindow::askHowToOpenLockedStudy(const QString& bundle, bool& breakLock)
{
    breakLock = false;
    const study::LockHolder holder = study::StudyLock::currentHolder(bundle.toStdString());
    if (holder.pid == 0)
        return study::Access::Write;
    const QString who = QString::fromStdString(holder.describe());
    if (!holder.isOtherHost()) // the kernel holds the lock for a live process here: never broken
    {
        statusBar()->showMessage(tr("Opened read-only: the study is being written by %1").arg(who), 15000);
        return study::Access::ReadOnly;
    }
    // A network share: the holder may have died on its host. Only the user can tell; nothing is broken silently.
    QMessageBox box(QMessageBox::Warning, tr("Study in use"),
                    tr("The study is being written by %1.\nOpen it read-only, or break the lock if you are sure that "
                       "program no longer runs.").arg(who),
                    QMessageBox::NoButton, this);
    QPushButton* readOnly = box.addButton(tr("Open Read-Only"), QMessageBox::AcceptRole);
    QPushButton* breakButton = box.addButton(tr("Break the Lock..."), QMessageBox::DestructiveRole);
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(readOnly);
    box.exec();
    if (box.clickedButton() == breakButton &&
        QMessageBox::question(this, tr("Break the lock"),
                              tr("If %1 still runs, both programs will write the study and results can be lost. "
                                 "Break the lock?").arg(who),
                              QMessageBox::Yes | QMessageBox::No, QMessageBox::No) == QMessageBox::Yes)
    {
        breakLock = true;
        return study::Access::Write;
    }
    if (box.clickedButton() == readOnly)
        return study::Access::ReadOnly;
    throw Cancelled();
}

bool MainWindow::openStudy(const QString& bundle)
{
    bool breakLock = false;
    study::Access access = study::Access::Write;
    try
    {
        access = askHowToOpenLockedStudy(bundle, breakLock);
    }
    catch (const Cancelled&)
    {
        return false;
    }
    auto opened = std::make_shared<std::optional<study::Study>>();
    auto image = std::make_shared<CtVolume>();
    return m_tasks.run(
        tr("Open study"),
        [path = bundle.toStdString(), opened, image, access, breakLock](const Progress& progress) {
            progress.report(0.0, "checking the study's files");
            opened->emplace(breakLock ? study::Study::openBreakingLock(path) : study::Study::open(path, access));
            progress.report(0.5, "loading the image");
            for (const study::Artifact& artifact : (*opened)->artifacts())
                if (artifact.kind == study::ArtifactKind::Image && !artifact.damaged)
                    *image = (*opened)->loadImage(artifact.id);
            progress.report(1.0, "opened");
        },
        [this, bundle, opened, image] {
            const std::vector<std::string> warnings = (*opened)->openWarnings();
            m_views->showImage(*image); // first: the study's saved view state then applies over it
            m_document.setStudy(std::move(**opened));
            rememberRecent(bundle);
            if (!warnings.empty())
            {
                QStringList lines;
                for (const std::string& warning : warnings)
                    lines << QString::fromStdString(storedTextForPeople(warning));
                showError(tr("Study opened with problems"), lines.join('\n'));
            }
        });
}

bool MainWindow::newStudy(const QString& bundle)
{
    try
    {
        study::Study created = study::Study::create(bundle.toStdString(), QFileInfo(bundle).completeBaseName().toStdString());
        created.save();
        m_views->showImage(CtVolume());
        m_document.setStudy(std::move(created));
        rememberRecent(bundle);
        setBusy(false);
        return true;
    }
    catch (const std::exception& error)
    {
        showError(tr("New study"), QString::fromStdString(textForPeople(error)));
        return false;
    }
}

bool MainWindow::saveStudy()
{
    if (!m_document.hasStudy() || m_tasks.isBusy())
        return false;
    keepViewStateInStudy();
    return m_tasks.run(
        tr("Save study"), [this](const Progress& progress) {
            progress.report(0.0, "writing the study");
            m_document.study().save(); // widgets do not edit the study while a task runs (actions disabled)
        },
        [this] { m_document.markSaved(); });
}

bool MainWindow::saveStudyAs(const QString& bundle)
{
    if (!m_document.hasStudy() || m_tasks.isBusy())
        return false;
    keepViewStateInStudy();
    return m_tasks.run(
        tr("Save study as"),
        [this, path = bundle.toStdString()](const Progress& progress) {
            progress.report(0.0, "copying the study");
            m_document.study().saveAs(path);
        },
        [this, bundle] {
            m_document.markSaved();
            rememberRecent(bundle);
        });
}

void MainWindow::showImageArtifact(const std::string& id)
{
    try
    {
        m_views->showImage(m_document.study().loadImage(id));
    }
    catch (const std::exception& error)
    {
        showError(tr("Show image"), QString::fromStdString(textForPeople(error)));
    }
}

void MainWindow::rememberRecent(const QString& bundle)
{
    QSettings settings;
    QStringList recent = settings.value("recentStudies").toStringList();
    recent.removeAll(bundle);
    recent.prepend(bundle);
    while (recent.size() > 8)
        recent.removeLast();
    settings.setValue("recentStudies", recent);
    rebuildRecentMenu();
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (m_tasks.isBusy())
    {
        m_tasks.cancel();
        m_tasks.waitForFinished();
    }
    if (m_document.isModified())
    {
        const auto answer = QMessageBox::question(this, tr("Unsaved changes"),
                                                  tr("Save the changes to this study before closing?"),
                                                  QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
        if (answer == QMessageBox::Cancel)
            return event->ignore();
        if (answer == QMessageBox::Save)
        {
            try
            {
                keepViewStateInStudy();
                m_document.study().save();
            }
            catch (const std::exception& error)
            {
                showError(tr("Save study"), QString::fromStdString(textForPeople(error)));
                return event->ignore();
            }
        }
    }
    QSettings().setValue("mainWindow/geometry", saveGeometry());
    QSettings().setValue("mainWindow/state", saveState());
    event->accept();
}

} // namespace vsim::gui
