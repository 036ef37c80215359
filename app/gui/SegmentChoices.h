#pragma once

// The centerline segments as a choice (the vessel view's and the endoscope's): "name (length mm)", the edge
// index as the item's data.
#include "vsim/core/SkeletonGraph.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QSignalBlocker>

#include <optional>
#include <string>
#include <vector>

namespace vsim::gui {

/// Fills `choices` with the segments of two points or more, named by `names` (anatomical, or "segment N");
/// returns the longest segment's edge index, -1 when there is none.
inline int fillSegmentChoices(QComboBox* choices, const SkeletonGraph& centerlines,
                              const std::vector<std::string>& names)
{
    choices->clear();
    int longest = -1;
    for (std::size_t e = 0; e < centerlines.edges.size(); ++e)
    {
        if (centerlines.edges[e].points.size() < 2)
            continue;
        const QString name =
            e < names.size() && !names[e].empty()
                ? QString::fromStdString(names[e])
                : QCoreApplication::translate("vsim::gui::VesselViewPanel", "segment %1").arg(e + 1);
        choices->addItem(QCoreApplication::translate("vsim::gui::VesselViewPanel", "%1 (%2 mm)")
                             .arg(name)
                             .arg(centerlines.edges[e].length(), 0, 'f', 0),
                         int(e));
        if (longest < 0 || centerlines.edges[e].length() > centerlines.edges[std::size_t(longest)].length())
            longest = int(e);
    }
    return longest;
}

/// Shows `edge` as the current choice without announcing it (the owner changed the segment itself).
inline void showSegmentChoice(QComboBox* choices, int edge)
{
    if (const int index = choices->findData(edge); index >= 0 && index != choices->currentIndex())
    {
        const QSignalBlocker quiet(choices);
        choices->setCurrentIndex(index);
    }
}

/// The frames of segment `edge` every `stepMm`; none for an edge out of range or shorter than one step.
inline std::optional<imaging::CenterlineFrames> segmentFrames(const SkeletonGraph& centerlines, int edge, double stepMm)
{
    if (edge < 0 || std::size_t(edge) >= centerlines.edges.size())
        return std::nullopt;
    const SkeletonGraph::Edge& chosen = centerlines.edges[std::size_t(edge)];
    try
    {
        return imaging::centerlineFrames(chosen.points, chosen.radii, stepMm);
    }
    catch (const std::exception&)
    {
        return std::nullopt; // shorter than one step
    }
}

} // namespace vsim::gui
