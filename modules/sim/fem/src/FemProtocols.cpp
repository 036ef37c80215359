#include "vsim/sim/fem/FemProtocols.h"

#include "vsim/core/Error.h"
#include "vsim/core/PrincipalAxis.h"
#include "vsim/core/Units.h"
#include "vsim/sim/fem/QuasiStaticTearing.h"
#include "vsim/sim/fem/StaticWallRun.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace vsim::sim::fem {

ElasticMaterial femMaterial(const ParameterSet& p)
{
    ElasticMaterial material;
    material.model = p.get("material_model") > 0.5 ? ElasticMaterial::Model::StVenantKirchhoff
                                                   : ElasticMaterial::Model::CorotationalLinear;
    material.youngModulusPa = units::mpaToPa(p.get("young_modulus_mpa"));
    material.poissonRatio = p.get("poisson_ratio");
    material.densityKgPerM3 = p.get("density_kg_m3");
    return material;
}

BackwardEulerSettings femIntegrator(const ParameterSet& p)
{
    BackwardEulerSettings settings;
    settings.timeStep = 1e-3 * p.get("time_step_ms");
    settings.rayleighAlpha = p.get("rayleigh_alpha");
    settings.rayleighBeta = p.get("rayleigh_beta_s");
    settings.cgTolerance = p.get("cg_tolerance");
    settings.cgMaxIterations = int(p.get("cg_max_iterations"));
    settings.preconditioner = p.get("cg_preconditioner") > 0.5 ? CgPreconditioner::Multigrid : CgPreconditioner::BlockJacobi;
    return settings;
}

