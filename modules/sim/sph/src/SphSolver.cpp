#include "vsim/sim/sph/SphSolver.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace vsim::sim::sph {
std::string signedPercentText(double fraction)
{
    std::string text = fraction >= 0.0 ? "+" : ""; // appended: GCC 12's -Wrestrict misreads "+" + std::string&&
    text += numberText(100.0 * fraction);
    return text;
}

std::string positionText(const Eigen::Vector3d& positionM)
{
    const Eigen::Vector3d x = 1e3 * positionM;
    // Appended piece by piece: GCC 12's -Wrestrict misreads "(" + std::string&& here.
    std::string text = "(";
    text += numberText(x.x());
    text += ", ";
    text += numberText(x.y());
    text += ", ";
    text += numberText(x.z());
    text += ") mm";
    return text;
}

std::vector<ParameterSpec> sphParameters()
{
    using K = ParameterSpec::Kind;
    return {
        {"spacing_mm", "Particle spacing", "mm", 0.5, 0.01, 100.0, "Particles",
         "the lattice the particles were seeded on: it sets their mass and the smoothing length", K::Real},
        {"smoothing_ratio", "Smoothing length", "x spacing", 2.0, 1.0, 3.0, "Particles",
         "h as a multiple of the spacing (the support is 2h); at 2 the quartic kernel's first moment on a "
         "lattice is "
         "within 0.2 % of the identity (5.7 % at 1.3: sph-kernel), so pressure gradients come out right",
         K::Real},
        {"density_kg_m3", "Rest density", "kg/m^3", 1060.0, 1.0, 20000.0, "Fluid",
         "blood 1060 (thesis Table 5.1)", K::Real},
        {"viscosity_pa_s", "Dynamic viscosity", "Pa s", 3.5e-3, 0.0, 100.0, "Fluid",
         "blood at high shear about 3.5e-3 (thesis: 3.56e-3)", K::Real},
        {"void_fraction", "Void fraction", "", 0.0, 0.0, 0.99, "Fluid",
         "the gas share of the mixture particles (thesis Table 5.1: 0.2 at the needle injection) where the input "
         "gives none: rest density and viscosity mixed with air's (1.205 kg/m^3, 1.86e-5 Pa s)", K::Real},
        {"sound_speed_m_s", "Numerical sound speed", "m/s", 10.0, 0.01, 1e4, "Fluid",
         "at least 10 times the largest flow speed keeps the density within about 1 % (Monaghan 1994)",
         K::Real},
        {"reference_pressure_pa", "Reference pressure", "Pa", 0.0, -1e6, 1e6, "Fluid",
         "the gauge pressure the rest density stands for (blood flow: the outlets' level): the dynamics work on the "
         "pressure above it, every pressure reported adds it back, and prescribed pressures are gauge (FluidModel.h)",
         K::Real},
        {"delta_sph", "Density diffusion", "", 0.1, 0.0, 1.0, "Numerics",
         "delta of the delta-SPH term (Molteni & Colagrossi 2009; 0 switches it off)", K::Real},
        {"density_summation", "Density by summation", "", 0, 0, 1, "Numerics",
         "1: each fluid particle's density from how closely its neighbours stand, m_i sum_j W_ij scaled so that the "
         "seeding lattice reads the rest density (no continuity equation, so no density diffusion: delta_sph and fpm "
         "have nothing to act on); it cannot drift from the particles' spacing, which the continuity density did in a "
         "stenotic jet's wake; vessels only (a fluid that fills its walls); 0: the continuity equation",
         K::Integer},
        {"density_relaxation_s", "Density relaxation time", "s", 0.0, 0.0, 1e3, "Numerics",
         "> 0: with the continuity equation, each fluid particle's density also relaxes towards its summation density "
         "over this time, so that it cannot drift from the particles' spacing over longer times (a stenotic jet's wake "
         "thinned out by 30 % at a constant continuity density) while keeping the continuity density's smoothness "
         "over shorter ones; a drift at rate r leaves the two about r times this apart; vessels only; 0: off",
         K::Real},
        {"particle_shifting", "Particle shifting", "", 0.0, 0.0, 10.0, "Numerics",
         "A of the shift's coefficient A h |v| (Lind et al. 2012, Skillen et al. 2013; 0: off): the drift also moves "
         "each fluid particle down the gradient of the particles' concentration, which keeps a fast jet's shear layer "
         "from tearing into streaks and voids; vessels only (not with a free surface or without tension)",
         K::Real},
        {"shifting_speed_m_s", "Shifting speed floor", "m/s", 0.0, 0.0, 1e3, "Numerics",
         "> 0: the shift's coefficient is A h max(|v|, this), so that slow zones (a stenosis's separation zone) are "
         "shifted too, where with |v| alone the particles clump and leave voids; the flow's largest speed makes it "
         "the delta+-SPH shift (Sun et al. 2017); 0: |v| alone",
         K::Real},
        {"shift_correction", "Shift correction", "", 0, 0, 1, "Numerics",
         "1: with particle shifting, a shifted particle's velocity follows it to where the shift moves it, "
         "v + dr . grad v (Lind et al. 2012's Taylor correction); 0: the particle keeps its velocity",
         K::Integer},
        {"fpm", "Finite Particle Method", "", 0, 0, 1, "Numerics",
         "1: the density rate from the velocity's divergence and the density diffusion's gradient by the first-order "
         "Finite Particle Method (thesis eq. 5.17), exact for linear fields where walls or a free surface cut the "
         "kernel; 0: the SPH sums",
         K::Integer},
        // down to 0.001: a stenosis's jet at throat Re 1000 takes 0.0048 (StenosisPipe::atFlow)
        {"cfl", "Courant number", "", 0.2, 0.001, 1.0, "Numerics", "the adaptive step's safety factor", K::Real},
        {"gravity_x_m_s2", "Gravity x", "m/s^2", 0.0, -100.0, 100.0, "Fluid", "patient frame (LPS)", K::Real},
        {"gravity_y_m_s2", "Gravity y", "m/s^2", 0.0, -100.0, 100.0, "Fluid",
         "patient frame (LPS): a supine patient's gravity is +9.81 (posterior)", K::Real},
        {"gravity_z_m_s2", "Gravity z", "m/s^2", 0.0, -100.0, 100.0, "Fluid", "patient frame (LPS)", K::Real},
        {"end_time_s", "End time", "s", 0.1, 0.0, 1e4, "Time", "simulated time", K::Real},
        {"density_guard", "Density guard", "", 0.03, 1e-4, 1.0, "Guards",
         "the run stops when a fluid particle's density is further than this from the rest density "
         "(relative)",
         K::Real},
        {"fluid_loss_guard", "Fluid loss guard", "", 0.0, 0.0, 1.0, "Guards",
         "> 0: the run stops when the fluid's net outflow through the open ends (outflow - inflow, the mass ledger's) "
         "exceeds this share of its first fluid mass: a vessel whose particles thin out while their densities still "
         "read full (the continuity density's drift: density_relaxation_s) empties, and its figures are not a flow's; "
         "0: off (a domain that fills: an injection)",
         K::Real},
        {"escape_margin_mm", "Escape margin", "mm", 5.0, 0.0, 1e4, "Guards",
         "the run stops when a particle leaves the particles' starting box grown by this", K::Real},
        {"reorder_every", "Reorder every", "steps", 20, 1, 1e6, "Numerics",
         "the particles are sorted by neighbour cell every so many steps", K::Integer},
        {"body_force_x_m_s2", "Body force x", "m/s^2", 0.0, -1e5, 1e5, "Fluid",
         "a driving force per unit mass (a pressure gradient over the density) in a periodic pipe or channel", K::Real},
        {"body_force_y_m_s2", "Body force y", "m/s^2", 0.0, -1e5, 1e5, "Fluid", "as body_force_x_m_s2", K::Real},
        {"body_force_z_m_s2", "Body force z", "m/s^2", 0.0, -1e5, 1e5, "Fluid", "as body_force_x_m_s2", K::Real},
        {"body_force_frequency_hz", "Body force frequency", "Hz", 0.0, 0.0, 1e5, "Fluid",
         "> 0: the body force oscillates as cos(2 pi f t) (Womersley flow); 0: steady", K::Real},
        {"periodic_x_mm", "Periodic length x", "mm", 0.0, 0.0, 1e4, "Domain",
         "validation channels: > 0 makes the domain [0, L) wrap around along x (0: open)", K::Real},
        {"periodic_y_mm", "Periodic length y", "mm", 0.0, 0.0, 1e4, "Domain", "as periodic_x_mm, along y", K::Real},
        {"periodic_z_mm", "Periodic length z", "mm", 0.0, 0.0, 1e4, "Domain", "as periodic_x_mm, along z", K::Real},
        {"free_surface", "Free surface", "", 0, 0, 1, "Walls",
         "1 for a liquid with a free surface (a tank, a dam break): the walls hold no suction above it; 0 in vessels",
         K::Integer},
        {"fluid_tension", "Tension in the fluid", "", 1, 0, 1, "Fluid",
         "1: a density below the rest density pulls the fluid together (Tait's negative pressure; vessels, tanks); 0: "
         "a liquid that breaks up (a stream falling from a needle, a splash): each particle's density is held at its "
         "rest density or above, its pressure at 0 or above, and the density guard reads compression only",
         K::Integer},
        {"wall_repulsion", "Wall repulsion", "x c0^2", 0.0, 0.0, 1.0, "Walls",
         "the walls' Lennard-Jones backstop (thesis ch. 5.4, Monaghan 1994): a wall particle closer than 0.9 spacings "
         "pushes a fluid particle away with D ((r0 / r)^12 - (r0 / r)^4) / r, D this times c0^2 (0.01: about the "
         "largest flow speed squared); it holds fluid out of walls thinner than the kernel, but empties a throat "
         "a few particles across (sph-stenosis at 0.2 mm: area ratio 4.97 against 3.34 without): 0, off",
         K::Real},
        {"absorption_distance_mm", "Absorption distance", "mm", 0.0, 0.0, 100.0, "Walls",
         "tracer particles (an injected drug) this close to a wall's surface are absorbed and counted (0: none)",
         K::Real},
    };
}

