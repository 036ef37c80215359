#include "vsim/app/BloodFlowPipeline.h"

#include "SphPipelineSupport.h"
#include "vsim/app/NetworkPipeline.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Units.h"
#include "vsim/mesh/ParticleSeeding.h"
#include "vsim/mesh/VesselSurface.h"
#include "vsim/sim/sph/SphSolver.h"


#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::app {
namespace {

constexpr int kWallSurfaceVertices = 20000; // the wall loads' surface: the label's iso-surface decimated to this

/// The surface's vertices (m) with their normals into the lumen (the outward vertex normals reversed).
std::vector<sim::sph::WallPoint> inwardWallPoints(const TriangleMesh& surface)
{
    const std::vector<Eigen::Vector3d> outward = surface.vertexNormals();
    std::vector<sim::sph::WallPoint> points;
    points.reserve(surface.points.size());
    for (std::size_t v = 0; v < surface.points.size(); ++v)
        points.push_back({1e-3 * surface.points[v], outward[v].norm() > 0.0 ? Eigen::Vector3d(-outward[v]) : Eigen::Vector3d::UnitX()});
    return points;
}

/// Whether a wall point (mm) lies within `bandMm` inside an open end's plane (or past it): there the kernels reach
/// the buffer particles whose velocity or pressure is prescribed, and the wall loads are the boundary's, not the
/// flow's (the coarse stenosis of cli_blood_flow read 5.8 Pa TAWSS at its inlet against 0.69 Pa at its throat).
bool nearOpenEnd(const Eigen::Vector3d& pointMm, const std::vector<EndPlane>& planes, double bandMm)
{
    for (const EndPlane& plane : planes)
    {
        const Eigen::Vector3d offset = pointMm - plane.centreMm;
        const double inside = offset.dot(plane.normal);
        if (inside < bandMm && (offset - inside * plane.normal).norm() <= plane.radiusMm)
            return true;
    }
    return false;
}

/// The lumen's inscribed radius at `pointMm` (mm): the distance to the nearest voxel that is not lumen, searched within
/// `reachMm` (returned when none is nearer).
double inscribedRadiusMm(const LabelVolume& label, const Eigen::Vector3d& pointMm, double reachMm, std::uint8_t lumen = 1)
{
    const VolumeGeometry& g = label.geometry();
    const Eigen::Vector3d centre = g.patientToIndex(pointMm);
    const Eigen::Vector3d halfWidth = (reachMm / g.spacing.array()).ceil().matrix();
    double nearest2 = reachMm * reachMm;
    for (int k = int(centre.z() - halfWidth.z()); k <= int(centre.z() + halfWidth.z()); ++k)
        for (int j = int(centre.y() - halfWidth.y()); j <= int(centre.y() + halfWidth.y()); ++j)
            for (int i = int(centre.x() - halfWidth.x()); i <= int(centre.x() + halfWidth.x()); ++i)
                if (!g.contains(i, j, k) || label.at(i, j, k) != lumen)
                {
                    const double d2 = (g.indexToPatient(Eigen::Vector3d(i, j, k)) - pointMm).squaredNorm();
                    nearest2 = std::min(nearest2, d2);
                }
    return std::sqrt(nearest2);
}

bool given(const BloodFlowSetup& setup, const std::string& name)
{
    return std::find(setup.given.begin(), setup.given.end(), name) != setup.given.end();
}

} // namespace

const std::vector<std::string>& bloodFlowChosenParameters()
{
    static const std::vector<std::string> chosen = {
        "spacing_mm", "end_time_s", "sound_speed_m_s", "cfl", "reference_pressure_pa", "fluid_loss_guard",
        "particle_shifting", "shifting_speed_m_s", "density_relaxation_s"};
    return chosen;
}

