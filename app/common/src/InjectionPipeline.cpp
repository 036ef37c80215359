#include "vsim/app/InjectionPipeline.h"

#include "SphPipelineSupport.h"
#include "vsim/app/NetworkPipeline.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Units.h"
#include "vsim/mesh/ParticleSeeding.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace vsim::app {
namespace {

constexpr double kGravity = 9.81;                 // m/s^2
constexpr double kTable51VoidFraction = 0.2;      // thesis Table 5.1
constexpr double kTable51GaugePressurePa = 5332.0; // thesis Table 5.1 (40 mmHg)

bool given(const InjectionSetup& setup, const std::string& name)
{
    return std::find(setup.given.begin(), setup.given.end(), name) != setup.given.end();
}

/// An orthonormal frame whose third column is the unit `axis`.
Eigen::Matrix3d frameAlong(const Eigen::Vector3d& axis)
{
    const Eigen::Vector3d helper = std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    Eigen::Matrix3d frame;
    frame.col(0) = axis.cross(helper).normalized();
    frame.col(1) = axis.cross(frame.col(0));
    frame.col(2) = axis;
    return frame;
}

/// Appends the wall particles of an open-topped box: its interior is [low, high] in `frame`'s coordinates (mm; the
/// third axis points down, the top at low.z() is open), `layers` layers of `spacingMm` outside it, their depths the
/// distance to the interior's surface (the first layer half a spacing, as the seeding's walls).
void appendCollectionBox(ParticleSet& set, const Eigen::Matrix3d& frame, const Eigen::Vector3d& low,
                         const Eigen::Vector3d& high, double spacingMm, int layers)
{
    std::array<long, 3> cells{};
    for (int a = 0; a < 3; ++a)
        cells[std::size_t(a)] = long(std::ceil((high[a] - low[a]) / spacingMm));
    const double thickness = layers * spacingMm;
    auto& wall = set.fields["wall"];
    auto& depth = set.fields["wall_depth_mm"];
    auto& buffer = set.fields["open_boundary"];
    for (long k = 0; k < cells[2] + layers; ++k)
        for (long j = -layers; j < cells[1] + layers; ++j)
            for (long i = -layers; i < cells[0] + layers; ++i)
            {
                const Eigen::Vector3d q = low + spacingMm * Eigen::Vector3d(double(i) + 0.5, double(j) + 0.5, double(k) + 0.5);
                const Eigen::Vector3d top = low + spacingMm * Eigen::Vector3d(double(cells[0]), double(cells[1]), double(cells[2]));
                const Eigen::Vector3d excess = (low - q).cwiseMax(q - top).cwiseMax(0.0);
                const double distance = excess.norm();
                if (distance <= 0.0 || distance > thickness)
                    continue;
                set.positionsMm.push_back(frame * q);
                wall.push_back(1.0), depth.push_back(distance), buffer.push_back(0.0);
            }
}

/// Whether `pointMm` (patient frame) lies behind an open end's plane, within its disk and the walls around it.
bool behindOpenEnd(const Eigen::Vector3d& pointMm, const EndPlane& plane, double wallMarginMm)
{
    const Eigen::Vector3d offset = pointMm - plane.centreMm;
    const double along = offset.dot(plane.normal);
    return along < 0.0 && (offset - along * plane.normal).norm() <= plane.radiusMm + wallMarginMm;
}

/// Whether `pointMm` lies within `bandMm` in front of an open end's plane, within its disk and the walls around it.
bool nearCut(const Eigen::Vector3d& pointMm, const EndPlane& plane, double bandMm, double wallMarginMm)
{
    const Eigen::Vector3d offset = pointMm - plane.centreMm;
    const double along = offset.dot(plane.normal);
    return along >= 0.0 && along < bandMm && (offset - along * plane.normal).norm() <= plane.radiusMm + wallMarginMm;
}

} // namespace

