#include "vsim/imaging/VesselMeasurements.h"

#include "vsim/core/Localized.h"
#include "vsim/core/Median.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::imaging {
namespace {

/// The lumen indicator (label == 1) interpolated trilinearly at a patient position; 0 outside the volume.
double lumenAt(const LabelVolume& label, const Eigen::Vector3d& patient)
{
    const Eigen::Vector3d index = label.geometry().patientToIndex(patient);
    const Eigen::Vector3d base = index.array().floor();
    const Eigen::Vector3d f = index - base;
    double value = 0;
    for (int corner = 0; corner < 8; ++corner)
    {
        const int i = int(base.x()) + (corner & 1), j = int(base.y()) + ((corner >> 1) & 1), k = int(base.z()) + ((corner >> 2) & 1);
        if (!label.geometry().contains(i, j, k) || label.at(i, j, k) != 1)
            continue;
        value += ((corner & 1) ? f.x() : 1 - f.x()) * (((corner >> 1) & 1) ? f.y() : 1 - f.y()) *
                 (((corner >> 2) & 1) ? f.z() : 1 - f.z());
    }
    return value;
}

/// The lumen section through `centre` perpendicular to `tangent`, within `reach` mm, sampled every `step` mm;
/// only the part connected to the centre counts.
CrossSection sectionAt(const LabelVolume& label, const Eigen::Vector3d& centre, const Eigen::Vector3d& tangent,
                       double reach, double step)
{
    const Eigen::Vector3d t = tangent.normalized();
    const Eigen::Vector3d u = t.unitOrthogonal(), v = t.cross(u);
    const int half = int(std::ceil(reach / step)), size = 2 * half + 1;
    std::vector<std::uint8_t> inside(std::size_t(size) * size), kept(inside.size(), 0);
    for (int b = 0; b < size; ++b)
        for (int a = 0; a < size; ++a)
            inside[std::size_t(b) * size + a] = lumenAt(label, centre + (a - half) * step * u + (b - half) * step * v) >= 0.5;
    // The component of the centre (or of the nearest inside sample within two steps).
    std::vector<int> stack;
    for (int r = 0; r <= 2 && stack.empty(); ++r)
        for (int b = half - r; b <= half + r && stack.empty(); ++b)
            for (int a = half - r; a <= half + r && stack.empty(); ++a)
                if (inside[std::size_t(b) * size + a])
                    stack.push_back(b * size + a);
    CrossSection section;
    section.centre = centre;
    std::vector<Eigen::Vector2d> cells;
    while (!stack.empty())
    {
        const int cell = stack.back();
        stack.pop_back();
        if (kept[std::size_t(cell)])
            continue;
        kept[std::size_t(cell)] = 1;
        const int a = cell % size, b = cell / size;
        cells.push_back(Eigen::Vector2d((a - half) * step, (b - half) * step));
        const int next[4][2] = {{a - 1, b}, {a + 1, b}, {a, b - 1}, {a, b + 1}};
        for (const auto& n : next)
            if (n[0] >= 0 && n[1] >= 0 && n[0] < size && n[1] < size && inside[std::size_t(n[1]) * size + n[0]] &&
                !kept[std::size_t(n[1]) * size + n[0]])
                stack.push_back(n[1] * size + n[0]);
    }
    section.areaMm2 = double(cells.size()) * step * step;
    section.equivalentDiameterMm = 2.0 * std::sqrt(section.areaMm2 / std::numbers::pi);
    if (cells.empty())
        return section;
    section.minDiameterMm = 1e300;
    for (int degrees = 0; degrees < 180; degrees += 3)
    {
        const Eigen::Vector2d direction(std::cos(degrees * std::numbers::pi / 180), std::sin(degrees * std::numbers::pi / 180));
        double low = 1e300, high = -1e300;
        for (const Eigen::Vector2d& cell : cells)
        {
            const double projection = cell.dot(direction);
            low = std::min(low, projection), high = std::max(high, projection);
        }
        const double width = high - low + step;
        section.minDiameterMm = std::min(section.minDiameterMm, width);
        section.maxDiameterMm = std::max(section.maxDiameterMm, width);
    }
    return section;
}

constexpr double kRoundness = 0.8; // smallest / largest caliper width of a section that counts as round

} // namespace

std::vector<ParameterSpec> measurementParameters()
{
    const std::string group = "Measurements";
    return {
        {"section_step_mm", "Section spacing", "mm", 1.0, 0.1, 20, group, "Distance between cross-sections."},
        {"junction_clearance_mm", "Junction clearance", "mm", 1.0, 0, 50, group,
         "Sections closer than 1.5 junction radii plus this to a junction, or this to a segment end, are left out "
         "of the figures (branches distort them)."},
    };
}