std::vector<ParameterSpec> femParameters()
{
    const std::string material = "Material", integration = "Integration", thesis = "Thesis rupture protocol",
                      physiological = "Physiological protocol", patient = "Patient (wall strength)";
    return {
        {"material_model", "Material model", "", 0, 0, 1, material,
         "0: co-rotational linear elasticity (thesis), 1: St. Venant-Kirchhoff (Green strain; CPU only).",
         ParameterSpec::Kind::Integer},
        {"young_modulus_mpa", "Young's modulus", "MPa", 4.23, 0.01, 1000, material, "Wall stiffness (thesis patient 1: 4.23 MPa)."},
        {"poisson_ratio", "Poisson's ratio", "", 0.23, 0.0, 0.49, material, "Thesis: 0.23 (printed as 0.23 MPa, a typo)."},
        {"density_kg_m3", "Density", "kg/m^3", 1100, 500, 3000, material, "Wall density (lumped mass)."},
        {"time_step_ms", "Time step", "ms", 1.0, 0.01, 100, integration, "Backward Euler step."},
        {"rayleigh_alpha", "Rayleigh alpha", "1/s", 0.0, 0.0, 1000, integration, "Mass-proportional damping (thesis: 0)."},
        {"rayleigh_beta_s", "Rayleigh beta", "s", 0.22, 0.0, 10, integration, "Stiffness-proportional damping (thesis: 0.22 s)."},
        {"cg_tolerance", "PCG tolerance", "", 1e-6, 1e-12, 1e-1, integration, "Relative residual of the implicit solve."},
        {"cg_max_iterations", "PCG iterations", "", 100, 1, 100000, integration, "Largest number of PCG iterations per step.",
         ParameterSpec::Kind::Integer},
        {"cg_preconditioner", "PCG preconditioner", "", 0, 0, 1, integration,
         "0: block Jacobi (the thesis's; hundreds of iterations to 1e-8 on a wall), 1: smoothed-aggregation multigrid "
         "(tens of iterations, each about five products; set up on the host at the first step; CPU and CUDA). With "
         "1, a tolerance of 1e-8 and a cap of a few hundred every step converges.",
         ParameterSpec::Kind::Integer},
        {"pressure_start_mpa", "Ramp start", "MPa", 8, 0, 100, thesis, "Mid-vessel pressure at the start of the ramp."},
        {"pressure_end_mpa", "Ramp end", "MPa", 12, 0, 100, thesis, "Mid-vessel pressure at the end of the ramp."},
        {"ramp_steps", "Ramp steps", "", 400, 1, 1000000, thesis, "Time steps of the damped ramp (quasi_static 0).",
         ParameterSpec::Kind::Integer},
        {"ramp_increment_mpa", "Ramp increment", "MPa", 0.25, 1e-4, 100, thesis,
         "Pressure step between the equilibria of the quasi-static ramp (the onset is then found by bisection to "
         "0.5 % whatever the step)."},
        {"loaded_fraction", "Loaded length", "", 1.0 / 3.0, 0.05, 1, thesis,
         "Share of the wall's length (about its middle, along its principal axis) that the pressure acts on."},
        {"tear_strength_mpa", "Tear strength", "MPa", 100, 0.01, 100000, thesis,
         "Largest principal stress at which an element tears (the thesis's tear factor; it does not print a value)."},
        {"quasi_static", "Quasi-static tearing", "", 0, 0, 1, thesis,
         "1: the wall in static equilibrium at each pressure of the ramp, the tearing onset bracketed by bisection to "
         "0.5 %, one element released per equilibrium (does not depend on the ramp); 0: the thesis's damped "
         "ramp, every element over the limit torn in the same step (the onset lags the ramp).",
         ParameterSpec::Kind::Integer},
        {"modified_newton", "Equilibrium iteration", "", 0, 0, 1, thesis,
         "Quasi-static tearing's equilibria. 0: full Newton (the pressure's load stiffness in the tangent, GMRES with "
         "a Cholesky preconditioner; CPU). 1: modified Newton without the load stiffness, its symmetric tangent by "
         "multigrid conjugate gradients (about 3 times the updates; CPU and CUDA, the same tears on both).",
         ParameterSpec::Kind::Integer},
        {"entropy_end", "Fracture entropy end", "nats", 3.9, 0, 20, thesis,
         "Stop once the fracture entropy passes this (3.9: about 50 torn elements' worth)."},
        {"pressure_mmhg", "Blood pressure", "mmHg", 120, 1, 400, physiological, "Systolic pressure on the lumen."},
        {"wall_model", "Wall model", "", 1, 0, 1, physiological,
         "1 (the clinical analysis): quadratic (10-node) tets with the Raghavan & Vorp 2000 hyperelastic AAA wall "
         "(nearly incompressible) and the Wang 2001 thrombus where the wall mesh has one, static equilibrium by load "
         "increments and Newton's method (CPU; on 2 cores about 20 s for 15,000 tets, 45 s for 30,000 with a thrombus "
         "layer, 85 s for the demo's 31,000 around a wide sac); 0: the Material group's law on linear tets, a damped "
         "load path then the equilibrium (GPU path possible; linear tets lock in bending and near incompressibility).",
         ParameterSpec::Kind::Integer},
        {"wall_poisson_ratio", "Wall Poisson's ratio", "", 0.49, 0.45, 0.499, physiological,
         "Near incompressibility of the hyperelastic wall: its bulk modulus from the small-strain shear modulus "
         "(wall model 1)."},
        {"zero_pressure_geometry", "Zero-pressure geometry", "", 0, 0, 1, physiological,
         "1: the unloaded geometry is found first (backward displacement, Bols et al. 2013) so that the loaded wall "
         "is the imaged one; 0: the imaged (loaded) geometry is taken as unloaded (wall model 1).",
         ParameterSpec::Kind::Integer},
        {"flow_wall_pressure", "Blood flow's wall pressure", "", 0, 0, 1, physiological,
         "1: the lumen carries the blood pressure plus the time-averaged wall pressure of the study's newest "
         "blood-flow run (relative to its outlets; one-way coupling), scaled with the load; 0: a uniform pressure "
         "(wall model 1).",
         ParameterSpec::Kind::Integer},
        {"load_increments", "Load increments", "", 1, 1, 100, physiological,
         "Pressure increments, each solved to equilibrium; one that fails is retried at half the size (wall "
         "model 1).", ParameterSpec::Kind::Integer},
        {"settle_time_s", "Load path time", "s", 0.5, 0.1, 100, physiological,
         "Wall model 0: simulated time of the damped load path: the pressure ramps up over its first quarter (beta = 0.22 s). The "
         "figures are those of the static equilibrium solved after it, which does not depend on the path."},
        {"settle_time_step_ms", "Settling time step", "ms", 10, 0.1, 100, physiological,
         "Wall model 0: backward Euler step while settling (the steady state does not depend on it)."},
        {"equilibrium_tolerance", "Equilibrium tolerance", "", 1e-6, 0, 1e-2, physiological,
         "The static equilibrium at the pressure is solved (Newton; GMRES with a sparse Cholesky or LU preconditioner) until ||f_int - f_ext|| / ||f_ext|| "
         "is below this; the figures are that state's. 0 (wall model 0 only): the damped path's last state."},
        {"female", "Female", "", -1, -1, 1, patient,
         "1 female, 0 male (Vande Geest 2006 SEX = +-0.5); -1 not given: no rupture index (never assumed).",
         ParameterSpec::Kind::Integer},
        {"family_history", "Family history of AAA", "", -1, -1, 1, patient,
         "1 with, 0 without a family history (HIST = +-0.5); -1 not given: no rupture index (never assumed).",
         ParameterSpec::Kind::Integer},
        {"thrombus_mm", "Thrombus thickness", "mm", 0, 0, 50, patient, "Local intraluminal thrombus thickness (ILT)."},
        {"reference_diameter_mm", "Reference diameter", "mm", 0, 0, 50, patient,
         "Non-aneurysmal aortic diameter for the normalised diameter (NORD); 0: the sac's neck outer diameter (the "
         "patient's own, from vascusim-cli sac), 20 mm without a sac."},
    };
}