void SphSolver::initialize(const SimulationInput& input, const ParameterSet& parameters)
{
    const ParticleSet& given = input.get<ParticleSet>("particles");
    given.validate();
    if (!given.fields.count("wall"))
        throw Error("the SPH input's particles need the field 'wall' (1 at wall particles, 0 in the fluid)");
    // Every field the input gives is read: a misspelt one ("void_fractoin") would otherwise be dropped
    // without a word and the run go on with the default it meant to replace.
    static const std::set<std::string> readFields = {"wall",           "wall_depth_mm",  "open_boundary",
                                                     "tracer",         "pressure_pa",    "velocity_x_m_s",
                                                     "velocity_y_m_s", "velocity_z_m_s", "void_fraction"};
    for (const auto& field : given.fields)
        if (!readFields.count(field.first))
            throw Error(storedText(Pattern{
                "the SPH input's particles carry the field '%1', which the solver does not read (it reads "
                "wall, wall_depth_mm, open_boundary, tracer, pressure_pa, velocity_x_m_s, velocity_y_m_s, "
                "velocity_z_m_s and void_fraction): is it misspelt?",
                {field.first}}));
    const double spacing = parameters.get("spacing_mm") * 1e-3;
    m_spacingM = spacing;
    m_kernel = std::make_unique<QuarticKernel>(parameters.get("smoothing_ratio") * spacing);
    const Eigen::Vector3d period =
        1e-3 * Eigen::Vector3d(parameters.get("periodic_x_mm"), parameters.get("periodic_y_mm"), parameters.get("periodic_z_mm"));
    m_grid = std::make_unique<NeighbourGrid>(m_kernel->support(), period);
    m_fluid.restDensity = parameters.get("density_kg_m3");
    m_fluid.viscosity = parameters.get("viscosity_pa_s");
    m_fluid.soundSpeed = parameters.get("sound_speed_m_s");
    m_fluid.densityDiffusion = parameters.get("delta_sph");
    m_fluid.particleShifting = parameters.get("particle_shifting");
    m_fluid.shiftingReciprocalWeight = 1.0 / m_kernel->value(spacing);
    m_fluid.shiftingSpeedMS = parameters.get("shifting_speed_m_s");
    m_fluid.shiftCorrection = parameters.get("shift_correction") > 0.5;
    m_fluid.finiteParticleMethod = parameters.get("fpm") > 0.5;
    m_fluid.referencePressurePa = parameters.get("reference_pressure_pa");
    m_fluid.wallRepulsion = parameters.get("wall_repulsion") * m_fluid.soundSpeed * m_fluid.soundSpeed;
    m_fluid.wallRepulsionRange = kWallRepulsionReach * spacing;
    m_fluid.tension = parameters.get("fluid_tension") > 0.5;
    if (m_fluid.particleShifting > 0.0 && (parameters.get("free_surface") > 0.5 || !m_fluid.tension))
        throw Error("particle shifting (particle_shifting > 0) needs a fluid that fills its vessel: a free surface "
                    "(free_surface 1) or a fluid without tension (fluid_tension 0) would be pushed apart at its edge; "
                    "set particle_shifting 0");
    m_fluid.densitySummation = parameters.get("density_summation") > 0.5;
    if (m_fluid.densitySummation && (parameters.get("free_surface") > 0.5 || !m_fluid.tension))
        throw Error("density by summation (density_summation 1) needs a fluid that fills its vessel: at a free surface "
                    "(free_surface 1) or the edge of a liquid without tension (fluid_tension 0) the particles' sums "
                    "fall short and would read as suction; set density_summation 0");
    if (m_fluid.densitySummation && m_fluid.finiteParticleMethod)
        throw Error("the Finite Particle Method (fpm 1) corrects the continuity equation's density rate, which density "
                    "by summation (density_summation 1) does not use: set one of them to 0");
    m_fluid.densityRelaxationS = parameters.get("density_relaxation_s");
    const bool filledVessel = parameters.get("free_surface") < 0.5 && m_fluid.tension;
    if (m_fluid.densityRelaxationS > 0.0 && (m_fluid.densitySummation || !filledVessel))
        throw Error("the density's relaxation towards summation (density_relaxation_s > 0) is for the continuity "
                    "density (density_summation 0) of a fluid that fills its vessel (free_surface 0, fluid_tension "
                    "1): set density_relaxation_s 0");
    if (m_fluid.densitySummation) // nothing to diffuse: no density rate
        m_fluid.densityDiffusion = 0.0;
    m_fluid.summationScale = 1.0 / (spacing * spacing * spacing * m_kernel->latticeSum(spacing));
    m_fluid.bodyForce = {parameters.get("body_force_x_m_s2"), parameters.get("body_force_y_m_s2"),
                         parameters.get("body_force_z_m_s2")};
    m_fluid.bodyForceFrequency = parameters.get("body_force_frequency_hz");
    m_fluid.gravity = {parameters.get("gravity_x_m_s2"), parameters.get("gravity_y_m_s2"),
                       parameters.get("gravity_z_m_s2")};
    m_cfl = parameters.get("cfl");
    m_endTimeS = parameters.get("end_time_s");
    m_densityGuard = parameters.get("density_guard");
    m_fluidLossGuard = parameters.get("fluid_loss_guard");
    m_reorderEvery = int(parameters.get("reorder_every"));
    m_timeS = 0.0, m_steps = 0;

    m_particles = ParticleState();
    const double volume = spacing * spacing * spacing;
    const auto givenVoid = given.fields.find("void_fraction");
    const double defaultVoid = parameters.get("void_fraction");
    const auto pressure = given.fields.find("pressure_pa");
    const auto vx = given.fields.find("velocity_x_m_s"), vy = given.fields.find("velocity_y_m_s"),
               vz = given.fields.find("velocity_z_m_s");
    const int velocityFields = int(vx != given.fields.end()) + int(vy != given.fields.end()) + int(vz != given.fields.end());
    if (velocityFields != 0 && velocityFields != 3)
        throw Error("the SPH input gives some of the particles' velocity components, not all three: give "
                    "velocity_x_m_s, velocity_y_m_s and velocity_z_m_s together");
    const auto depth = given.fields.find("wall_depth_mm");
    const auto buffer = given.fields.find("open_boundary"), tracer = given.fields.find("tracer");
    m_absorptionDistanceM = parameters.get("absorption_distance_mm") * 1e-3;
    m_freeSurface = parameters.get("free_surface") > 0.5;
    if (given.size() == 0)
        throw Error("the SPH input has no particles");
    m_boxLow = m_boxHigh = m_grid->wrap(given.positionsMm.front() * 1e-3);
    for (std::size_t i = 0; i < given.size(); ++i)
    {
        const Eigen::Vector3d x = m_grid->wrap(given.positionsMm[i] * 1e-3);
        const bool isWall = given.fields.at("wall")[i] > 0.5;
        // Wall particles imitate the fluid they hold: the parameter's mixture.
        const double voidFraction =
            isWall || givenVoid == given.fields.end() ? defaultVoid : std::clamp(givenVoid->second[i], 0.0, 0.99);
        const double rho = pressure == given.fields.end()
                               ? m_fluid.mixtureDensity(voidFraction)
                               : m_fluid.densityAt(pressure->second[i] - m_fluid.referencePressurePa, voidFraction);
        m_particles.add(x, rho, m_fluid.mixtureDensity(voidFraction) * volume, isWall,
                        depth == given.fields.end() ? -1.0 : depth->second[i] * 1e-3, voidFraction);
        if (velocityFields == 3)
            m_particles.velocity.back() = {vx->second[i], vy->second[i], vz->second[i]};
        if (buffer != given.fields.end() && !isWall)
            m_particles.boundary.back() = std::uint8_t(std::clamp(std::lround(buffer->second[i]), 0L, 255L));
        if (tracer != given.fields.end())
            m_particles.tracer.back() = tracer->second[i] > 0.5 ? 1 : 0;
        m_boxLow = m_boxLow.cwiseMin(x), m_boxHigh = m_boxHigh.cwiseMax(x);
    }
    const double margin = parameters.get("escape_margin_mm") * 1e-3;
    m_boxLow.array() -= margin, m_boxHigh.array() += margin;
    for (int a = 0; a < 3; ++a) // nothing escapes along a periodic axis
        if (period[a] > 0.0)
            m_boxLow[a] = -INFINITY, m_boxHigh[a] = INFINITY;
    m_nextId = int(given.size());
    m_sections.reset();
    m_wallLoads.reset();
    m_ledger = {};
    m_ledger.inflowKg.assign(m_openBoundaries.boundaries().size(), 0.0);
    m_ledger.outflowKg.assign(m_openBoundaries.boundaries().size(), 0.0);
    m_openBoundaries.setReferencePressure(m_fluid.referencePressurePa);
    m_openBoundaries.checkBufferDepths(m_particles, m_kernel->support(), spacing);
    m_openBoundaries.initialize(m_particles, m_kernel->support(), spacing);
    releaseBackstopAtOpenEnds();
    for (std::size_t i = 0; i < m_particles.size(); ++i) // a buffer holds what its boundary lets in
        if (m_particles.boundary[i])
            m_particles.tracer[i] = m_openBoundaries.boundaries()[m_particles.boundary[i] - 1u].tracer ? 1 : 0;
    m_grid->build(m_particles.position);
    m_particles.reorder(*m_grid); // neighbours near in memory
    m_grid->build(m_particles.position);
    setGuardDepths();
    m_initialFluidMass = fluidMass();
    m_stepper.reset(), m_stale = false, m_pendingS = 0.0;
    m_tookSavedRates = m_startState && goOnFrom(*m_startState);
    if (!m_tookSavedRates)
        updateRates(m_timeS);
    m_stepS = stableTimeStep(m_rates, *m_kernel, m_fluid, m_cfl);
    if (m_stepperFactory)
        m_stepper = m_stepperFactory(*this);
    if (m_stepper)
    {
        // Sampled where the particles come back (every m_syncEvery steps), each sample weighted by its time.
        m_sections.sampleEveryCall(), m_wallLoads.sampleEveryCall();
        // The mass balance against the stepper's own masses (the GPU's are single precision).
        m_stale = true;
        if (!m_startState)
            m_initialFluidMass = fluidMass();
    }
}