VesselMeasurements measureVessels(const LabelVolume& label, const SkeletonGraph& centerlines, const ParameterSet& p,
                                  const Progress& progress)
{
    if (centerlines.edges.empty())
        throw Error("no centerlines to measure: run vascusim-cli centerline first");
    const double stepMm = p.get("section_step_mm"), clearance = p.get("junction_clearance_mm");
    const double sample = 0.5 * label.geometry().spacing.minCoeff();
    // Junctions and the largest radius at each.
    std::vector<double> junctionRadius(centerlines.nodes.size(), 0.0);
    for (const SkeletonGraph::Edge& edge : centerlines.edges)
    {
        junctionRadius[std::size_t(edge.from)] = std::max(junctionRadius[std::size_t(edge.from)], edge.radii.front());
        junctionRadius[std::size_t(edge.to)] = std::max(junctionRadius[std::size_t(edge.to)], edge.radii.back());
    }
    VesselMeasurements result;
    for (std::size_t e = 0; e < centerlines.edges.size(); ++e)
    {
        const SkeletonGraph::Edge& edge = centerlines.edges[e];
        SegmentMeasurements segment;
        segment.from = edge.from;
        segment.to = edge.to;
        segment.lengthMm = edge.length();
        double arc = 0, nextSection = 0;
        for (std::size_t i = 0; i < edge.points.size(); ++i)
        {
            if (i > 0)
                arc += (edge.points[i] - edge.points[i - 1]).norm();
            if (arc + 1e-9 < nextSection)
                continue;
            nextSection += stepMm;
            const Eigen::Vector3d tangent =
                edge.points[std::min(i + 1, edge.points.size() - 1)] - edge.points[i > 0 ? i - 1 : 0];
            if (tangent.norm() < 1e-9)
                continue;
            CrossSection section = sectionAt(label, edge.points[i], tangent, 2.5 * edge.radii[i] + 3.0, sample);
            section.arcLengthMm = arc;
            for (int node : {edge.from, edge.to})
                if (centerlines.degree(node) >= 3 &&
                    (edge.points[i] - centerlines.nodes[std::size_t(node)].position).norm() <
                        1.5 * junctionRadius[std::size_t(node)] + clearance)
                    section.nearJunction = true;
            if (arc < clearance || segment.lengthMm - arc < clearance)
                section.nearJunction = true;
            segment.sections.push_back(section);
        }
        std::vector<double> diameters, areas;
        for (const CrossSection& section : segment.sections)
            if (!section.nearJunction && section.areaMm2 > 0)
            {
                diameters.push_back(section.equivalentDiameterMm);
                areas.push_back(section.areaMm2);
                // The maximum diameter comes from round sections only: an elongated one is cut obliquely or
                // holds part of a branch, and its caliper width is not a vessel diameter.
                if (section.minDiameterMm >= kRoundness * section.maxDiameterMm)
                {
                    segment.maxDiameterMm = std::max(segment.maxDiameterMm, section.equivalentDiameterMm);
                    segment.maxCaliperMm = std::max(segment.maxCaliperMm, section.maxDiameterMm);
                }
            }
        if (!diameters.empty())
        {
            segment.referenceDiameterMm = median(diameters, 0.0);
            segment.minimalDiameterMm = *std::min_element(diameters.begin(), diameters.end());
            segment.diameterStenosisPercent = 100.0 * (1.0 - segment.minimalDiameterMm / segment.referenceDiameterMm);
            segment.areaStenosisPercent =
                100.0 * (1.0 - *std::min_element(areas.begin(), areas.end()) / median(areas, 0.0));
            const auto first = std::find_if(segment.sections.begin(), segment.sections.end(),
                                            [](const CrossSection& s) { return !s.nearJunction && s.areaMm2 > 0; });
            const auto last = std::find_if(segment.sections.rbegin(), segment.sections.rend(),
                                           [](const CrossSection& s) { return !s.nearJunction && s.areaMm2 > 0; });
            segment.startRadiusMm = 0.5 * first->equivalentDiameterMm;
            segment.endRadiusMm = 0.5 * last->equivalentDiameterMm;
        }
        result.maxDiameterMm = std::max(result.maxDiameterMm, segment.maxDiameterMm);
        result.maxCaliperMm = std::max(result.maxCaliperMm, segment.maxCaliperMm);
        if (result.worstStenosisSegment < 0 ||
            segment.diameterStenosisPercent > result.segments[std::size_t(result.worstStenosisSegment)].diameterStenosisPercent)
            result.worstStenosisSegment = int(result.segments.size());
        result.segments.push_back(std::move(segment));
        progress.report(double(e + 1) / double(centerlines.edges.size()), localized("vsim::Progress", "measuring"));
    }
    return result;
}

} // namespace vsim::imaging