std::vector<ParameterSpec> femProtocolParameters(const std::string& protocol)
{
    std::vector<std::string> groups = {"Material", "Integration"};
    std::vector<std::string> unused;
    if (protocol == "physiological")
        groups.insert(groups.end(), {"Physiological protocol", "Patient (wall strength)"}), unused = {"time_step_ms"};
    else if (protocol == "thesis-rupture")
        groups.push_back("Thesis rupture protocol");
    else if (protocol != "interactive")
        throw Error(Pattern{"unknown protocol '%1' (thesis-rupture, physiological, interactive)", {protocol}});
    std::vector<ParameterSpec> used;
    for (const ParameterSpec& spec : femParameters())
        if (std::find(groups.begin(), groups.end(), spec.group) != groups.end() &&
            std::find(unused.begin(), unused.end(), spec.key) == unused.end())
            used.push_back(spec);
    return used;
}

bool femUsesQuadraticWall(const std::string& protocol, const ParameterSet& parameters)
{
    return protocol == "physiological" && parameters.get("wall_model") > 0.5;
}

bool femUsesQuasiStaticTearing(const std::string& protocol, const ParameterSet& parameters)
{
    return protocol == "thesis-rupture" && parameters.get("quasi_static") > 0.5;
}

std::map<std::string, std::string> femProtocolValues(const ParameterSet& parameters, const std::string& protocol)
{
    // The quadratic hyperelastic wall has its own law and no time stepping: the Material and Integration groups
    // and the load path's settings do not enter it; the linear one has no increments or wall Poisson's ratio.
    const bool quadratic = femUsesQuadraticWall(protocol, parameters);
    const std::vector<std::string> linearOnly = {"settle_time_s", "settle_time_step_ms"},
                                   quadraticOnly = {"wall_poisson_ratio", "load_increments", "zero_pressure_geometry",
                                                    "flow_wall_pressure"};
    const std::map<std::string, std::string> all = parameters.valuesAsText();
    std::map<std::string, std::string> used;
    for (const ParameterSpec& spec : femProtocolParameters(protocol))
    {
        const auto& skip = quadratic ? linearOnly : quadraticOnly;
        if (std::find(skip.begin(), skip.end(), spec.key) != skip.end() ||
            (quadratic && (spec.group == "Material" || spec.group == "Integration")))
            continue;
        used[spec.key] = all.at(spec.key);
    }
    return used;
}

double vandeGeestWallStrength(double thrombusCm, double normalizedDiameter, bool familyHistory, bool female)
{
    const double newtonPerCm2 = 71.9 - 37.9 * (std::sqrt(std::max(thrombusCm, 0.0)) - 0.81) -
                                15.6 * (normalizedDiameter - 2.46) - 21.3 * (familyHistory ? 0.5 : -0.5) +
                                19.3 * (female ? 0.5 : -0.5);
    return newtonPerCm2 * 1e4; // N/cm^2 -> Pa
}