std::vector<ParameterSpec> injectionSetupParameters()
{
    using K = ParameterSpec::Kind;
    const InjectionSetup defaults;
    return {
        {"needle_bore_mm", "Needle bore", "mm", defaults.needleBoreMm, 0.1, 20.0, "Needle",
         "the needle's inner diameter (16 G: 1.19 mm); the particles a third of it unless the spacing is given", K::Real},
        {"particles_per_s", "Generation rate", "particles/s", defaults.particlesPerSecond, 1.0, 1e7, "Needle",
         "particles of the run's spacing a second (thesis Table 5.1: 300)", K::Real},
        {"box_depth_mm", "Collection box depth", "mm", defaults.collectionDepthMm, 1.0, 500.0, "Collection box",
         "its floor below the vessel's lowest wall", K::Real},
        {"box_margin_mm", "Collection box margin", "mm", defaults.collectionMarginMm, 0.0, 500.0, "Collection box",
         "its sides beyond the open ends", K::Real},
        {"spacing_mm", "Particle spacing", "mm", 0.0, 0.0, 100.0, "Particles", "0: a third of the bore", K::Real},
        {"end_time_s", "End time", "s", 0.0, 0.0, 1e4, "Time", "0: twice a free fall from the needle to the box's floor",
         K::Real},
        {"frames", "Frames", "", double(defaults.frames), 1, 10000, "Time", "frames kept over the run", K::Integer},
    };
}

const std::vector<std::string>& injectionChosenParameters()
{
    static const std::vector<std::string> chosen = {
        "spacing_mm", "void_fraction", "reference_pressure_pa", "free_surface", "fluid_tension", "cfl",
        "wall_repulsion", "gravity_x_m_s2", "gravity_y_m_s2", "gravity_z_m_s2", "sound_speed_m_s", "end_time_s"};
    return chosen;
}

InjectionSetup injectionSetupFrom(const ParameterSet& form, const ParameterSet& solverParameters,
                                  const std::set<std::string>& automatic)
{
    InjectionSetup setup;
    setup.parameters = solverParameters;
    setup.given = givenUnlessAutomatic(solverParameters, automatic);
    setup.needleBoreMm = form.get("needle_bore_mm");
    setup.particlesPerSecond = form.get("particles_per_s");
    setup.collectionDepthMm = form.get("box_depth_mm");
    setup.collectionMarginMm = form.get("box_margin_mm");
    for (const char* key : {"spacing_mm", "end_time_s"})
        if (form.get(key) > 0.0)
            setup.parameters.set(key, form.get(key)), setup.given.push_back(key);
    setup.frames = int(form.get("frames"));
    return setup;
}

