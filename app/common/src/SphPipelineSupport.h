#pragma once

// What the SPH pipelines (BloodFlowPipeline.h, InjectionPipeline.h) share: paths along a study's centerlines with
// their radii, the planes of the vessel ends, the stepper a backend name asks for, and an open boundary as the
// documents print it. Internal to app/common.

#include "vsim/app/NetworkPipeline.h"
#include "vsim/sim/common/RunDriver.h"
#include "vsim/sim/sph/SphSolver.h"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <set>
#include <string>
#include <vector>

namespace vsim::app {

/// A centerline path with its lumen radius at every point (mm), oriented from its first point.
struct RadiusPath
{
    std::vector<Eigen::Vector3d> points;
    std::vector<double> radii;

    double length() const
    {
        double sum = 0.0;
        for (std::size_t k = 1; k < points.size(); ++k)
            sum += (points[k] - points[k - 1]).norm();
        return sum;
    }
    /// The point, unit tangent and radius at arc length s (mm) from the first point (clamped to the path).
    void at(double s, Eigen::Vector3d& point, Eigen::Vector3d& tangent, double& radius) const
    {
        s = std::max(0.0, s);
        for (std::size_t k = 1; k < points.size(); ++k)
        {
            const double step = (points[k] - points[k - 1]).norm();
            if (s <= step || k + 1 == points.size())
            {
                const double share = step > 0.0 ? std::min(1.0, s / step) : 0.0;
                point = points[k - 1] + share * (points[k] - points[k - 1]);
                radius = radii[k - 1] + share * (radii[k] - radii[k - 1]);
                tangent = (points[k] - points[k - 1]).normalized();
                return;
            }
            s -= step;
        }
        point = points.front(), radius = radii.front(), tangent = Eigen::Vector3d::UnitX();
    }
    /// The tangent averaged over +-`halfMm` around arc length s (steadier than one polyline step's).
    Eigen::Vector3d smoothTangent(double s, double halfMm) const { return chord(s - halfMm, s + halfMm); }
    /// The unit chord from arc length `from` to `to` (mm, clipped to the path; its tangent where they meet).
    Eigen::Vector3d chord(double from, double to) const
    {
        Eigen::Vector3d before, after, tangent;
        double radius = 0.0;
        at(std::max(0.0, from), before, tangent, radius);
        at(std::min(length(), to), after, tangent, radius);
        return (after - before).norm() > 0.0 ? Eigen::Vector3d((after - before).normalized()) : tangent;
    }
};

/// Segment `e`'s path oriented to start at node `from`, with its conical radii.
RadiusPath orientedSegment(const VesselNetwork& network, int e, int from);

/// The path through the tree from node `from` to node `to` (their segments' paths joined); throws vsim::Error when
/// they are not connected.
RadiusPath pathBetween(const VesselNetwork& network, int from, int to);

/// An open end's plane: `insetMm` inside the vessel along the end's centerline, its normal into the vessel.
struct EndPlane
{
    int node = -1;
    Eigen::Vector3d centreMm = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitX();
    double radiusMm = 0.0, insetMm = 0.0;
};

/// End `node`'s plane: half its radius inside (at least two spacings, at most 0.45 of its segment), perpendicular to
/// the vessel's direction over the three radii inside it, with a disk of 1.5 radii and a spacing.
EndPlane endPlane(const VesselNetwork& network, int node, double spacingMm);

/// A study's vessels as an SPH run starts from them: the centerlines' network, their lumen label and the network's
/// ends.
struct SphVessels
{
    VesselNetwork network;
    std::string labelId;
    std::vector<int> ends;
};
/// Throws vsim::Error for centerlines without a lumen label or a network of fewer than two ends (`feeder`, "the
/// inlet" or "the needle", and an open one).
SphVessels sphVessels(const study::Study& study, const std::string& centerlinesId, const std::string& feeder,
                      std::vector<std::string>& warnings, const Progress& progress);
/// End node `wanted`, or where it is -1 the root (the end of the largest vessel; the first end without one); throws
/// vsim::Error naming `role` and the ends when it is not an end.
int chosenEnd(const SphVessels& vessels, int wanted, const std::string& role);

/// The stepper a backend name asks for: the CPU's (an empty factory) for "cpu", the GPU's for "cuda" (refused
/// without one), and on "auto" the GPU's when there is a device, falling back to the CPU with a line in `warnings`
/// where it refuses the case. `device` gets the GPU's summary when there is one. Throws vsim::Error for another name.
/// The factory keeps a reference to `warnings`.
sim::sph::SphStepperFactory chooseSphStepper(const std::string& requested, std::string& device,
                                             std::vector<std::string>& warnings);

/// Runs `solver` (its boundaries and stepper set) on `input` under `control`, with `frames` frames over the run's
/// end time when the control asks for none; `backend` becomes "cuda" when the GPU stepped it, else "cpu" with
/// `device` cleared.
SolverRun runSph(sim::sph::SphSolver& solver, const SimulationInput& input, const ParameterSet& parameters,
                 sim::RunControl control, int frames, const Progress& progress, std::string& backend,
                 std::string& device);

/// An open boundary as the run documents and the provenance print it (mm, ml/s, mmHg).
nlohmann::json openBoundaryJson(const sim::sph::OpenBoundary& boundary);

/// The solver parameters a workstation form gives: every one but those ticked `automatic` (the pipeline chooses
/// those).
std::vector<std::string> givenUnlessAutomatic(const ParameterSet& solverParameters,
                                              const std::set<std::string>& automatic);

} // namespace vsim::app