FemRunResult runThesisRupture(const TetMesh& wall, const ParameterSet& p, const Progress& progress,
                              const StepperFactory& stepper, const StaticModelFactory& staticModel)
{
    const PrincipalAxis axis = principalAxis(wall.points);
    const double half = 0.5 * p.get("loaded_fraction") * 2.0 * axis.halfLength;
    const auto loaded = [=](const Eigen::Vector3d& c) { return std::abs((c - axis.centre).dot(axis.direction)) <= half; };
    const double start = units::mpaToPa(p.get("pressure_start_mpa")), end = units::mpaToPa(p.get("pressure_end_mpa"));
    if (femUsesQuasiStaticTearing("thesis-rupture", p))
    {
        QuasiStaticTearingSetup setup;
        setup.wall = wall;
        setup.material = femMaterial(p);
        setup.loaded = loaded;
        setup.startPa = start;
        setup.endPa = end;
        setup.incrementPa = units::mpaToPa(p.get("ramp_increment_mpa"));
        setup.tearStressPa = units::mpaToPa(p.get("tear_strength_mpa"));
        setup.entropyEnd = p.get("entropy_end");
        setup.modifiedNewton = p.get("modified_newton") > 0.5;
        if (setup.modifiedNewton)
            setup.equilibriumElsewhere = staticModel;
        return runQuasiStaticTearing(setup, progress);
    }
    FemRunSetup setup;
    setup.stepper = stepper;
    setup.wall = wall;
    setup.material = femMaterial(p);
    setup.integrator = femIntegrator(p);
    setup.steps = int(p.get("ramp_steps"));
    const double duration = setup.steps * setup.integrator.timeStep;
    setup.pressurePa = [=](double t) { return start + (end - start) * std::clamp(t / duration, 0.0, 1.0); };
    setup.loaded = loaded;
    setup.frameEvery = std::max(1, setup.steps / 40);
    setup.tearing = true;
    setup.tearStressPa = units::mpaToPa(p.get("tear_strength_mpa"));
    setup.entropyEnd = p.get("entropy_end");
    return runFem(setup, progress);
}

namespace {

constexpr double kDefaultReferenceDiameterMm = 20.0; ///< NORD's reference without a given one or a sac's neck
/// The band next to the wall's held ends left out of the sac's peaks (mm): a clamped shell's bending boundary layer
/// decays over about 2.4 sqrt(R t), 15 mm for R 25 mm and t 1.5 mm; 10 mm keeps most of a short sac.
constexpr double kHeldEndBandMm = 10.0;

/// Vande Geest 2006 strength per element and the rupture index stress / strength as cell fields of the last frame,
/// the peak's metrics; returns the index. Inside the sac (with its local geometry) ILT and NORD are the sac's
/// thrombus along the element's radius and its outer diameter there over the reference; elsewhere the diameter is
/// the nearest centerline point's and the thrombus `thrombus_mm`.
std::vector<double> addRuptureIndex(FemRunResult& result, const SkeletonGraph& centerlines, const ParameterSet& p,
                                    const SacRegion* sac)
{
    TetMesh& last = result.frames.back();
    const auto& stress = last.cellFields.at("von_mises_kpa");
    const double reference = p.get("reference_diameter_mm") > 0.0 ? p.get("reference_diameter_mm")
                             : sac && sac->neckDiameterMm > 0.0  ? sac->neckDiameterMm
                                                                 : kDefaultReferenceDiameterMm;
    result.metrics["reference_diameter_used_mm"] = reference;
    const bool female = p.get("female") > 0.5, history = p.get("family_history") > 0.5;
    const double thrombusCm = 0.1 * p.get("thrombus_mm");
    std::vector<double> strength(last.tets.size()), index(last.tets.size());
    std::size_t fromSac = 0;
    const auto material = last.cellFields.find("material");
    for (std::size_t t = 0; t < last.tets.size(); ++t)
    {
        if (material != last.cellFields.end() && material->second[t] > 0.5)
            continue; // thrombus: no wall strength, index 0
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int node : last.tets[t])
            centroid += 0.25 * last.points[std::size_t(node)];
        if (sac && sac->local && sac->contains && sac->contains(centroid))
            if (const LocalSac here = sac->local(centroid); here.outerDiameterMm > 0.0)
            {
                strength[t] = vandeGeestWallStrength(0.1 * here.thrombusMm, here.outerDiameterMm / reference, history, female);
                index[t] = stress[t] * 1e3 / strength[t];
                ++fromSac;
                continue;
            }
        double nearest = 1e300, radius = 0.0;
        for (const auto& edge : centerlines.edges)
            for (std::size_t i = 0; i < edge.points.size(); ++i)
                if (const double d = (edge.points[i] - centroid).squaredNorm(); d < nearest)
                    nearest = d, radius = edge.radii[i];
        strength[t] = vandeGeestWallStrength(thrombusCm, 2.0 * radius / reference, history, female);
        index[t] = stress[t] * 1e3 / strength[t];
    }
    const std::size_t peak = std::size_t(std::max_element(index.begin(), index.end()) - index.begin());
    Eigen::Vector3d where = Eigen::Vector3d::Zero();
    for (int node : last.tets[peak])
        where += 0.25 * last.points[std::size_t(node)];
    result.metrics["peak_rupture_index"] = index[peak];
    result.metrics["peak_rupture_index_x_mm"] = where.x();
    result.metrics["peak_rupture_index_y_mm"] = where.y();
    result.metrics["peak_rupture_index_z_mm"] = where.z();
    result.metrics["strength_at_peak_rupture_index_kpa"] = strength[peak] * 1e-3;
    result.metrics["strength_from_sac_elements"] = double(fromSac);
    for (double& s : strength)
        s *= 1e-3;
    last.cellFields["wall_strength_kpa"] = std::move(strength);
    last.cellFields["rupture_index"] = index;
    return index;
}

} // namespace

