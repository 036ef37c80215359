// SphSolver's saved runs (SphCheckpoint.h): the run now as a checkpoint, and a checkpoint put in place of the
// particles as given at initialize().

#include "vsim/sim/sph/SphSolver.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <unordered_map>

namespace vsim::sim::sph {
namespace {

/// The checkpoint's counter of the time stepped since the last samples with another stepper (s).
constexpr const char* kPendingSample = "sph_pending_sample_s";

} // namespace

bool SphSolver::goOnFrom(const SphCheckpoint& saved)
{
    const ParticleState& seeded = m_particles;
    std::unordered_map<int, std::size_t> seededWall;
    for (std::size_t i = 0; i < seeded.size(); ++i)
        if (seeded.wall[i])
            seededWall.emplace(seeded.id[i], i);
    ParticleState p = saved.particles;
    std::size_t walls = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
    {
        if (!p.wall[i])
        {
            p.wallDepth[i] = p.guardDepth[i] = -1.0, p.backstop[i] = 0;
            continue;
        }
        const auto found = seededWall.find(p.id[i]);
        // A wall particle stays where it was seeded; the GPU's single precision moves it by far less than this.
        if (found == seededWall.end() || (p.position[i] - seeded.position[found->second]).norm() > 1e-3 * m_spacingM)
            throw Error(Pattern{"the saved run's wall particle %1 is not this run's: the checkpoint belongs to "
                                "another problem",
                                {std::to_string(p.id[i])}});
        const std::size_t j = found->second;
        p.position[i] = seeded.position[j], p.wallDepth[i] = seeded.wallDepth[j];
        p.guardDepth[i] = seeded.guardDepth[j], p.backstop[i] = seeded.backstop[j];
        ++walls;
    }
    if (walls != seededWall.size())
        throw Error(Pattern{"the saved run has %1 wall particles, this run %2: the checkpoint belongs to another "
                            "problem",
                            {std::to_string(walls), std::to_string(seededWall.size())}});
    if (saved.ledger.inflowKg.size() != m_ledger.inflowKg.size())
        throw Error(Pattern{"the saved run has %1 open boundaries, this run %2: the checkpoint belongs to another "
                            "problem",
                            {std::to_string(saved.ledger.inflowKg.size()), std::to_string(m_ledger.inflowKg.size())}});
    if (!m_openBoundaries.empty())
        m_openBoundaries.restoreLast(saved.boundaryFlowRateM3S, saved.boundaryPressurePa);
    m_particles = std::move(p);
    m_timeS = saved.timeS, m_steps = saved.steps, m_ledger = saved.ledger;
    m_nextId = saved.nextId;
    for (int id : m_particles.id)
        m_nextId = std::max(m_nextId, id + 1);
    m_initialFluidMass = saved.initialFluidMassKg;
    if (const auto pending = saved.counters.find(kPendingSample); pending != saved.counters.end())
        m_pendingS = pending->second;
    m_sections.restore(saved.sections), m_wallLoads.restore(saved.wallLoads);
    m_grid->build(m_particles.position);
    const std::size_t n = m_particles.size();
    if (saved.rates.acceleration.size() == n && saved.rates.densityRate.size() == n &&
        saved.rates.wallDistance.size() == n)
    {
        // The first drift moves the particles by the saved shift velocities: a run with the other setting is
        // another problem (a stepper would have none to take, or leave them out).
        const bool savedShifting = saved.rates.shiftVelocity.size() == n;
        if (savedShifting && m_fluid.particleShifting <= 0.0)
            throw Error("the saved run shifted its particles and this run does not (particle_shifting 0): the "
                        "checkpoint belongs to another problem");
        if (!savedShifting && m_fluid.particleShifting > 0.0)
            throw Error("this run shifts its particles (particle_shifting) and the saved run did not: the "
                        "checkpoint belongs to another problem");
        // The saved order is the one the rates are in: kept (the next reorder comes when the run's would).
        m_rates = saved.rates;
        m_rates.densityGradient.assign(n, Eigen::Vector3d::Zero());
        m_rates.guardedWallDistance.assign(n, INFINITY);
        return true;
    }
    m_particles.reorder(*m_grid);
    m_grid->build(m_particles.position);
    return false;
}

SphCheckpoint SphSolver::checkpoint() const
{
    SphCheckpoint c;
    c.particles = particles();
    c.timeS = m_timeS, c.steps = m_steps, c.nextId = m_nextId;
    for (int id : c.particles.id) // the stepper numbers its own
        c.nextId = std::max(c.nextId, id + 1);
    c.ledger = massLedger();
    c.initialFluidMassKg = m_initialFluidMass;
    c.sections = m_sections.sums(), c.wallLoads = m_wallLoads.sums();
    if (m_stepper) // the rates the next kick takes, in the particles' order
        c.rates = m_stepper->nextRates();
    else
    {
        c.rates.acceleration = m_rates.acceleration, c.rates.densityRate = m_rates.densityRate;
        c.rates.shiftVelocity = m_rates.shiftVelocity, c.rates.wallDistance = m_rates.wallDistance;
        c.rates.largestAcceleration = m_rates.largestAcceleration;
        c.rates.largestViscousRate = m_rates.largestViscousRate;
        c.rates.largestKinematicViscosity = m_rates.largestKinematicViscosity;
    }
    for (std::size_t k = 0; k < m_openBoundaries.boundaries().size(); ++k)
    {
        c.boundaryFlowRateM3S.push_back(m_stepper ? m_stepper->flowRate(k) : m_openBoundaries.flowRate(k));
        c.boundaryPressurePa.push_back(m_stepper ? m_stepper->pressure(k) : m_openBoundaries.pressure(k));
    }
    c.counters[kPendingSample] = m_pendingS;
    return c;
}

} // namespace vsim::sim::sph