const ParticleState& SphSolver::particles() const
{
    if (m_stepper && m_stale)
        m_particles = m_stepper->download(), m_stale = false;
    return m_particles;
}

StepOutcome SphSolver::stepElsewhere()
{
    const std::string guard = m_stepper->step();
    m_timeS = m_stepper->timeS(), m_stepS = m_stepper->lastStepS(), m_pendingS += m_stepS, m_stale = true;
    ++m_steps;
    if (!guard.empty())
        return StepOutcome::guard(guard);
    if (const std::string loss = fluidLossText(m_timeS); !loss.empty())
        return StepOutcome::guard(loss);
    if (m_steps % m_syncEvery == 0 || m_timeS >= m_endTimeS)
    {
        const ParticleState& p = particles();
        m_grid->build(p.position);
        m_sections.sample(p, m_fluid, m_timeS, m_pendingS);
        m_wallLoads.sample(p, *m_grid, *m_kernel, m_fluid, m_spacingM, m_timeS, m_pendingS);
        m_pendingS = 0.0;
    }
    return {};
}

SphStepSettings SphSolver::stepSettings() const
{
    SphStepSettings settings;
    settings.cfl = m_cfl, settings.densityGuard = m_densityGuard, settings.spacingM = m_spacingM;
    settings.freeSurface = m_freeSurface;
    settings.boxLowM = m_boxLow, settings.boxHighM = m_boxHigh;
    settings.periodicLengthM = m_grid ? m_grid->periodicLength() : Eigen::Vector3d::Zero();
    settings.openBoundaries = !m_openBoundaries.empty();
    settings.absorption = m_absorptionDistanceM > 0.0;
    return settings;
}

