// SegmentChoices.h: the choices, the inlet's paths (depth first over the tree) and their joined frames.
#include "SegmentChoices.h"
#include "vsim/core/StoredText.h"
#include "vsim/imaging/VesselNames.h"
#include "vsim/viz/DecimalText.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QSignalBlocker>

#include <algorithm>
#include <cstdlib>

namespace vsim::gui {

QString segmentName(const SkeletonGraph& centerlines, const std::vector<std::string>& names, std::size_t e)
{
    // A segment without a name (none, or the automatic naming's "unnamed") goes by its number.
    return e < names.size() && !names[e].empty() && names[e] != imaging::kUnnamedSegment
               ? QString::fromStdString(storedTextForPeople(names[e])) // an anatomical name in the reader's language
               : QCoreApplication::translate("vsim::gui::VesselViewPanel", "segment %1").arg(e + 1);
}

std::vector<std::pair<VesselPath, double>> inletPaths(const SkeletonGraph& centerlines, std::size_t limit)
{
    int inlet = -1;
    double widest = -1.0;
    for (const SkeletonGraph::Edge& edge : centerlines.edges)
    {
        if (edge.radii.empty())
            continue;
        for (const auto& [node, radius] :
             {std::pair{edge.from, edge.radii.front()}, std::pair{edge.to, edge.radii.back()}})
            if (centerlines.degree(node) == 1 && radius > widest)
                widest = radius, inlet = node;
    }
    std::vector<std::pair<VesselPath, double>> paths;
    if (inlet < 0)
        return paths;
    // Depth-first from the inlet over the tree (a cycle's edge is walked once).
    std::vector<char> used(centerlines.edges.size(), 0);
    std::vector<std::pair<int, std::pair<VesselPath, double>>> open{{inlet, {}}};
    while (!open.empty())
    {
        auto [node, path] = open.back();
        open.pop_back();
        bool extended = false;
        for (std::size_t e = 0; e < centerlines.edges.size(); ++e)
        {
            const SkeletonGraph::Edge& edge = centerlines.edges[e];
            if (used[e] || edge.points.size() < 2 || (edge.from != node && edge.to != node))
                continue;
            used[e] = 1;
            extended = true;
            auto next = path;
            next.first.append(edge.from == node ? int(e) + 1 : -(int(e) + 1));
            next.second += edge.length();
            open.emplace_back(edge.from == node ? edge.to : edge.from, next);
        }
        if (!extended && path.first.size() >= 2)
            paths.push_back(path);
    }
    std::sort(paths.begin(), paths.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    if (paths.size() > limit)
        paths.resize(limit);
    return paths;
}

int fillSegmentChoices(QComboBox* choices, const SkeletonGraph& centerlines,
                       const std::vector<std::string>& names)
{
    choices->clear();
    int longest = -1;
    double longestMm = -1.0;
    for (std::size_t e = 0; e < centerlines.edges.size(); ++e)
    {
        if (centerlines.edges[e].points.size() < 2)
            continue;
        const double length = centerlines.edges[e].length();
        choices->addItem(QCoreApplication::translate("vsim::gui::VesselViewPanel", "%1 (%2 mm)")
                             .arg(segmentName(centerlines, names, e))
                             .arg(viz::decimalText(length, 0)),
                         VesselPath{int(e) + 1});
        if (length > longestMm)
            longestMm = length, longest = choices->count() - 1;
    }
    for (const auto& [path, length] : inletPaths(centerlines))
    {
        const auto edgeOf = [](const QVariant& step) { return std::size_t(std::abs(step.toInt()) - 1); };
        choices->addItem(QCoreApplication::translate("vsim::gui::VesselViewPanel", "%1 to %2 (%3 mm)")
                             .arg(segmentName(centerlines, names, edgeOf(path.front())),
                                  segmentName(centerlines, names, edgeOf(path.back())))
                             .arg(viz::decimalText(length, 0)),
                         path);
    }
    return longest;
}

void showSegmentChoice(QComboBox* choices, const VesselPath& path)
{
    if (const int index = choices->findData(path); index >= 0 && index != choices->currentIndex())
    {
        const QSignalBlocker quiet(choices);
        choices->setCurrentIndex(index);
    }
}

std::pair<std::vector<Eigen::Vector3d>, std::vector<double>> pathPolyline(const SkeletonGraph& centerlines,
                                                                          const VesselPath& path)
{
    std::vector<Eigen::Vector3d> points;
    std::vector<double> radii;
    for (const QVariant& step : path)
    {
        const int edge = std::abs(step.toInt()) - 1;
        if (edge < 0 || std::size_t(edge) >= centerlines.edges.size())
            return {};
        const SkeletonGraph::Edge& e = centerlines.edges[std::size_t(edge)];
        const bool forwards = step.toInt() > 0;
        for (std::size_t i = 0; i < e.points.size(); ++i)
        {
            const std::size_t at = forwards ? i : e.points.size() - 1 - i;
            if (!points.empty() && i == 0)
                continue; // the junction, shared with the previous segment's end
            points.push_back(e.points[at]);
            radii.push_back(at < e.radii.size() ? e.radii[at] : 0.0);
        }
    }
    return {points, radii};
}

std::optional<imaging::CenterlineFrames> pathFrames(const SkeletonGraph& centerlines, const VesselPath& path,
                                                    double stepMm)
{
    const auto [points, radii] = pathPolyline(centerlines, path);
    if (points.size() < 2)
        return std::nullopt;
    try
    {
        return imaging::centerlineFrames(points, radii, stepMm);
    }
    catch (const std::exception&)
    {
        return std::nullopt; // shorter than one step
    }
}

int singleSegment(const VesselPath& path)
{
    return path.size() == 1 ? std::abs(path.front().toInt()) - 1 : -1;
}

bool adoptPath(const SkeletonGraph& centerlines, const VesselPath& path, double stepMm, QComboBox* choices,
               VesselPath& current, imaging::CenterlineFrames& frames)
{
    if (path == current)
        return false;
    std::optional<imaging::CenterlineFrames> made = pathFrames(centerlines, path, stepMm);
    if (!made)
        return false;
    frames = std::move(*made);
    current = path;
    showSegmentChoice(choices, path);
    return true;
}

} // namespace vsim::gui
