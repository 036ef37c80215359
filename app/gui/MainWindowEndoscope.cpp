// Vessels > Virtual Endoscope (issue 20, item 8): the endoscope dock inside the lumen of the newest
// centerlines' label; the slice views follow the camera; a played flow run's particles fly past it
// (drawRunFrame).
#include "EndoscopePanel.h"
#include "MainWindow.h"
#include "SceneCache.h"
#include "ViewLayout.h"
#include "vsim/app/SacRecord.h"
#include "vsim/app/SegmentNames.h"

#include <QDockWidget>

#include <algorithm>
#include <memory>

namespace vsim::gui {

bool MainWindow::showEndoscope()
{
    const std::string centerlinesId =
        m_document.hasStudy() ? m_document.study().newestArtifact(study::ArtifactKind::Skeleton, "centerline")
                              : std::string();
    const std::string labelId =
        centerlinesId.empty() ? std::string() : app::lumenLabelOfCenterlines(m_document.study(), centerlinesId);
    if (centerlinesId.empty() || labelId.empty())
    {
        showError(tr("Virtual endoscope"),
                  tr("The endoscope flies along a centerline: run Skeleton && Centerlines first."));
        return false;
    }
    if (!m_endoscope)
    {
        m_endoscope = new EndoscopePanel(this);
        connect(m_endoscope, &EndoscopePanel::positionChanged, this,
                [this](const Eigen::Vector3d& p) { m_views->jumpTo(p); });
        m_endoscopeDock = new QDockWidget(tr("Virtual Endoscope"), this);
        m_endoscopeDock->setObjectName("endoscopeDock");
        m_endoscopeDock->setWidget(m_endoscope);
        addDockWidget(Qt::BottomDockWidgetArea, m_endoscopeDock);
        connect(m_endoscopeDock, &QDockWidget::visibilityChanged, this,
                [this](bool visible)
                {
                    if (!visible)
                        m_endoscope->pause();
                });
    }
    // The lumen's display surface: the scene's, else made now in the background.
    auto surface = std::make_shared<TriangleMesh>();
    if (const auto cached = m_scene.lumenSurfaces.find(labelId); cached != m_scene.lumenSurfaces.end())
        *surface = cached->second;
    const bool needsSurface = surface->triangles.empty();
    auto show = [this, surface, centerlinesId, labelId]
    {
        try
        {
            if (!m_scene.lumenSurfaces.count(labelId))
                m_scene.lumenSurfaces[labelId] = *surface;
            const SkeletonGraph centerlines = m_document.study().loadSkeleton(centerlinesId);
            m_endoscope->setData(*surface, centerlines,
                                 app::segmentNames(m_document.study(), centerlinesId, centerlines));
            m_endoscopeDock->show();
            m_endoscopeDock->raise();
            resizeDocks({m_endoscopeDock}, {std::max(360, height() / 3)}, Qt::Vertical);
        }
        catch (const std::exception& error)
        {
            showError(tr("Virtual endoscope"), QString::fromStdString(textForPeople(error)));
        }
    };
    if (!needsSurface)
    {
        show();
        return m_endoscope->hasData();
    }
    return m_tasks.run(
        tr("Virtual endoscope"),
        [this, surface, labelId](const Progress& progress)
        { *surface = displaySurface(m_document.study().loadLabel(labelId), progress); },
        show);
}

} // namespace vsim::gui
