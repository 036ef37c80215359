#include "vsim/sim/fem/FemRun.h"

#include "vsim/core/Error.h"
#include "vsim/core/Units.h"
#include "vsim/sim/fem/CorotationalFem.h"
#include "vsim/sim/fem/SurfaceLoads.h"
#include "vsim/sim/fem/Tearing.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace vsim::sim::fem {
namespace {

/// A pressure face by its element and the corner it is opposite to, so that it follows node splits.
struct ElementFace
{
    std::size_t element;
    int opposite;
};

constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}}; // outward for a positive tet

std::vector<ElementFace> lumenElementFaces(const TetMesh& wall, const std::vector<double>& layer,
                                           const std::function<bool(const Eigen::Vector3d&)>& loaded)
{
    std::vector<std::size_t> owners;
    const std::vector<std::array<int, 3>> faces = boundaryFaces(wall.tets, &owners);
    std::vector<ElementFace> lumen;
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
        const auto& face = faces[f];
        if (layer[std::size_t(face[0])] != 0.0 || layer[std::size_t(face[1])] != 0.0 || layer[std::size_t(face[2])] != 0.0)
            continue;
        const Eigen::Vector3d centroid =
            (wall.points[std::size_t(face[0])] + wall.points[std::size_t(face[1])] + wall.points[std::size_t(face[2])]) / 3.0;
        if (loaded && !loaded(centroid))
            continue;
        // The face is opposite the owner's one corner that is not on it.
        const auto& tet = wall.tets[owners[f]];
        int opposite = 0;
        while (std::find(face.begin(), face.end(), tet[std::size_t(opposite)]) != face.end())
            ++opposite;
        lumen.push_back({owners[f], opposite});
    }
    return lumen;
}

std::vector<std::array<int, 3>> faceNodes(const std::vector<ElementFace>& faces, const CorotationalFem& model)
{
    std::vector<std::array<int, 3>> nodes;
    nodes.reserve(faces.size());
    for (const ElementFace& face : faces)
    {
        const auto& tet = model.tets()[face.element];
        nodes.push_back({tet[std::size_t(kFaces[face.opposite][0])], tet[std::size_t(kFaces[face.opposite][1])],
                         tet[std::size_t(kFaces[face.opposite][2])]});
    }
    return nodes;
}

/// Averages per-tet values over the tets that came from one prism (original element index / 3).
std::vector<double> averageByPrism(const std::vector<double>& perTet, const std::vector<std::size_t>& originalElement)
{
    std::map<std::size_t, std::pair<double, int>> sums;
    for (std::size_t t = 0; t < perTet.size(); ++t)
    {
        auto& [sum, count] = sums[originalElement[t] / 3];
        sum += perTet[t];
        ++count;
    }
    std::vector<double> out(perTet.size());
    for (std::size_t t = 0; t < perTet.size(); ++t)
    {
        const auto& [sum, count] = sums[originalElement[t] / 3];
        out[t] = sum / count;
    }
    return out;
}

TetMesh frameOf(const CorotationalFem& model, const std::vector<std::size_t>& originalElement)
{
    TetMesh frame;
    frame.tets = model.tets();
    const std::size_t n = model.nodeCount();
    frame.points.resize(n);
    std::vector<double> dx(n), dy(n), dz(n), magnitude(n);
    for (std::size_t i = 0; i < n; ++i)
    {
        frame.points[i] = units::mToMm(1.0) * model.restPositions()[i];
        const Eigen::Vector3d d = units::mToMm(1.0) * (model.positions().segment<3>(Eigen::Index(3 * i)) - model.restPositions()[i]);
        dx[i] = d.x(), dy[i] = d.y(), dz[i] = d.z(), magnitude[i] = d.norm();
    }
    frame.pointFields["displacement_x_mm"] = dx;
    frame.pointFields["displacement_y_mm"] = dy;
    frame.pointFields["displacement_z_mm"] = dz;
    frame.pointFields["displacement_mm"] = magnitude;
    const ElementStresses stresses = model.elementStresses();
    std::vector<double> vonMises = averageByPrism(stresses.vonMises, originalElement);
    std::vector<double> principal = averageByPrism(stresses.maxPrincipal, originalElement);
    for (double& v : vonMises)
        v *= 1e-3;
    for (double& v : principal)
        v *= 1e-3;
    frame.cellFields["von_mises_kpa"] = vonMises;
    frame.cellFields["max_principal_kpa"] = principal;
    return frame;
}

