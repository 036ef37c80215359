#include "vsim/app/FlowWallPressure.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/fem/StaticWallRun.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vsim::app {

FlowWallPressure addFlowWallPressure(const study::Study& study, TetMesh& wall)
{
    FlowWallPressure used;
    used.wallLoadsId = study.newestArtifact(study::ArtifactKind::Surface, "simulate sph");
    if (used.wallLoadsId.empty())
        throw Error("flow_wall_pressure 1 needs a blood-flow run's wall loads in the study (Flow > Blood Flow, or "
                    "vascusim-cli simulate sph, run to its averaging window)");
    const study::Artifact& loads = study.artifact(used.wallLoadsId);
    used.runId = loads.provenance.inputs.empty() ? std::string() : loads.provenance.inputs.front();
    double outletPa = 0.0;
    if (study.hasArtifact(used.runId))
        if (const auto& p = study.artifact(used.runId).provenance.parameters; p.count("outlet_pressure_pa"))
            outletPa = std::stod(p.at("outlet_pressure_pa"));
    const TriangleMesh surface = study.loadSurface(used.wallLoadsId);
    const auto pressure = surface.pointFields.find("wall_pressure_pa");
    const auto layer = wall.pointFields.find("wall_layer");
    if (pressure == surface.pointFields.end())
        throw Error(Pattern{"the wall loads %1 have no wall_pressure_pa", {used.wallLoadsId}});
    if (layer == wall.pointFields.end())
        throw Error("the wall mesh has no wall_layer field: its lumen is not known");

    // The flow's vertices that carry a value (NaN past an open end's plane).
    std::vector<std::size_t> valued;
    for (std::size_t v = 0; v < surface.points.size(); ++v)
        if (std::isfinite(pressure->second[v]))
            valued.push_back(v);
    std::vector<double> added(wall.points.size(), 0.0);
    used.smallestPa = std::numeric_limits<double>::infinity(), used.largestPa = -used.smallestPa;
    for (std::size_t n = 0; n < wall.points.size(); ++n)
    {
        if (layer->second[n] != 0.0)
            continue;
        ++used.lumenPoints;
        // Brute force: some 10^3-10^4 lumen points against at most 20,000 flow vertices, well under a second.
        double nearest2 = kFlowPressureReachMm * kFlowPressureReachMm;
        std::size_t nearest = surface.points.size();
        for (std::size_t v : valued)
            if (const double d2 = (surface.points[v] - wall.points[n]).squaredNorm(); d2 <= nearest2)
                nearest2 = d2, nearest = v;
        if (nearest == surface.points.size())
            continue;
        ++used.coveredPoints;
        added[n] = pressure->second[nearest] - outletPa;
        used.smallestPa = std::min(used.smallestPa, added[n]), used.largestPa = std::max(used.largestPa, added[n]);
    }
    if (used.coveredPoints == 0)
        throw Error(Pattern{"none of the wall's %1 lumen points lies within %2 mm of the blood flow's wall (%3): the "
                            "flow ran through other vessels",
                            {std::to_string(used.lumenPoints), numberText(kFlowPressureReachMm), used.wallLoadsId}});
    wall.pointFields[sim::fem::kLumenExtraPressureField] = std::move(added);
    return used;
}

} // namespace vsim::app