long double SphSolver::fluidMass() const
{
    const ParticleState& p = particles();
    long double mass = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.isFluid(i))
            mass += p.mass[i];
    return mass;
}

void SphSolver::updateRates(double timeS)
{
    if (m_fluid.densitySummation)
        summationDensity(m_particles, *m_grid, *m_kernel, m_fluid);
    if (!m_openBoundaries.empty())
        m_openBoundaries.impose(m_particles, *m_grid, *m_kernel, m_fluid, timeS);
    extrapolateWallPressure(m_particles, *m_grid, *m_kernel, m_fluid, m_freeSurface);
    computeRates(m_particles, pressures(m_particles, m_fluid), *m_grid, *m_kernel, m_fluid, timeS, m_rates);
}

StepOutcome SphSolver::step(RunStatus&, const Progress&)
{
    m_tookSavedRates = false;
    if (m_stepper)
        return stepElsewhere();
    const double dt = std::min(stableTimeStep(m_rates, *m_kernel, m_fluid, m_cfl), m_endTimeS - m_timeS);
    const ParticleState before = m_particles;
    const SphRates ratesBefore = m_rates;
    const MassLedger ledgerBefore = m_ledger;
    const int nextIdBefore = m_nextId;
    ParticleState& p = m_particles;
    // Kick and drift with the rates at the start of the step, then the second kick with the rates at the
    // drifted positions (leapfrog, kick-drift-kick); the wall particles stay where they are, the buffer particles
    // drift with their imposed velocities.
    const bool shifting = !m_rates.shiftVelocity.empty();
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        p.density[i] += 0.5 * dt * m_rates.densityRate[i];
        if (p.wall[i])
            continue;
        p.density[i] = std::max(p.density[i], m_fluid.densityFloor(p.voidFraction[i]));
        if (!p.boundary[i])
            p.velocity[i] += 0.5 * dt * m_rates.acceleration[i];
        Eigen::Vector3d drift = p.velocity[i];
        if (shifting && !p.boundary[i])
            drift += m_rates.shiftVelocity[i];
        p.position[i] = m_grid->wrap(p.position[i] + dt * drift);
    }
    absorbTracer();
    if (!m_openBoundaries.empty())
        m_openBoundaries.exchange(p, m_nextId, m_ledger);
    // Puts the state before the step back and stops the run with what went wrong at the step's end time.
    auto putBack = [&](const std::string& what)
    {
        m_particles = before, m_rates = ratesBefore, m_ledger = ledgerBefore, m_nextId = nextIdBefore;
        m_grid->build(m_particles.position);
        return StepOutcome::guard(storedText(Pattern{"at t = %1 s %2", {numberText(m_timeS + dt), what}}));
    };
    try
    {
        m_grid->build(p.position);
        if ((m_steps + 1) % m_reorderEvery == 0) // the rates are recomputed below, in the new order
        {
            p.reorder(*m_grid);
            m_grid->build(p.position);
        }
    }
    catch (const Error& error)
    {
        return putBack(storedText(Pattern{"(sorting the particles): %1", {error.message()}}));
    }
    updateRates(m_timeS + dt);
    double worstDensity = 0.0;
    std::size_t worst = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        const bool fluid = p.isFluid(i);
        p.density[i] += 0.5 * dt * m_rates.densityRate[i];
        if (!p.wall[i])
            p.density[i] = std::max(p.density[i], m_fluid.densityFloor(p.voidFraction[i]));
        if (fluid)
            p.velocity[i] += 0.5 * dt * m_rates.acceleration[i];
        const double variation = m_fluid.densityVariation(p.density[i], p.voidFraction[i]);
        if (!std::isfinite(variation) || !p.position[i].allFinite() || !p.velocity[i].allFinite())
            return putBack(storedText(Pattern{"particle %1 has a value that is not finite", {std::to_string(p.id[i])}}));
        if (fluid && variation > worstDensity)
            worstDensity = variation, worst = i;
        if ((p.position[i].array() < m_boxLow.array()).any() ||
            (p.position[i].array() > m_boxHigh.array()).any())
            return putBack(storedText(Pattern{
                "particle %1 left the domain (through a wall or an open end without an outlet)", {std::to_string(p.id[i])}}));
        // Through the wall: a fluid particle deeper than half a spacing below the surface the wall particles
        // describe by their guard depths (ParticleState::guardDepth: the lattice's own surface where a smooth
        // wall steps). Half, not less: the fluid packs up to a few tenths of a spacing closer to a wall than it was
        // seeded (at a quarter spacing sph-stenosis's converging side stopped the run at 11.5 ms). Not against the
        // walls around an open end's buffer, which hands fluid over as close to them as it came (SphRates.h).
        if (fluid && m_rates.guardedWallDistance[i] < -0.5 * m_spacingM)
            return putBack(storedText(Pattern{
                "fluid particle %1 went %2 mm into the wall at %3: the time step or the sound speed is too large for "
                "the flow, or the wall thinner than the kernel (a segmentation's ragged edge: the walls' backstop, "
                "parameter wall_repulsion 0.01)",
                {std::to_string(p.id[i]), numberText(-1e3 * m_rates.guardedWallDistance[i]), positionText(p.position[i])}}));
    }
    if (worstDensity > m_densityGuard)
    {
        const std::string where =
            std::isfinite(m_rates.wallDistance[worst])
                ? storedText(Pattern{"%1 mm from the wall", {numberText(1e3 * m_rates.wallDistance[worst])}})
                : storedText("away from the walls");
        const double departure = m_fluid.densityDeparture(p.density[worst], p.voidFraction[worst]);
        return putBack(storedText(Pattern{"particle %1's density is %2 % from the rest density (guard %3 %) at %4, "
                                          "%5: raise the sound speed or lower the inflow",
                                          {std::to_string(p.id[worst]), signedPercentText(departure),
                                           numberText(100.0 * m_densityGuard),
                                           positionText(p.position[worst]), where}}));
    }
    if (const std::string loss = fluidLossText(m_timeS + dt); !loss.empty())
    {
        StepOutcome outcome = putBack(""); // the state before the step, with the loss's own words
        outcome.message = loss;
        return outcome;
    }
    m_timeS += dt;
    m_stepS = dt;
    ++m_steps;
    m_sections.sample(p, m_fluid, m_timeS, dt);
    m_wallLoads.sample(p, *m_grid, *m_kernel, m_fluid, m_spacingM, m_timeS, dt);
    return {};
}