namespace {

FemRunResult runLinearPhysiological(const TetMesh& wall, const ParameterSet& p, double pressure, const Progress& progress,
                                    const StepperFactory& stepper)
{
    if (const auto material = wall.cellFields.find("material"); material != wall.cellFields.end() &&
        std::any_of(material->second.begin(), material->second.end(), [](double m) { return m > 0.5; }))
        throw Error("this wall has an intraluminal thrombus layer, which the linear wall model (wall_model 0) cannot "
                    "tell from the wall: run wall_model 1, or build the wall without --thrombus");
    FemRunSetup setup;
    setup.stepper = stepper;
    setup.wall = wall;
    setup.material = femMaterial(p);
    setup.integrator = femIntegrator(p);
    // The load path by pseudo-time (the damped wall follows the pressure ramp; its frames are the run's series),
    // then the static equilibrium at the pressure by Newton's method (WallSimulation::equilibrate): the figures.
    const double settle = p.get("settle_time_s");
    setup.integrator.timeStep = 1e-3 * p.get("settle_time_step_ms");
    setup.pressurePa = [=](double t) { return pressure * std::clamp(t / (0.25 * settle), 0.0, 1.0); };
    setup.steps = std::max(1, int(std::lround(settle / setup.integrator.timeStep)));
    setup.frameEvery = std::max(1, setup.steps / 20);
    setup.equilibriumTolerance = p.get("equilibrium_tolerance");
    return runFem(setup, progress);
}

void addWallStrength(FemRunResult& result, const TetMesh& wall, const SkeletonGraph& centerlines,
                     const ParameterSet& p, const SacRegion* sac, double pressure)
{
    // Wall strength per element (local diameter from the nearest centerline point) and the rupture index, when the
    // patient's sex and family history are given (the strength model needs both; neither is assumed).
    double maxDiameter = 0.0;
    for (const auto& edge : centerlines.edges)
        for (double r : edge.radii)
            maxDiameter = std::max(maxDiameter, 2.0 * r);
    const bool patientGiven = p.get("female") >= 0.0 && p.get("family_history") >= 0.0;
    result.metrics["rupture_index_computed"] = patientGiven ? 1.0 : 0.0;
    std::vector<double> index;
    if (patientGiven)
        index = addRuptureIndex(result, centerlines, p, sac);
    result.metrics["max_diameter_mm"] = maxDiameter;
    result.metrics["pressure_kpa"] = pressure * 1e-3;
    if (sac)
    {
        const TetMesh& frame = result.frames.back();
        // The held ends clamp the wall: their bending boundary layer (Saint-Venant) is no property of the sac. The
        // sac's peaks leave out elements within kHeldEndBandMm of a held node (where the image ends near the sac).
        std::vector<Eigen::Vector3d> held;
        const auto& endSet = wall.pointFields.at("end_set");
        for (std::size_t n = 0; n < wall.points.size(); ++n)
            if (endSet[n] > 0.0)
                held.push_back(wall.points[n]);
        std::size_t nearEnds = 0;
        SacRegion away = *sac;
        away.contains = [&](const Eigen::Vector3d& p) {
            if (!sac->contains(p))
                return false;
            for (const Eigen::Vector3d& h : held)
                if ((h - p).squaredNorm() < kHeldEndBandMm * kHeldEndBandMm)
                {
                    ++nearEnds;
                    return false;
                }
            return true;
        };
        const SacPeak stressPeak = peakInSac(frame, frame.cellFields.at("von_mises_kpa"), away, centerlines);
        result.metrics["sac_elements_near_held_ends"] = double(nearEnds);
        result.metrics["held_end_band_mm"] = kHeldEndBandMm;
        result.metrics["sac_elements"] = double(stressPeak.elements);
        std::vector<std::pair<std::string, SacPeak>> peaks{{"sac_pws", stressPeak}};
        if (!index.empty())
            peaks.push_back({"sac_pwri", peakInSac(frame, index, away, centerlines)});
        for (const auto& [prefix, peak] : peaks)
        {
            const std::string unit = prefix == "sac_pws" ? "_kpa" : "";
            result.metrics[prefix + "_p99" + unit] = peak.percentile99;
            result.metrics[prefix + "_nodal_max" + unit] = peak.nodalMax;
            result.metrics[prefix + "_x_mm"] = peak.whereMm.x();
            result.metrics[prefix + "_y_mm"] = peak.whereMm.y();
            result.metrics[prefix + "_z_mm"] = peak.whereMm.z();
            result.metrics[prefix + "_along_centerline_mm"] = peak.alongCenterlineMm;
            result.metrics[prefix + "_clock_h"] = peak.clockHours;
        }
    }
}

} // namespace

