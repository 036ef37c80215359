#pragma once

// The flow through a cross-section of a vessel (issue 18: the stenosis metrics, the mass checks): the fluid
// particles in a slab of the given thickness about a plane, within a disk, stand for the section. With V_i = m_i /
// rho_i the particles' volumes and u_i = v_i . n their speeds along the normal:
//   area A = sum V_i / thickness, flow rate Q = sum V_i u_i / thickness, mean velocity Q / A,
//   peak velocity max u_i (the duplex peak velocity's counterpart), mean pressure sum V_i p_i / sum V_i.
// SI: m, m/s, m^3/s, Pa.

#include "vsim/sim/sph/FluidModel.h"
#include "vsim/sim/sph/ParticleState.h"

#include <Eigen/Core>

namespace vsim::sim::sph {

struct CrossSection
{
    Eigen::Vector3d centreM = Eigen::Vector3d::Zero();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitX(); ///< unit, the flow's direction
    double radiusM = 0.0;                              ///< the disk that holds the section
    double thicknessM = 0.0;                           ///< the slab (a few spacings)
};

struct SectionFlow
{
    double areaM2 = 0.0, flowRateM3S = 0.0, meanVelocityMS = 0.0, peakVelocityMS = 0.0, meanPressurePa = 0.0;
    int particles = 0;
};

/// The section's flow from the fluid particles (buffers and walls left out).
SectionFlow sectionFlow(const ParticleState& particles, const FluidModel& fluid, const CrossSection& section);

} // namespace vsim::sim::sph