InjectionRun runInjection(const study::Study& study, const InjectionSetup& setup, sim::RunControl control,
                          const Progress& progress)
{
    InjectionRun injection;
    const sim::sph::SphStepperFactory stepper = chooseSphStepper(setup.backend, injection.device, injection.warnings);
    progress.report(0.0, localized("vsim::Progress", "vessel ends from the centerlines"));
    const SphVessels vessels =
        sphVessels(study, setup.centerlinesId, "the needle", injection.warnings, progress.subRange(0.0, 0.05));
    const VesselNetwork& network = vessels.network;
    const std::string& labelId = vessels.labelId;
    const std::vector<int>& ends = vessels.ends;
    const int needleNode = chosenEnd(vessels, setup.needleEndNode, "the needle");
    if (!(setup.needleBoreMm > 0.0) || !(setup.particlesPerSecond > 0.0) || !(setup.collectionDepthMm > 0.0) ||
        !(setup.collectionMarginMm >= 0.0))
        throw Error("the needle's bore, the generation rate and the box's depth must be positive, the box's margin "
                    "not negative");

    ParameterSet& parameters = injection.parameters = setup.parameters;
    if (!given(setup, "spacing_mm")) // three particles across the bore
        parameters.set("spacing_mm", setup.needleBoreMm / 3.0);
    const double spacingMm = parameters.get("spacing_mm");
    if (setup.needleBoreMm < 2.0 * spacingMm)
        throw Error(Pattern{"the needle's bore (%1 mm) needs at least two particles across: a spacing of at most %2 mm",
                            {numberText(setup.needleBoreMm), numberText(0.5 * setup.needleBoreMm)}});
    if (!given(setup, "void_fraction"))
        parameters.set("void_fraction", kTable51VoidFraction);
    if (!given(setup, "reference_pressure_pa"))
        parameters.set("reference_pressure_pa", kTable51GaugePressurePa);
    if (!given(setup, "free_surface")) // the blood runs down an empty vessel and gathers in the box
        parameters.set("free_surface", 1);
    if (!given(setup, "fluid_tension")) // a stream falling from the needle breaks up (SphSolver.h)
        parameters.set("fluid_tension", 0);
    // The stenosis jets' Courant number (SphSolver.h). Before the density floor, a particle at the needle's mouth ran
    // 473 % over the rest density at 75 ms at the solver's 0.2 and not at 0.1 (0.8 mm particles, 2026-11-28); with
    // the floor, runs at 0.2 (`--param cfl=0.2`) held as well as at 0.1 on the GPU, and the benches use it.
    if (!given(setup, "cfl"))
        parameters.set("cfl", sim::sph::kStenosisCfl);
    // The walls' backstop (thesis ch. 5.4: its ghost walls repel): the first drops land on the box's floor at the
    // free fall's speed with nothing under them to build a pressure, and one went 0.41 mm into it without it
    // (before the density floor, 2026-11-28).
    if (!given(setup, "wall_repulsion"))
        parameters.set("wall_repulsion", 0.01);

    // The needle's plane and the open ends; gravity from the needle towards the open ends.
    const EndPlane needlePlane = endPlane(network, needleNode, spacingMm);
    std::vector<EndPlane> openPlanes;
    Eigen::Vector3d openCentre = Eigen::Vector3d::Zero();
    for (int end : ends)
        if (end != needleNode)
        {
            openPlanes.push_back(endPlane(network, end, spacingMm));
            openCentre += openPlanes.back().centreMm / double(ends.size() - 1);
            injection.openEnds.push_back(end);
        }
    injection.gravityDirection = (openCentre - needlePlane.centreMm).normalized();
    if (!given(setup, "gravity_x_m_s2") && !given(setup, "gravity_y_m_s2") && !given(setup, "gravity_z_m_s2"))
        for (int a = 0; a < 3; ++a)
            parameters.set(std::string("gravity_") + char('x' + a) + "_m_s2", kGravity * injection.gravityDirection[a]);

    // The particles: the lumen's walls with the needle's buffer, the vessel emptied, the other ends opened.
    progress.report(0.05, localized("vsim::Progress", "particles from the lumen label"));
    const double depthMm = 2.0 * parameters.get("smoothing_ratio") * spacingMm; // the kernel's support
    mesh::ParticleSeeding seeding;
    seeding.spacingMm = spacingMm;
    seeding.wallLayers = int(std::ceil(depthMm / spacingMm - 1e-9));
    seeding.openEnds.push_back({needlePlane.centreMm, needlePlane.normal, 0.5 * setup.needleBoreMm, depthMm});
    const ParticleSet seeded = mesh::seedVesselParticles(study.loadLabel(labelId), seeding);
    const double wallMarginMm = (seeding.wallLayers + 1) * spacingMm;
    ParticleSet particles;
    for (const char* field : {"wall", "wall_depth_mm", "open_boundary"})
        particles.fields[field];
    for (std::size_t i = 0; i < seeded.size(); ++i)
    {
        const bool wall = seeded.fields.at("wall")[i] > 0.5, buffer = seeded.fields.at("open_boundary")[i] > 0.5;
        const Eigen::Vector3d& x = seeded.positionsMm[i];
        if ((!wall && !buffer) ||
            (wall && std::any_of(openPlanes.begin(), openPlanes.end(),
                                 [&](const EndPlane& plane) { return behindOpenEnd(x, plane, wallMarginMm); })))
            continue;
        particles.positionsMm.push_back(x);
        for (const char* field : {"wall", "wall_depth_mm", "open_boundary"})
            particles.fields[field].push_back(seeded.fields.at(field)[i]);
        // A wall particle's depth is below the lumen's surface; at an open end's cut the wall ends in a face that
        // depth does not describe, and blood pouring past it would read as gone into the wall (a particle 0.4 mm
        // "into" the cut's outer layer stopped the run, 2026-11-28): there the depth is unknown (SphRates.h).
        if (wall && std::any_of(openPlanes.begin(), openPlanes.end(), [&](const EndPlane& plane)
                                { return nearCut(x, plane, depthMm, wallMarginMm); }))
            particles.fields["wall_depth_mm"].back() = -1.0;
    }

    // The collection box below the vessel's lowest wall particle, in gravity's frame.
    injection.boxFrame = frameAlong(injection.gravityDirection);
    const Eigen::Matrix3d toFrame = injection.boxFrame.transpose();
    double lowest = -INFINITY;
    for (const Eigen::Vector3d& x : particles.positionsMm)
        lowest = std::max(lowest, (toFrame * x).z());
    injection.vesselLengthMm = lowest - (toFrame * needlePlane.centreMm).z();
    Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
    for (const EndPlane& plane : openPlanes)
    {
        const Eigen::Vector3d c = toFrame * plane.centreMm;
        const double reach = plane.radiusMm + wallMarginMm + setup.collectionMarginMm;
        low = low.cwiseMin(c - Eigen::Vector3d::Constant(reach)), high = high.cwiseMax(c + Eigen::Vector3d::Constant(reach));
    }
    low.z() = lowest + 2.0 * spacingMm, high.z() = low.z() + setup.collectionDepthMm;
    injection.boxLowMm = low, injection.boxHighMm = high;
    // Its sides rise as far again above its top, around the vessel's end: drops splashing from the floor flew over
    // sides that ended at the top and left the domain (GPU, 2026-11-28).
    Eigen::Vector3d wallsFrom = low;
    wallsFrom.z() -= setup.collectionDepthMm;
    appendCollectionBox(particles, injection.boxFrame, wallsFrom, high, spacingMm, seeding.wallLayers);

    // The needle: a velocity inlet of the generation rate, parabolic in the bore.
    const double spacingM = 1e-3 * spacingMm;
    sim::sph::OpenBoundary& needle = injection.needle;
    needle.name = "needle";
    needle.centreM = 1e-3 * needlePlane.centreMm, needle.normal = needlePlane.normal;
    needle.radiusM = 0.5e-3 * setup.needleBoreMm;
    needle.prescribed = sim::sph::OpenBoundary::Prescribed::Velocity;
    needle.flowRateM3S = setup.particlesPerSecond * spacingM * spacingM * spacingM;
    needle.parabolic = true;
    needle.tracer = parameters.get("absorption_distance_mm") > 0.0; // the walls take up the injected drug

    // The sound speed: 40 times the fastest speed expected (a free fall from the needle to the box's floor, plus the
    // needle's peak). Not the flows' 10: a drop landing at speed v compresses by about v / c0 (the water hammer's
    // rho c0 v), not (v / c0)^2. On the heart phantom (GPU, 2026-11-28) the landing stopped the run by the 3 %
    // density guard at 20 times; at 40 it ran on with the density within 0.62 %. The end time: twice that fall's
    // time.
    const double fallM = 1e-3 * (high.z() - (toFrame * needlePlane.centreMm).z());
    const double needlePeak = 2.0 * needle.flowRateM3S / (std::numbers::pi * needle.radiusM * needle.radiusM);
    const double fallSpeed = std::sqrt(2.0 * kGravity * fallM);
    if (!given(setup, "sound_speed_m_s"))
        parameters.set("sound_speed_m_s", 40.0 * (fallSpeed + needlePeak));
    if (!given(setup, "end_time_s"))
        parameters.set("end_time_s", 2.0 * std::sqrt(2.0 * fallM / kGravity));

    SimulationInput input;
    input.data["particles"] = std::move(particles);
    input.sources["particles"] = labelId;
    sim::sph::SphSolver solver;
    solver.setOpenBoundaries({needle});
    solver.setStepper(stepper);
    injection.run = runSph(solver, input, parameters, control, setup.frames, progress.subRange(0.05, 1.0),
                           injection.backend, injection.device);

    // The fill at every kept frame.
    const double particleMl = 1e-3 * spacingMm * spacingMm * spacingMm;
    const double needleLevel = (toFrame * needlePlane.centreMm).z();
    for (const RunFrame& frame : injection.run.frames)
    {
        const auto* set = std::get_if<ParticleSet>(&frame.data);
        if (!set)
            continue;
        InjectionFill fill;
        fill.timeS = frame.position;
        const std::vector<double>&wall = set->fields.at("wall"), &buffer = set->fields.at("open_boundary");
        for (std::size_t i = 0; i < set->size(); ++i)
        {
            if (wall[i] > 0.5 || buffer[i] > 0.5)
                continue;
            const Eigen::Vector3d q = toFrame * set->positionsMm[i];
            const bool inBox = q.z() >= low.z() && q.x() >= low.x() && q.x() <= high.x() && q.y() >= low.y() &&
                               q.y() <= high.y();
            (inBox ? fill.collectedMl : fill.inVesselMl) += particleMl;
            if (!inBox)
                fill.frontMm = std::max(fill.frontMm, q.z() - needleLevel);
        }
        if (fill.collectedMl > 0.0 && injection.firstCollectedS < 0.0)
            injection.firstCollectedS = fill.timeS;
        injection.fill.push_back(fill);
    }
    return injection;
}

} // namespace vsim::app