std::vector<ParameterSpec> bloodFlowSetupParameters()
{
    using K = ParameterSpec::Kind;
    return {
        {"inlet_mean_velocity_m_s", "Inlet mean velocity", "m/s", 0.2, -10.0, 10.0, "Inlet",
         "over the inlet's section (the end of the largest vessel), parabolic, ramped up from rest", K::Real},
        {"inlet_flow_rate_ml_s", "Inlet flow rate", "ml/s", 0.0, 0.0, 1e4, "Inlet", "> 0: replaces the mean velocity",
         K::Real},
        {"outlet_pressure_mmhg", "Outlet pressure", "mmHg", 0.0, -100.0, 300.0, "Outlets",
         "at every other vessel end (gauge: the pressures reported are relative to it)", K::Real},
        {"compare_mm", "Compare at", "mm", 6.0, 0.5, 500.0, "Stenosis figures",
         "the sections upstream and downstream of the throat the velocity ratios compare with (thesis: 6 mm in the "
         "hand, 30 mm in the heart)", K::Real},
        {"spacing_mm", "Particle spacing", "mm", 0.0, 0.0, 100.0, "Particles", "0: a fifth of the inlet's radius",
         K::Real},
        {"end_time_s", "End time", "s", 0.0, 0.0, 1e4, "Time",
         "0: twice the inflow's ramp (two quarter-wave periods of the vessel)", K::Real},
        {"frames", "Frames", "", 20, 1, 10000, "Time", "frames kept over the run", K::Integer},
    };
}

BloodFlowSetup bloodFlowSetupFrom(const ParameterSet& form, const ParameterSet& solverParameters,
                                  const std::set<std::string>& automatic)
{
    BloodFlowSetup setup;
    setup.parameters = solverParameters;
    setup.given = givenUnlessAutomatic(solverParameters, automatic);
    if (form.get("inlet_flow_rate_ml_s") > 0.0)
        setup.inlet.kind = BloodFlowInlet::Kind::FlowRate, setup.inlet.value = 1e-6 * form.get("inlet_flow_rate_ml_s");
    else
        setup.inlet.kind = BloodFlowInlet::Kind::MeanVelocity, setup.inlet.value = form.get("inlet_mean_velocity_m_s");
    setup.outletPressurePa = units::mmHgToPa(form.get("outlet_pressure_mmhg"));
    setup.compareMm = form.get("compare_mm");
    for (const char* key : {"spacing_mm", "end_time_s"})
        if (form.get(key) > 0.0)
            setup.parameters.set(key, form.get(key)), setup.given.push_back(key);
    setup.frames = int(form.get("frames"));
    return setup;
}