std::string SphSolver::fluidLossText(double timeS) const
{
    if (!(m_fluidLossGuard > 0.0) || !(m_initialFluidMass > 0.0))
        return {};
    const MassLedger& ledger = massLedger();
    const double share = double((ledger.totalOutflow() - ledger.totalInflow()) / m_initialFluidMass);
    if (share <= m_fluidLossGuard)
        return {};
    return storedText(Pattern{"at t = %1 s the vessel has lost %2 % of its first fluid mass through its "
                              "open ends (outflow - inflow; fluid_loss_guard %3 %): its particles no longer fill "
                              "it, so its figures would not be a flow's; relax the density towards summation "
                              "(density_relaxation_s) or raise the sound speed",
                              {numberText(timeS), numberText(100.0 * share), numberText(100.0 * m_fluidLossGuard)}});
}

void SphSolver::releaseBackstopAtOpenEnds()
{
    // A buffer moves along its end's normal past the wall particles around it, which sit on the lattice: the fluid
    // it hands over stands as close to them as it came (0.23 spacings on the stenosis phantom), and the backstop
    // would push it off. Those walls are straight and a kernel deep: they need none.
    const double reach = m_kernel->support();
    ParticleState& p = m_particles;
    for (std::size_t k = 0; k < m_openBoundaries.boundaries().size(); ++k)
    {
        const OpenBoundary& b = m_openBoundaries.boundaries()[k];
        for (std::size_t i = 0; i < p.size(); ++i)
        {
            const double along = m_openBoundaries.signedDistance(k, p.position[i]);
            const Eigen::Vector3d offset = p.position[i] - b.centreM;
            if (p.wall[i] && along < reach && along > -2.0 * reach &&
                (offset - offset.dot(b.normal) * b.normal).norm() <= b.radiusM + reach)
                p.backstop[i] = 0;
        }
    }
}

