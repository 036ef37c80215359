// The wall-mechanics steps of the workflow: the wall mesh around the newest centerlines and the lumen label they were
// traced from, and the
// wall runs (physiological wall stress with the rupture index, the thesis rupture protocol) in the task runner,
// added to the study (undoable) and shown in 3D coloured by stress with a legend.

#include "ArtifactCommands.h"
#include "InteractiveWall.h"
#include "MainWindow.h"
#include "ParameterForm.h"
#include "ViewLayout.h"
#include "vsim/app/RunRecord.h"
#include "vsim/app/SacRecord.h"
#include "vsim/app/WallPipeline.h"
#include "vsim/sim/fem/FemProtocols.h"
#include "vsim/viz/DecimalText.h"
#include "vsim/viz/VolumeView3D.h"

#include <QCheckBox>
#include <QDockWidget>
#include <QFormLayout>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSlider>
#include <QStatusBar>

#include <algorithm>
#include <optional>
#include <cstdlib>

namespace vsim::gui {

void MainWindow::createWallMenu()
{
    m_wallMeshParameters = ParameterSet(app::wallMeshParameters());
    m_femParameters = ParameterSet(sim::fem::femParameters());
    QMenu* wall = menuBar()->addMenu(tr("&Wall"));
    m_documentActions << wall->addAction(tr("Build &Wall Mesh"), this, [this] { buildWallMesh(); });
    m_documentActions << wall->addAction(tr("Wall Stress at &Blood Pressure"), this,
                                         [this] { simulateWall("physiological"); });
    m_documentActions << wall->addAction(tr("&Interactive Protocol"), this, [this] { startInteractiveWall(); });
    wall->addSeparator();
    m_documentActions << wall->addAction(tr("Wall &Parameters..."), this, [this] {
        editParametersInDialog(this, tr("Wall parameters"),
                               {{tr("Wall mesh"), &m_wallMeshParameters}, {tr("Wall mechanics"), &m_femParameters}});
    });
    // The thesis's experiment: pressures of 8-12 MPa, about 600 times systolic. A reproduction for research, kept
    // apart from the clinical analyses.
    QMenu* research = menuBar()->addMenu(tr("&Research"));
    m_documentActions << research->addAction(tr("&Thesis Rupture Protocol (not physiological pressures)"), this,
                                             [this] { simulateWall("thesis-rupture"); });
}

bool MainWindow::buildWallMesh()
{
    if (!m_document.hasStudy())
        return false;
    const std::string centerlinesId = m_document.study().newestArtifact(study::ArtifactKind::Skeleton, "centerline");
    // The lumen the centerlines were traced from (not the newest label: that may be the AAA sac's).
    const std::string labelId = centerlinesId.empty() ? std::string() : app::lumenLabelOfCenterlines(m_document.study(), centerlinesId);
    if (labelId.empty() || centerlinesId.empty())
    {
        showError(tr("Wall mesh"), tr("The wall needs a vessel label and centerlines: run Segment and Skeleton && "
                                      "Centerlines first."));
        return false;
    }
    std::string sacId;
    if (m_wallMeshParameters.get("thrombus_layer") > 0.5)
    {
        app::newestSacFigures(m_document.study(), &sacId);
        if (sacId.empty())
        {
            showError(tr("Wall mesh"), tr("The thrombus layer needs the AAA sac: run Vessels > AAA Sac first, or set "
                                          "Thrombus layer to 0 in the wall mesh parameters."));
            return false;
        }
    }
    auto build = std::make_shared<app::WallMeshBuild>();
    const double thickness = m_wallMeshParameters.get("thickness_mm"), budget = m_wallMeshParameters.get("target_vertices");
    return m_tasks.run(
        tr("Wall mesh"),
        [this, labelId, centerlinesId, sacId, thickness, budget, build](const Progress& progress) {
            const std::optional<LabelVolume> sacLabels =
                sacId.empty() ? std::nullopt : std::optional<LabelVolume>(m_document.study().loadLabel(sacId));
            *build = app::buildWallMesh(m_document.study().loadLabel(labelId),
                                        m_document.study().loadSkeleton(centerlinesId), thickness, budget, progress,
                                        sacLabels ? &*sacLabels : nullptr);
        },
        [this, labelId, centerlinesId, sacId, thickness, budget, build] {
            const std::string id =
                app::addWallMesh(m_document.study(), *build, labelId, centerlinesId, thickness, budget, sacId);
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Wall mesh")));
            statusBar()->showMessage(tr("Wall: %1 elements, smallest dihedral angle %2 deg")
                                         .arg(build->wall.mesh.tets.size())
                                         .arg(viz::decimalText(build->wall.minDihedralDeg, 1)),
                                     8000);
        });
}

bool MainWindow::simulateWall(const std::string& protocol)
{
    if (!m_document.hasStudy())
        return false;
    const std::string wallId = m_document.study().newestArtifact(study::ArtifactKind::TetMesh, "mesh wall");
    const std::string centerlinesId = m_document.study().newestArtifact(study::ArtifactKind::Skeleton, "centerline");
    if (wallId.empty() || (protocol == "physiological" && centerlinesId.empty()))
    {
        showError(tr("Wall mechanics"), tr("Build the wall mesh first (Wall > Build Wall Mesh)."));
        return false;
    }
    auto run = std::make_shared<sim::fem::FemRunResult>();
    const ParameterSet parameters = m_femParameters;
    const app::WallBackend backend = app::chooseWallBackend("auto", protocol, parameters); // the GPU when there is one
    return m_tasks.run(
        protocol == "physiological" ? tr("Wall stress") : tr("Thesis rupture protocol"),
        [this, protocol, wallId, centerlinesId, parameters, backend, run](const Progress& progress) {
            *run = app::runWallProtocol(m_document.study(), protocol, wallId, centerlinesId, parameters, backend, progress);
        },
        [this, protocol, wallId, centerlinesId, parameters, backend, run] {
            const app::WallRunIds ids =
                app::addWallRun(m_document.study(), *run, protocol, wallId,
                                protocol == "physiological" ? centerlinesId : std::string(), parameters, backend);
            const std::string& id = ids.stress;
            m_scene.wallFrames[id] = run->frames.back();
            m_document.undoStack()->push(
                new AddedArtifactCommand(m_document, std::vector<std::string>{ids.run, ids.stress}, tr("Wall stress")));
            if (const std::string warning = app::runStatusWarning(run->status); !warning.empty())
                showError(tr("Wall mechanics"),
                          tr("Read these results with care: %1").arg(QString::fromStdString(warning)));
            else if (protocol == "physiological")
            {
                // The sac's figures when the study has a sac; the rupture index only when sex and family history
                // were given.
                const auto& m = run->metrics;
                const bool sac = m.count("sac_pws_p99_kpa") > 0;
                QString text = sac ? tr("Peak wall stress in the sac %1 kPa (99th percentile)")
                                         .arg(viz::decimalText(m.at("sac_pws_p99_kpa"), 0))
                                   : tr("Highest wall stress %1 kPa (no sac measured)")
                                       .arg(viz::decimalText(m.at("peak_von_mises_kpa"), 0));
                if (sac && m.count("sac_pwri_p99"))
                    text += tr(", rupture index %1").arg(viz::decimalText(m.at("sac_pwri_p99"), 2));
                else if (!m.count("peak_rupture_index"))
                    text += tr("; no rupture index: give the patient's sex and family history");
                statusBar()->showMessage(text, 10000);
            }
        });
}

void MainWindow::showWallStress(const TetMesh& frame, const study::Artifact& run)
{
    const RunStatus status = app::runStatusOf(run);
    const TriangleMesh surface = app::frameSurface(frame, "von_mises_kpa");
    const auto& stress = surface.pointFields.at("von_mises_kpa");
    double high = stress.empty() ? 1.0 : *std::max_element(stress.begin(), stress.end());
    // The colour scale covers the sac's figures (the surface average runs below the element peaks), as the report's.
    for (const char* key : {"sac_pws_p99_kpa", "sac_pws_nodal_max_kpa"})
        if (const auto figure = run.attributes.find(key); figure != run.attributes.end())
            high = std::max(high, std::atof(figure->second.c_str()));
    viz::VolumeView3D* view = m_views->volumeView();
    view->clearSurfaces();
    view->clearLines();
    view->setVolumeVisible(false);
    const QString title = !status.converged()  ? tr("von Mises (kPa), NOT CONVERGED")
                          : !status.complete() ? tr("von Mises (kPa), STOPPED EARLY")
                                               : tr("von Mises (kPa)");
    view->showFieldSurface(surface, "von_mises_kpa", 0.0, std::max(high, 1e-6), title);
    view->showCallouts(app::sacPeakCallouts(run)); // where the sac's PWS and PWRI are
}

bool MainWindow::startInteractiveWall()
{
    if (!m_document.hasStudy())
        return false;
    const std::string wallId = m_document.study().newestArtifact(study::ArtifactKind::TetMesh, "mesh wall");
    if (wallId.empty())
    {
        showError(tr("Wall mechanics"), tr("Build the wall mesh first (Wall > Build Wall Mesh)."));
        return false;
    }
    stopInteractiveWall();
    m_drawnScene.clear(); // the protocol draws its own frame: the study's scene is drawn again when it closes
    const sim::fem::ElasticMaterial material = sim::fem::femMaterial(m_femParameters);
    const sim::fem::BackwardEulerSettings settings = sim::fem::femIntegrator(m_femParameters);
    viz::VolumeView3D* view = m_views->volumeView();
    try
    {
        view->clearSurfaces();
        view->clearLines();
        view->setVolumeVisible(false);
        m_interactiveWall = new InteractiveWall(m_document.study().loadTetMesh(wallId), material, settings, view, this);
    }
    catch (const std::exception& error)
    {
        showError(tr("Wall mechanics"), QString::fromStdString(textForPeople(error)));
        return false;
    }
    view->setDragEnabled(true);
    connect(view, &viz::VolumeView3D::pointGrabbed, m_interactiveWall, &InteractiveWall::grab);
    connect(view, &viz::VolumeView3D::pointDragged, m_interactiveWall, &InteractiveWall::dragTo);
    connect(view, &viz::VolumeView3D::pointReleased, m_interactiveWall, &InteractiveWall::release);

    auto* panel = new QWidget(this);
    auto* form = new QFormLayout(panel);
    auto* play = new QPushButton(tr("Play"), panel);
    play->setObjectName("interactivePlay");
    play->setCheckable(true);
    auto* pressure = new QSlider(Qt::Horizontal, panel);
    pressure->setObjectName("interactivePressure");
    pressure->setRange(0, 300);
    auto* pressureLabel = new QLabel(tr("0 mmHg"), panel);
    auto* tearing = new QCheckBox(tr("Tear at %1 MPa").arg(m_femParameters.get("tear_strength_mpa")), panel);
    auto* status = new QLabel(panel);
    form->addRow(play);
    form->addRow(tr("Pressure"), pressure);
    form->addRow(QString(), pressureLabel);
    form->addRow(tearing);
    form->addRow(status);
    form->addRow(new QLabel(tr("Drag the wall with the left button in the 3D view."), panel));
    connect(play, &QPushButton::toggled, this, [this, play](bool on) {
        on ? m_interactiveWall->play() : m_interactiveWall->pause();
        play->setText(on ? tr("Pause") : tr("Play"));
    });
    connect(pressure, &QSlider::valueChanged, this, [this, pressureLabel](int mmHg) {
        m_interactiveWall->setPressureMmHg(mmHg);
        pressureLabel->setText(tr("%1 mmHg").arg(mmHg));
    });
    const double strength = m_femParameters.get("tear_strength_mpa");
    connect(tearing, &QCheckBox::toggled, this, [this, strength](bool on) { m_interactiveWall->setTearStrengthMpa(on ? strength : 0.0); });
    connect(m_interactiveWall, &InteractiveWall::frameShown, status, [status](double fps, double peak) {
        status->setText(tr("%1 frames/s, peak von Mises %2 kPa")
            .arg(viz::decimalText(fps, 0))
            .arg(viz::decimalText(peak, 1)));
    });
    connect(m_interactiveWall, &InteractiveWall::stopped, this, [this, play](const QString& reason) {
        play->setChecked(false);
        showError(tr("Wall mechanics"), tr("The simulation paused: %1").arg(reason));
    });
    m_interactiveDock = new QDockWidget(tr("Interactive Wall"), this);
    m_interactiveDock->setObjectName("interactiveWallDock");
    m_interactiveDock->setWidget(panel);
    addDockWidget(Qt::RightDockWidgetArea, m_interactiveDock);
    return true;
}

void MainWindow::stopInteractiveWall()
{
    if (!m_interactiveWall)
        return;
    m_interactiveWall->pause();
    m_views->volumeView()->setDragEnabled(false);
    m_interactiveWall->deleteLater();
    m_interactiveWall = nullptr;
    if (m_interactiveDock)
    {
        m_interactiveDock->deleteLater();
        m_interactiveDock = nullptr;
    }
    refreshScene(); // back to what the study holds: the interactive frame was never saved
}

} // namespace vsim::gui