BloodFlowRun runBloodFlow(const study::Study& study, const BloodFlowSetup& setup, sim::RunControl control,
                          const Progress& progress)
{
    BloodFlowRun flow;
    const sim::sph::SphStepperFactory stepper = chooseSphStepper(setup.backend, flow.device, flow.warnings);
    progress.report(0.0, localized("vsim::Progress", "vessel ends from the centerlines"));
    const SphVessels vessels = sphVessels(study, setup.centerlinesId, "the inlet", flow.warnings, progress.subRange(0.0, 0.05));
    const VesselNetwork& network = vessels.network;
    const std::string& labelId = vessels.labelId;
    std::vector<int> ends = vessels.ends;
    const int inletNode = chosenEnd(vessels, setup.inlet.endNode, "the inlet");

    ParameterSet& parameters = flow.parameters = setup.parameters;
    const std::vector<std::vector<int>> incident = network.incidentSegments();
    const double inletRadiusMm = orientedSegment(network, incident[std::size_t(inletNode)].front(), inletNode).radii.front();
    if (!given(setup, "spacing_mm")) // five particles per radius at the inlet
        parameters.set("spacing_mm", std::max(0.05, inletRadiusMm / 5.0));
    const double spacingMm = parameters.get("spacing_mm");

    // The compared path: to the outlet whose way from the inlet is the narrowest.
    RadiusPath compared;
    double narrowest = INFINITY;
    int comparedOutlet = -1;
    for (int end : ends)
        if (end != inletNode)
        {
            RadiusPath path = pathBetween(network, inletNode, end);
            const double smallest = *std::min_element(path.radii.begin(), path.radii.end());
            if (smallest < narrowest)
                narrowest = smallest, compared = std::move(path), comparedOutlet = end;
        }

    // The narrowest lumen along the compared path (its inscribed radius on the centerline every spacing, away from the
    // ends, where the image's border cuts the lumen: the centerlines' conical segments do not see a stenosis within a
    // segment), and the path's Poiseuille resistance integral, sum ds / r^4 (m^-3), and volume (m^3) from those radii.
    const LabelVolume label = study.loadLabel(labelId);
    const double skip = 2.0 * spacingMm + 1.5 * std::max(compared.radii.front(), compared.radii.back()); // the ends
    double resistanceIntegral = 0.0, pathVolumeM3 = 0.0;
    for (double s = 0.5 * spacingMm; s < compared.length(); s += spacingMm)
    {
        Eigen::Vector3d point, tangent;
        double radius = 0.0;
        compared.at(s, point, tangent, radius);
        if (s >= skip && s <= compared.length() - skip)
        {
            radius = std::max(0.5 * spacingMm, inscribedRadiusMm(label, point, 1.5 * radius + spacingMm));
            narrowest = std::min(narrowest, radius);
        }
        // (a centerline's radius can be 0 where the thinning left a stub: no thinner than half a spacing)
        const double ds = 1e-3 * std::min(spacingMm, compared.length() - s + 0.5 * spacingMm);
        const double r = 1e-3 * std::max(0.5 * spacingMm, radius);
        resistanceIntegral += ds / std::pow(r, 4), pathVolumeM3 += std::numbers::pi * r * r * ds;
    }

    // The inflow's scale, the sound speed and the times. The sound speed: 10 times the largest speed expected (the
    // inlet's mean speed through the narrowest section, parabolic), and at least what holds the path's Poiseuille
    // pressure drop within 0.5 % of the density (slow flow through a long, narrow vessel: there the viscous pressure,
    // not the speed, compresses a soft fluid).
    const double inletAreaM2 = std::numbers::pi * std::pow(1e-3 * inletRadiusMm, 2);
    const double narrowestAreaM2 = std::numbers::pi * std::pow(1e-3 * narrowest, 2);
    sim::sph::FluidModel blood;
    blood.restDensity = parameters.get("density_kg_m3"), blood.viscosity = parameters.get("viscosity_pa_s");
    const double density = blood.mixtureDensity(parameters.get("void_fraction"));
    double expectedPeak = 0.0, viscousDropPa = 0.0, flowRate = 0.0;
    if (setup.inlet.kind == BloodFlowInlet::Kind::Pressure)
        expectedPeak = std::sqrt(2.0 * std::abs(setup.inlet.value - setup.outletPressurePa) / density); // Bernoulli
    else
    {
        flowRate = std::abs(setup.inlet.kind == BloodFlowInlet::Kind::FlowRate ? setup.inlet.value
                                                                               : setup.inlet.value * inletAreaM2);
        double largestFactor = 1.0;
        for (const auto& point : setup.inlet.waveform.points)
            largestFactor = std::max(largestFactor, point.second);
        expectedPeak = 2.0 * flowRate * largestFactor / narrowestAreaM2;
        viscousDropPa = 8.0 * blood.mixtureViscosity(parameters.get("void_fraction")) * flowRate * largestFactor *
                        resistanceIntegral / std::numbers::pi;
    }
    if (!given(setup, "sound_speed_m_s"))
        parameters.set("sound_speed_m_s",
                       std::max({0.5, 10.0 * expectedPeak, std::sqrt(viscousDropPa / (0.005 * density))}));
    if (!given(setup, "reference_pressure_pa")) // the outlets' level: pressures reported against the same zero
        parameters.set("reference_pressure_pa", setup.outletPressurePa);
    // A stenosis's jet needs the smaller step, the smaller the faster it is (SphSolver.h: stenosisCfl), by the
    // Reynolds number of the narrowest section's mean flow (half the parabolic peak expected there) over its
    // diameter.
    const double throatReynolds = density * 0.5 * expectedPeak * 2e-3 * narrowest /
                                  blood.mixtureViscosity(parameters.get("void_fraction"));
    if (!given(setup, "cfl"))
        parameters.set("cfl", sim::sph::stenosisCfl(throatReynolds));
    // ... and the shift with its floor at the narrowest section's mean speed at the inflow's peak (half the
    // parabolic peak expected there), and the continuity density relaxed towards summation (SphSolver.h:
    // kStenosisShifting).
    if (!given(setup, "particle_shifting"))
        parameters.set("particle_shifting", sim::sph::kStenosisShifting);
    if (!given(setup, "shifting_speed_m_s") && parameters.get("particle_shifting") > 0.0)
        parameters.set("shifting_speed_m_s", 0.5 * expectedPeak);
    if (!given(setup, "density_relaxation_s") && parameters.get("density_summation") == 0.0)
        parameters.set("density_relaxation_s", sim::sph::kStenosisRelaxationSmoothingTimes * 1e-3 * spacingMm *
                                                   parameters.get("smoothing_ratio") /
                                                   parameters.get("sound_speed_m_s"));
    // A vessel that empties through its outlets while its particles' densities read full (SphRates.h: the continuity
    // density's drift) stops with the reason rather than print a thinned flow's figures. 10 %: over three times what
    // a pulse's compression stores (the density guard's 3 %).
    if (!given(setup, "fluid_loss_guard"))
        parameters.set("fluid_loss_guard", 0.1);
    const double soundSpeed = parameters.get("sound_speed_m_s");
    const double pathLengthM = 1e-3 * compared.length();
    flow.rampS = setup.rampS >= 0.0 ? setup.rampS : 8.0 * pathLengthM / soundSpeed; // two quarter-wave periods
    // The weakly compressible vessel settles like a resistor charging a capacitor: its resistance (the Poiseuille
    // drop over the flow rate) times its compliance (volume / rho c0^2).
    flow.settlingS =
        flowRate > 0.0 ? viscousDropPa / flowRate * pathVolumeM3 / (density * soundSpeed * soundSpeed) : 0.0;
    const double period = setup.inlet.waveform.period();
    if (!given(setup, "end_time_s"))
        parameters.set("end_time_s", period > 0.0 ? flow.rampS + std::max(2.0 * period, 5.0 * flow.settlingS)
                                                  : flow.rampS + std::max(flow.rampS, 5.0 * flow.settlingS));
    const double endTime = parameters.get("end_time_s");
    flow.averagedFromS = period > 0.0 ? std::max(0.0, endTime - period) : flow.rampS + 0.5 * std::max(0.0, endTime - flow.rampS);
    if (period <= 0.0 && endTime <= flow.rampS)
        flow.warnings.push_back(storedText(Pattern{
            "the run ends before the inflow has risen (%1 s): the figures are not of a settled flow",
            {numberText(flow.rampS)}}));
    else if (flow.averagedFromS < flow.rampS + 3.0 * flow.settlingS)
        flow.warnings.push_back(storedText(Pattern{
            "the averaging starts %1 s after the inflow's rise, under three settling times (3 x %2 s: the vessel's "
            "resistance x compliance at this sound speed): the figures may not be of a settled flow",
            {numberText(flow.averagedFromS - flow.rampS), numberText(flow.settlingS)}}));

    // The open ends and the particles.
    const double depthMm = 2.0 * parameters.get("smoothing_ratio") * spacingMm; // the kernel's support
    mesh::ParticleSeeding seeding;
    seeding.spacingMm = spacingMm;
    seeding.wallLayers = int(std::ceil(depthMm / spacingMm - 1e-9));
    std::stable_partition(ends.begin(), ends.end(), [&](int end) { return end == inletNode; }); // the inlet first
    std::vector<EndPlane> planes;
    for (int end : ends)
    {
        const EndPlane plane = endPlane(network, end, spacingMm);
        planes.push_back(plane);
        seeding.openEnds.push_back({plane.centreMm, plane.normal, plane.radiusMm, depthMm});
        sim::sph::OpenBoundary boundary;
        boundary.centreM = 1e-3 * plane.centreMm, boundary.normal = plane.normal, boundary.radiusM = 1e-3 * plane.radiusMm;
        if (end == inletNode)
        {
            boundary.name = "inlet";
            boundary.waveform = setup.inlet.waveform;
            boundary.rampS = flow.rampS;
            if (setup.inlet.kind == BloodFlowInlet::Kind::Pressure)
                boundary.prescribed = sim::sph::OpenBoundary::Prescribed::Pressure, boundary.pressurePa = setup.inlet.value;
            else
            {
                boundary.prescribed = sim::sph::OpenBoundary::Prescribed::Velocity;
                boundary.parabolic = setup.inlet.parabolic;
                boundary.flowRateM3S = setup.inlet.kind == BloodFlowInlet::Kind::FlowRate ? setup.inlet.value
                                                                                          : setup.inlet.value * inletAreaM2;
            }
        }
        else
        {
            boundary.name = "outlet " + std::to_string(end);
            boundary.prescribed = sim::sph::OpenBoundary::Prescribed::Pressure;
            boundary.pressurePa = setup.outletPressurePa;
        }
        flow.boundaries.push_back(boundary);
    }
    progress.report(0.05, localized("vsim::Progress", "particles from the lumen label"));
    SimulationInput input;
    input.data["particles"] = mesh::seedVesselParticles(label, seeding);
    input.sources["particles"] = labelId;

    // Sections along the compared path between its planes, every two spacings.
    const EndPlane& inletPlane = planes[std::size_t(std::find(ends.begin(), ends.end(), inletNode) - ends.begin())];
    const EndPlane& outletPlane = planes[std::size_t(std::find(ends.begin(), ends.end(), comparedOutlet) - ends.begin())];
    std::vector<sim::sph::CrossSection> sections;
    for (double s = inletPlane.insetMm + 2.0 * spacingMm; s <= compared.length() - outletPlane.insetMm - 2.0 * spacingMm;
         s += 2.0 * spacingMm)
    {
        Eigen::Vector3d centre, tangent;
        double radius = 0.0;
        compared.at(s, centre, tangent, radius);
        sections.push_back({1e-3 * centre, compared.smoothTangent(s, std::max(spacingMm, 0.5 * radius)),
                            1e-3 * (1.5 * radius + spacingMm), 2e-3 * spacingMm});
        flow.sectionArcMm.push_back(s - inletPlane.insetMm);
        flow.sectionCentresMm.push_back(centre);
    }
    // The wall loads on the lumen's surface, averaged over the sections' window, every 10th step.
    progress.report(0.05, localized("vsim::Progress", "the lumen's surface for the wall loads"));
    ParameterSet surfaceParameters(mesh::surfaceParameters());
    surfaceParameters.set("target_vertices", double(kWallSurfaceVertices));
    flow.wallSurface = mesh::extractVesselSurface(label, 1, surfaceParameters).surface;
    sim::sph::SphSolver solver;
    solver.setOpenBoundaries(flow.boundaries);
    solver.setSections(sections, flow.averagedFromS, int(std::ceil(double(sections.size()) / 30.0)));
    solver.setWallPoints(inwardWallPoints(flow.wallSurface), flow.averagedFromS, 10);
    solver.setStepper(stepper); // the GPU's particles come back every 10th step for the sections and the wall
    flow.run = runSph(solver, input, parameters, control, setup.frames, progress.subRange(0.05, 1.0), flow.backend,
                      flow.device);
    flow.sections = solver.sections().averages();
    flow.sectionLargestPeaks = solver.sections().largestPeaks();
    flow.averagedS = solver.sections().averagedTime();
    {
        const std::vector<sim::sph::WallLoadAverage> loads = solver.wallLoads().averages();
        auto &tawss = flow.wallSurface.pointFields["tawss_pa"], &osi = flow.wallSurface.pointFields["osi"],
             &pressure = flow.wallSurface.pointFields["wall_pressure_pa"];
        for (std::size_t v = 0; v < loads.size(); ++v)
        {
            const sim::sph::WallLoadAverage& load = loads[v];
            const bool sampled = load.sampledTimeS > 0.0 && !nearOpenEnd(flow.wallSurface.points[v], planes, depthMm);
            tawss.push_back(sampled ? load.tawssPa : NAN);
            osi.push_back(sampled ? load.osi : NAN);
            pressure.push_back(sampled ? load.meanPressurePa : NAN);
        }
    }
    if (flow.averagedS > 0.0)
    {
        try
        {
            flow.stenosis = sim::sph::stenosisFigures(flow.sectionArcMm, flow.sections, setup.compareMm);
        }
        catch (const Error& error)
        {
            flow.warnings.push_back(storedText(Pattern{"no stenosis figures: %1", {error.message()}}));
        }
    }
    else
        flow.warnings.push_back(storedText(Pattern{
            "the run stopped before its averaging window (from %1 s): no section averages or stenosis figures",
            {numberText(flow.averagedFromS)}}));
    return flow;
}

} // namespace vsim::app
