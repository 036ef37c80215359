#include "SphPipelineSupport.h"

#include "BackendChoice.h"
#include "GpuPlugin.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"

#include <algorithm>
#include <queue>

namespace vsim::app {

/// Segment `e`'s path oriented to start at node `from`, with its conical radii.
RadiusPath orientedSegment(const VesselNetwork& network, int e, int from)
{
    const VesselNetwork::Segment& segment = network.segments[std::size_t(e)];
    RadiusPath path;
    path.points = network.segmentPath(std::size_t(e));
    double total = 0.0;
    std::vector<double> arc{0.0};
    for (std::size_t k = 1; k < path.points.size(); ++k)
        arc.push_back(total += (path.points[k] - path.points[k - 1]).norm());
    for (double s : arc)
        path.radii.push_back(segment.startRadiusMm + (total > 0.0 ? s / total : 0.0) * (segment.endRadiusMm - segment.startRadiusMm));
    if (segment.from != from)
    {
        std::reverse(path.points.begin(), path.points.end());
        std::reverse(path.radii.begin(), path.radii.end());
    }
    return path;
}

/// The path through the tree from node `from` to node `to` (their segments' paths joined).
RadiusPath pathBetween(const VesselNetwork& network, int from, int to)
{
    const std::vector<std::vector<int>> incident = network.incidentSegments();
    std::vector<int> viaSegment(network.nodes.size(), -2);
    std::queue<int> queue;
    queue.push(from), viaSegment[std::size_t(from)] = -1;
    while (!queue.empty())
    {
        const int node = queue.front();
        queue.pop();
        for (int e : incident[std::size_t(node)])
        {
            const VesselNetwork::Segment& s = network.segments[std::size_t(e)];
            const int next = s.from == node ? s.to : s.from;
            if (viaSegment[std::size_t(next)] == -2)
                viaSegment[std::size_t(next)] = e, queue.push(next);
        }
    }
    if (viaSegment[std::size_t(to)] == -2)
        throw Error(Pattern{"the vessel ends %1 and %2 are not connected", {std::to_string(from), std::to_string(to)}});
    std::vector<std::pair<int, int>> steps; // (segment, its start node on the way) from `to` back to `from`
    for (int node = to; node != from;)
    {
        const int e = viaSegment[std::size_t(node)];
        const VesselNetwork::Segment& s = network.segments[std::size_t(e)];
        const int previous = s.from == node ? s.to : s.from;
        steps.push_back({e, previous});
        node = previous;
    }
    RadiusPath path;
    for (auto it = steps.rbegin(); it != steps.rend(); ++it)
    {
        const RadiusPath piece = orientedSegment(network, it->first, it->second);
        const std::size_t skip = path.points.empty() ? 0 : 1; // the junction point once
        path.points.insert(path.points.end(), piece.points.begin() + long(skip), piece.points.end());
        path.radii.insert(path.radii.end(), piece.radii.begin() + long(skip), piece.radii.end());
    }
    return path;
}

EndPlane endPlane(const VesselNetwork& network, int node, double spacingMm)
{
    const std::vector<std::vector<int>> incident = network.incidentSegments();
    const RadiusPath path = orientedSegment(network, incident[std::size_t(node)].front(), node);
    EndPlane plane;
    plane.node = node;
    const double endRadius = path.radii.front();
    plane.insetMm = std::min(std::max(2.0 * spacingMm, 0.5 * endRadius), 0.45 * path.length());
    Eigen::Vector3d tangent;
    double radius = 0.0;
    path.at(plane.insetMm, plane.centreMm, tangent, radius);
    // The vessel's direction over the three radii inside the plane: the centerline's last millimetre bends towards
    // where the image's border cuts the lumen (a 2.5 mm artery 8.4 degrees off the slices: 10 degrees off its axis).
    plane.normal = path.chord(plane.insetMm, plane.insetMm + std::max(2.0 * spacingMm, 3.0 * radius));
    plane.radiusMm = 1.5 * std::max(radius, endRadius) + spacingMm;
    return plane;
}

sim::sph::SphStepperFactory chooseSphStepper(const std::string& requested, std::string& device,
                                             std::vector<std::string>& warnings)
{
    if (!chooseCuda(requested, device))
        return {};
    const sim::sph::SphStepperFactory gpuStepper = gpuPlugin()->sphStepperFactory();
    if (requested == "cuda")
        return gpuStepper;
    // auto: a solver the GPU's stepper refuses (SphStepper's limits) runs on the CPU, with a warning.
    return [&warnings, gpuStepper](const sim::sph::SphSolver& solver) -> std::unique_ptr<sim::sph::SphStepper>
    {
        try
        {
            return gpuStepper(solver);
        }
        catch (const Error& refused)
        {
            warnings.push_back(storedText(Pattern{"ran on the CPU: %1", {refused.message()}}));
            return nullptr;
        }
    };
}


SphVessels sphVessels(const study::Study& study, const std::string& centerlinesId, const std::string& feeder,
                      std::vector<std::string>& warnings, const Progress& progress)
{
    SphVessels vessels{buildStudyNetwork(study, centerlinesId, warnings, progress), labelOfCenterlines(study, centerlinesId),
                       {}};
    if (vessels.labelId.empty())
        throw Error(Pattern{"the centerlines '%1' have no lumen label to fill with particles", {centerlinesId}});
    vessels.ends = vessels.network.endNodes();
    if (vessels.ends.size() < 2)
        throw Error(Pattern{"the vessels need at least two open ends (%1's and an outlet); the centerlines have %2",
                            {feeder, std::to_string(vessels.ends.size())}});
    return vessels;
}

int chosenEnd(const SphVessels& vessels, int wanted, const std::string& role)
{
    const int node = wanted >= 0 ? wanted : vessels.network.root >= 0 ? vessels.network.root : vessels.ends.front();
    if (std::find(vessels.ends.begin(), vessels.ends.end(), node) == vessels.ends.end())
    {
        std::string list;
        for (int e : vessels.ends)
            list += (list.empty() ? "" : ", ") + std::to_string(e);
        throw Error(Pattern{"%1's node %2 is not a vessel end (ends: %3)", {role, std::to_string(node), list}});
    }
    return node;
}

SolverRun runSph(sim::sph::SphSolver& solver, const SimulationInput& input, const ParameterSet& parameters,
                 sim::RunControl control, int frames, const Progress& progress, std::string& backend,
                 std::string& device)
{
    if (control.frameEvery <= 0.0 && control.frameEverySteps <= 0)
        control.frameEvery = parameters.get("end_time_s") / std::max(1, frames);
    SolverRun run = sim::runSolver(solver, input, parameters, control, progress);
    backend = solver.steppedElsewhere() ? "cuda" : "cpu";
    if (backend == "cpu")
        device.clear();
    return run;
}

nlohmann::json openBoundaryJson(const sim::sph::OpenBoundary& b)
{
    nlohmann::json json{{"name", b.name},
                        {"centre_mm", {1e3 * b.centreM.x(), 1e3 * b.centreM.y(), 1e3 * b.centreM.z()}},
                        {"normal_into_vessel", {b.normal.x(), b.normal.y(), b.normal.z()}},
                        {"disk_radius_mm", 1e3 * b.radiusM}};
    if (b.prescribed == sim::sph::OpenBoundary::Prescribed::Velocity)
    {
        json["prescribed"] = "flow rate";
        json["flow_rate_ml_s"] = 1e6 * b.flowRateM3S;
        json["profile"] = b.parabolic ? "parabolic" : "plug";
        json["ramp_s"] = b.rampS;
    }
    else
    {
        json["prescribed"] = "pressure";
        json["pressure_mmhg"] = units::paToMmHg(b.pressurePa);
    }
    if (!b.waveform.points.empty())
        json["waveform_period_s"] = b.waveform.period();
    return json;
}

std::vector<std::string> givenUnlessAutomatic(const ParameterSet& solverParameters,
                                              const std::set<std::string>& automatic)
{
    std::vector<std::string> given;
    for (const ParameterSpec& spec : solverParameters.specs())
        if (!automatic.count(spec.key))
            given.push_back(spec.key);
    return given;
}

} // namespace vsim::app
