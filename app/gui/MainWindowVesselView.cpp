// The "3D + CPR" layout (View > Layout, Vessels > Along the Vessel): the vessel view of the newest centerlines on
// the shown CT, with the AAA sac's outer-wall caliper when the sac was measured; moving along it moves the MPRs'
// cursor there.
#include "MainWindow.h"
#include "VesselViewPanel.h"
#include "ViewLayout.h"
#include "vsim/app/SacRecord.h"
#include "vsim/app/SegmentNames.h"
#include "vsim/viz/SliceView.h"

namespace vsim::gui {

bool MainWindow::showVesselView()
{
    const viz::SliceView* axial = m_views->sliceView(viz::SliceOrientation::Axial);
    const std::string centerlinesId =
        m_document.hasStudy() ? m_document.study().newestArtifact(study::ArtifactKind::Skeleton, "centerline") : std::string();
    if (centerlinesId.empty() || !axial->hasImage())
    {
        showError(tr("Along the vessel"), tr("The vessel view follows a centerline: run Skeleton && Centerlines first."));
        return false;
    }
    try
    {
        const SkeletonGraph centerlines = m_document.study().loadSkeleton(centerlinesId);
        VesselViewPanel* panel = m_views->vesselPanel();
        if (!m_vesselViewConnected)
        {
            connect(panel, &VesselViewPanel::positionChanged, this, [this](const Eigen::Vector3d& p) { m_views->jumpTo(p); });
            m_vesselViewConnected = true;
        }
        const auto measured = m_scene.measurements.find(centerlinesId);
        panel->setData(axial->image(), centerlines, app::segmentNames(m_document.study(), centerlinesId, centerlines),
                       measured == m_scene.measurements.end() ? nullptr : &measured->second);
        // The AAA sac's labels, when measured: the cross-section's outer-wall caliper.
        std::string sacId;
        app::newestSacFigures(m_document.study(), &sacId);
        panel->setSacLabels(sacId.empty() ? std::nullopt : std::optional(m_document.study().loadLabel(sacId)));
        m_views->setLayoutMode(LayoutMode::VolumePlusCpr);
        return panel->hasData();
    }
    catch (const std::exception& error)
    {
        showError(tr("Along the vessel"), QString::fromStdString(textForPeople(error)));
        return false;
    }
}

} // namespace vsim::gui