void SphSolver::setGuardDepths()
{
    // The surface a wall's own particles make lies half a spacing beyond the fluid particle nearest each of them
    // (as ParticleSeeding measures a label's walls). A smooth wall seeded on a lattice (the analytic phantoms)
    // steps: on sph-stenosis's diverging side at 0.1 mm the fluid filled a notch 0.5 spacings below the smooth
    // surface without nearing a wall particle, and the guard stopped the jet at a throat Re of 97 and 200
    // (2026-11-30, RESULTS.md). A wall particle beyond the support from the fluid keeps its given depth.
    ParticleState& p = m_particles;
    const double half = 0.5 * m_spacingM;
#pragma omp parallel for schedule(dynamic, 256)
    for (int i = 0; i < int(p.size()); ++i)
    {
        const std::size_t si = std::size_t(i);
        if (!p.wall[si] || p.wallDepth[si] < 0.0)
            continue;
        double nearest = INFINITY;
        m_grid->forEachNeighbour(p.position, i, [&](int j, const Eigen::Vector3d&, double r) {
            if (!p.wall[std::size_t(j)])
                nearest = std::min(nearest, r);
        });
        p.guardDepth[si] = std::min(p.wallDepth[si], std::max(0.0, nearest - half));
    }
}

void SphSolver::absorbTracer()
{
    if (!(m_absorptionDistanceM > 0.0))
        return;
    ParticleState& p = m_particles;
    std::vector<std::uint8_t> keep(p.size(), 1);
    bool any = false;
    for (std::size_t i = 0; i < p.size(); ++i) // the wall distances of the step's start
        if (p.isFluid(i) && p.tracer[i] && m_rates.wallDistance[i] < m_absorptionDistanceM)
        {
            keep[i] = 0, any = true;
            m_ledger.absorbedKg += p.mass[i];
        }
    if (any)
        p.keepOnly(keep);
}