FemRunResult runPhysiological(const TetMesh& wall, const SkeletonGraph& centerlines, const ParameterSet& p,
                              const Progress& progress, const StepperFactory& stepper, const SacRegion* sac)
{
    if (centerlines.edges.empty())
        throw Error("the physiological protocol needs centerlines (for the local diameter)");
    const double pressure = units::mmHgToPa(p.get("pressure_mmhg"));
    FemRunResult result;
    const bool coupled = p.get("flow_wall_pressure") > 0.5;
    if (coupled && !wall.pointFields.count(kLumenExtraPressureField))
        throw Error("flow_wall_pressure 1 needs the blood flow's wall pressure on the wall's lumen (vascusim-cli "
                    "simulate fem or the workstation add it from the study's newest blood-flow run)");
    if (coupled && !femUsesQuadraticWall("physiological", p))
        throw Error("flow_wall_pressure 1 needs wall_model 1 (the quadratic hyperelastic wall)");
    if (femUsesQuadraticWall("physiological", p))
    {
        StaticWallSetup setup;
        setup.wall = wall;
        if (!coupled) // a uniform lumen pressure unless asked for
            setup.wall.pointFields.erase(kLumenExtraPressureField);
        // The wall, and the intraluminal thrombus where the mesh has it (mesh wall with the sac: material 1).
        setup.materials = {HyperelasticMaterial::raghavanVorp2000(p.get("wall_poisson_ratio")),
                           HyperelasticMaterial::wang2001Thrombus(p.get("wall_poisson_ratio"))};
        if (const auto material = wall.cellFields.find("material"); material != wall.cellFields.end())
            for (double m : material->second)
                setup.elementMaterial.push_back(m > 0.5 ? 1 : 0);
        setup.pressurePa = pressure;
        setup.loadIncrements = int(p.get("load_increments"));
        setup.tolerance = p.get("equilibrium_tolerance");
        if (!(setup.tolerance > 0.0))
            throw Error("equilibrium_tolerance 0 (the damped path's last state) needs wall_model 0");
        // The zero-pressure geometry: within 0.05 mm of the image in at most 10 full solves.
        result = p.get("zero_pressure_geometry") > 0.5 ? runStaticWallFromZeroPressure(setup, 10, 0.05, progress)
                                                        : runStaticWall(setup, progress);
    }
    else
        result = runLinearPhysiological(wall, p, pressure, progress, stepper);
    addWallStrength(result, wall, centerlines, p, sac, pressure);
    return result;
}

} // namespace vsim::sim::fem