bool finite(const Eigen::VectorXd& v) { return v.allFinite(); }

} // namespace

std::vector<double> prismAverage(const std::vector<double>& perTet, const TetMesh& wall)
{
    std::vector<std::size_t> identity(wall.tets.size());
    for (std::size_t t = 0; t < identity.size(); ++t)
        identity[t] = t;
    return averageByPrism(perTet, identity);
}

FemRunResult runFem(const FemRunSetup& setup, const Progress& progress)
{
    const auto layer = setup.wall.pointFields.find("wall_layer");
    const auto endSet = setup.wall.pointFields.find("end_set");
    if (layer == setup.wall.pointFields.end() || endSet == setup.wall.pointFields.end())
        throw Error("the tetrahedral mesh is not a vessel wall (wall_layer / end_set fields missing): build it with "
                    "'mesh wall'");
    if (!setup.pressurePa)
        throw Error("the run has no pressure curve");
    std::vector<Eigen::Vector3d> rest(setup.wall.points.size());
    for (std::size_t i = 0; i < rest.size(); ++i)
        rest[i] = units::mmToM(1.0) * setup.wall.points[i];
    CorotationalFem model(rest, setup.wall.tets, setup.material);
    std::vector<std::uint8_t> fixed(3 * model.nodeCount(), 0);
    std::size_t fixedNodes = 0;
    for (std::size_t i = 0; i < model.nodeCount(); ++i)
        if (endSet->second[i] > 0.0)
        {
            fixed[3 * i] = fixed[3 * i + 1] = fixed[3 * i + 2] = 1;
            ++fixedNodes;
        }
    if (fixedNodes == 0)
        throw Error("the wall has no fixed end (end_set is 0 everywhere): build it from centerlines with ends");
    std::vector<ElementFace> faces = lumenElementFaces(setup.wall, layer->second, setup.loaded);
    if (faces.empty())
        throw Error("no lumen face carries the pressure");
    std::vector<std::size_t> originalElement(model.elementCount());
    for (std::size_t t = 0; t < originalElement.size(); ++t)
        originalElement[t] = t;

    FemRunResult result;
    BackwardEuler integrator(model, setup.integrator);
    FractureEntropy entropy;
    const double h = setup.integrator.timeStep;
    auto addFrame = [&](double time, double pressure) {
        result.frames.push_back(frameOf(model, originalElement));
        result.frameTimesS.push_back(time);
        result.framePressuresPa.push_back(pressure);
    };
    addFrame(0.0, setup.pressurePa(0.0));
    long cgIterations = 0;
    int stepsRun = 0;
    double onsetPressure = -1.0;
    Eigen::VectorXd forces;
    for (int step = 1; step <= setup.steps; ++step)
    {
        progress.throwIfCancelled();
        const double time = step * h, pressure = setup.pressurePa(time);
        const Eigen::VectorXd lastPositions = model.positions(), lastVelocities = model.velocities();
        std::string guard;
        forces = Eigen::VectorXd::Zero(model.positions().size());
        addPressureForces(faceNodes(faces, model), model.positions(), pressure, forces);
        const StepReport report = integrator.step(model, forces, fixed);
        cgIterations += report.cgIterations;
        if (!finite(model.positions()))
            guard = "the solution is no longer finite (NaN or infinity)";
        else if (report.invertedElements > 0)
        {
            const Eigen::Vector3d where = 1e3 * model.firstInvertedCentroid();
            char place[96];
            std::snprintf(place, sizeof place, " (the first near %.1f, %.1f, %.1f mm)", where.x(), where.y(), where.z());
            guard = std::to_string(report.invertedElements) + " elements inverted" + place;
        }
        else if (!report.cgConverged && report.cgIterations < setup.integrator.cgMaxIterations)
            guard = "the conjugate gradients broke down (the system is not positive definite)";
        if (!guard.empty())
        {
            model.positions() = lastPositions;
            model.velocities() = lastVelocities;
            model.updateElements();
            result.stopReason = guard + " at step " + std::to_string(step) + " (t = " + std::to_string(time) +
                                " s, pressure " + std::to_string(pressure * 1e-6) + " MPa); the last good state is kept";
            break;
        }
        stepsRun = step;
        if (setup.tearing)
        {
            const std::vector<std::size_t> over = elementsOverStrength(model.elementStresses(), setup.tearStressPa);
            if (!over.empty())
            {
                const std::vector<double> energies = model.elementEnergies();
                for (std::size_t e : over)
                    entropy.addTornElement(energies[e]);
                if (onsetPressure < 0.0)
                    onsetPressure = pressure;
                DetachedModel detached = detachElements(model, over);
                std::vector<long> newElementOf(model.elementCount(), -1);
                for (std::size_t e = 0; e < detached.oldElementOf.size(); ++e)
                    newElementOf[detached.oldElementOf[e]] = long(e);
                std::vector<ElementFace> kept;
                for (const ElementFace& face : faces)
                    if (newElementOf[face.element] >= 0)
                        kept.push_back({std::size_t(newElementOf[face.element]), face.opposite});
                faces = std::move(kept);
                std::vector<std::uint8_t> newFixed(3 * detached.model.nodeCount());
                for (std::size_t n = 0; n < detached.model.nodeCount(); ++n)
                    for (int d = 0; d < 3; ++d)
                        newFixed[3 * n + std::size_t(d)] = fixed[3 * std::size_t(detached.oldNodeOf[n]) + std::size_t(d)];
                fixed = std::move(newFixed);
                std::vector<std::size_t> newOriginal(detached.oldElementOf.size());
                for (std::size_t e = 0; e < newOriginal.size(); ++e)
                    newOriginal[e] = originalElement[detached.oldElementOf[e]];
                originalElement = std::move(newOriginal);
                model = std::move(detached.model);
                integrator = BackwardEuler(model, setup.integrator);
                result.entropyCurve.push_back({pressure, entropy.value()});
                if (setup.entropyEnd > 0.0 && entropy.value() >= setup.entropyEnd)
                {
                    result.stopReason = "the fracture entropy reached " + std::to_string(entropy.value()) +
                                        " (end condition " + std::to_string(setup.entropyEnd) + ")";
                    addFrame(time, pressure);
                    break;
                }
            }
        }
        if (step % std::max(1, setup.frameEvery) == 0 || step == setup.steps)
            addFrame(time, pressure);
        progress.report(double(step) / setup.steps, "simulating");
    }
    const double lastTime = stepsRun * h;
    if (!result.stopReason.empty() && result.frameTimesS.back() != lastTime)
        addFrame(lastTime, setup.pressurePa(lastTime)); // the last good state

    const TetMesh& last = result.frames.back();
    const auto& vonMises = last.cellFields.at("von_mises_kpa");
    const auto peak = std::max_element(vonMises.begin(), vonMises.end());
    Eigen::Vector3d where = Eigen::Vector3d::Zero();
    for (int node : last.tets[std::size_t(peak - vonMises.begin())])
        where += 0.25 * last.points[std::size_t(node)];
    const auto& displacement = last.pointFields.at("displacement_mm");
    result.metrics["peak_von_mises_kpa"] = *peak;
    result.metrics["peak_von_mises_x_mm"] = where.x();
    result.metrics["peak_von_mises_y_mm"] = where.y();
    result.metrics["peak_von_mises_z_mm"] = where.z();
    result.metrics["peak_max_principal_kpa"] =
        *std::max_element(last.cellFields.at("max_principal_kpa").begin(), last.cellFields.at("max_principal_kpa").end());
    result.metrics["max_displacement_mm"] = *std::max_element(displacement.begin(), displacement.end());
    result.metrics["steps"] = stepsRun;
    result.metrics["mean_cg_iterations"] = stepsRun ? double(cgIterations) / stepsRun : 0.0;
    result.metrics["final_pressure_kpa"] = setup.pressurePa(lastTime) * 1e-3;
    if (setup.tearing)
    {
        result.metrics["torn_elements"] = double(entropy.tornElements());
        result.metrics["fracture_entropy"] = entropy.value();
        result.metrics["tear_onset_pressure_mpa"] = onsetPressure >= 0.0 ? onsetPressure * 1e-6 : -1.0;
    }
    return result;
}

} // namespace vsim::sim::fem
