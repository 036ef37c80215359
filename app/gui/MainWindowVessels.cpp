// The vessel steps of the workflow: segmentation, skeleton and centerlines, run in the task runner and added to
// the study as undoable artifacts. The parameters are the declared defaults (the parameter form comes next).

#include "ArtifactCommands.h"
#include "MainWindow.h"
#include "ViewLayout.h"
#include "vsim/imaging/Centerlines.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselSegmentation.h"
#include "vsim/mesh/VesselSurface.h"
#include "vsim/viz/SliceView.h"
#include "vsim/viz/VolumeView3D.h"

#include <QMenu>
#include <QMenuBar>

#include <sstream>

namespace vsim::gui {
namespace {

std::map<std::string, std::string> asText(const ParameterSet& parameters)
{
    std::map<std::string, std::string> text;
    for (const auto& [key, value] : parameters.values())
    {
        std::ostringstream number;
        number << value;
        text[key] = number.str();
    }
    return text;
}

const QColor kLumenColour(220, 60, 50);

} // namespace

void MainWindow::createVesselMenu()
{
    QMenu* vessels = menuBar()->addMenu(tr("V&essels"));
    m_documentActions << vessels->addAction(tr("&Segment Vessels"), this, [this] { segmentVessels(); });
    // Click a vessel in any MPR view (the linked cursor goes there), then segment from that seed.
    m_documentActions << vessels->addAction(tr("Segment from the &Cursor"), this, [this] {
        segmentVessels(m_views->sliceView(viz::SliceOrientation::Axial)->cursor());
    });
    m_documentActions << vessels->addAction(tr("S&keleton and Centerlines"), this,
                                            [this] { extractSkeletonAndCenterlines(); });
}

std::string MainWindow::newestArtifact(study::ArtifactKind kind) const
{
    const auto& artifacts = m_document.study().artifacts();
    for (auto it = artifacts.rbegin(); it != artifacts.rend(); ++it)
        if (it->kind == kind && !it->damaged)
            return it->id;
    return {};
}

bool MainWindow::segmentVessels(const std::optional<Eigen::Vector3d>& seedMm)
{
    if (!m_document.hasStudy())
        return false;
    const std::string imageId = newestArtifact(study::ArtifactKind::Image);
    if (imageId.empty())
    {
        showError(tr("Segment vessels"), tr("The study has no CT image: import one first."));
        return false;
    }
    struct Outcome
    {
        imaging::SegmentationResult segmentation;
        TriangleMesh surface;
        std::map<std::string, std::string> parameters;
    };
    auto outcome = std::make_shared<Outcome>();
    return m_tasks.run(
        tr("Segment vessels"),
        [this, imageId, seedMm, outcome](const Progress& progress) {
            const CtVolume ct = m_document.study().loadImage(imageId); // the study is not edited while a task runs
            const ParameterSet parameters(imaging::segmentationParameters());
            outcome->segmentation = imaging::segmentVessels(ct, parameters, seedMm, progress.subRange(0.0, 0.8));
            outcome->parameters = asText(parameters);
            ParameterSet surface(mesh::surfaceParameters());
            surface.set("target_vertices", 20000); // enough for display
            outcome->surface =
                mesh::extractVesselSurface(outcome->segmentation.label, 1, surface, progress.subRange(0.8, 1.0)).surface;
        },
        [this, imageId, outcome] {
            study::Provenance provenance;
            provenance.command = "segment";
            provenance.inputs = {imageId};
            provenance.parameters = outcome->parameters;
            const Eigen::Vector3d& seed = outcome->segmentation.seedMm;
            provenance.parameters["seed_mm"] = QString("%1,%2,%3").arg(seed.x()).arg(seed.y()).arg(seed.z()).toStdString();
            provenance.parameters["seed_found_automatically"] = outcome->segmentation.seedFound ? "yes" : "no";
            const std::string id = m_document.study().addLabel(outcome->segmentation.label, "Vessel lumen", provenance,
                                                               outcome->segmentation.warnings);
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, id, tr("Segment vessels")));
            m_views->volumeView()->clearSurfaces();
            m_views->volumeView()->addSurface(outcome->surface, kLumenColour);
        });
}

bool MainWindow::extractSkeletonAndCenterlines()
{
    if (!m_document.hasStudy())
        return false;
    const std::string labelId = newestArtifact(study::ArtifactKind::Label);
    if (labelId.empty())
    {
        showError(tr("Skeleton and centerlines"), tr("The study has no vessel label: segment the vessels first."));
        return false;
    }
    struct Outcome
    {
        imaging::SkeletonResult skeleton;
        SkeletonGraph centerlines;
        std::map<std::string, std::string> skeletonParameters, centerlineParameters;
    };
    auto outcome = std::make_shared<Outcome>();
    return m_tasks.run(
        tr("Skeleton and centerlines"),
        [this, labelId, outcome](const Progress& progress) {
            const LabelVolume label = m_document.study().loadLabel(labelId);
            const ParameterSet skeleton(imaging::skeletonParameters()), centerline(imaging::centerlineParameters());
            outcome->skeleton = imaging::extractSkeleton(label, 1, skeleton, progress.subRange(0.0, 0.6));
            outcome->centerlines = imaging::extractCenterlines(label, 1, outcome->skeleton.graph, centerline, std::nullopt,
                                                               progress.subRange(0.6, 1.0));
            outcome->skeletonParameters = asText(skeleton);
            outcome->centerlineParameters = asText(centerline);
        },
        [this, labelId, outcome] {
            study::Provenance skeleton;
            skeleton.command = "skeleton";
            skeleton.inputs = {labelId};
            skeleton.parameters = outcome->skeletonParameters;
            const std::string skeletonId =
                m_document.study().addSkeleton(outcome->skeleton.graph, "Vessel skeleton", skeleton);
            study::Provenance centerline;
            centerline.command = "centerline";
            centerline.inputs = {skeletonId, labelId};
            centerline.parameters = outcome->centerlineParameters;
            const std::string centerlineId =
                m_document.study().addSkeleton(outcome->centerlines, "Centerlines", centerline);
            m_document.undoStack()->beginMacro(tr("Skeleton and centerlines"));
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, skeletonId, tr("Skeleton")));
            m_document.undoStack()->push(new AddedArtifactCommand(m_document, centerlineId, tr("Centerlines")));
            m_document.undoStack()->endMacro();
        });
}

} // namespace vsim::gui