SimulationData SphSolver::snapshot() const
{
    const ParticleState& p = particles();
    std::vector<std::size_t> byId(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        byId[i] = i;
    std::sort(byId.begin(), byId.end(), [&p](std::size_t a, std::size_t b) { return p.id[a] < p.id[b]; });
    ParticleSet frame;
    frame.positionsMm.resize(p.size());
    const char* names[] = {"speed_m_s", "velocity_x_m_s", "velocity_y_m_s", "velocity_z_m_s", "pressure_pa",
                           "density_kg_m3", "void_fraction", "wall", "open_boundary", "tracer"};
    std::vector<std::vector<double>*> fields;
    for (const char* name : names)
        fields.push_back(&(frame.fields[name] = std::vector<double>(p.size())));
    for (std::size_t k = 0; k < p.size(); ++k)
    {
        const std::size_t i = byId[k];
        frame.positionsMm[k] = p.position[i] * 1e3;
        const double values[] = {p.velocity[i].norm(), p.velocity[i].x(), p.velocity[i].y(), p.velocity[i].z(),
                                 m_fluid.reportedPressure(p.density[i], p.voidFraction[i]), p.density[i],
                                 p.voidFraction[i], double(p.wall[i]), double(p.boundary[i]), double(p.tracer[i])};
        for (std::size_t f = 0; f < fields.size(); ++f)
            (*fields[f])[k] = values[f];
    }
    return frame;
}

std::map<std::string, double> SphSolver::metrics() const
{
    const ParticleState& p = particles();
    double fluid = 0.0, speed = 0.0, density = 0.0, energy = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (p.isFluid(i))
        {
            ++fluid;
            speed = std::max(speed, p.velocity[i].norm());
            density = std::max(density, m_fluid.densityVariation(p.density[i], p.voidFraction[i]));
            energy += 0.5 * p.mass[i] * p.velocity[i].squaredNorm();
        }
    std::map<std::string, double> metrics{{"particles", double(p.size())}, {"fluid_particles", fluid},
                                          {"time_step_s", m_stepS},        {"steps", double(m_steps)},
                                          {"largest_speed_m_s", speed},    {"largest_density_variation", density},
                                          {"kinetic_energy_j", energy},    {"fluid_mass_kg", double(fluidMass())}};
    if (m_openBoundaries.empty() && !(m_absorptionDistanceM > 0.0))
        return metrics;
    const MassLedger& ledger = massLedger();
    metrics["inflow_kg"] = double(ledger.totalInflow());
    metrics["outflow_kg"] = double(ledger.totalOutflow());
    metrics["absorbed_kg"] = double(ledger.absorbedKg);
    metrics["fluid_mass_change_kg"] = double(fluidMass() - m_initialFluidMass);
    const std::vector<OpenBoundary>& boundaries = m_openBoundaries.boundaries();
    for (std::size_t k = 0; k < boundaries.size(); ++k)
    {
        std::string key = boundaries[k].name;
        std::replace(key.begin(), key.end(), ' ', '_');
        metrics[key + "_flow_rate_ml_s"] = 1e6 * (m_stepper ? m_stepper->flowRate(k) : m_openBoundaries.flowRate(k));
        metrics[key + "_pressure_pa"] =
            m_fluid.referencePressurePa + (m_stepper ? m_stepper->pressure(k) : m_openBoundaries.pressure(k));
        metrics[key + "_net_inflow_kg"] = double(ledger.inflowKg[k] - ledger.outflowKg[k]);
    }
    return metrics;
}

} // namespace vsim::sim::sph
