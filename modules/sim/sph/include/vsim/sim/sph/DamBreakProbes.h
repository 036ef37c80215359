#pragma once

// The water heights of SPHERIC benchmark 2 (DamBreak.h) where the experiment measured them (Kleefsman et al.
// 2005: four wire probes on the tank's centre line, H1-H3 between the obstacle and the column, H4 in the column),
// read from the particles the way a wire probe reads the water: the height of the water column standing on the
// floor at the probe, up to its first surface.

#include "vsim/sim/sph/ParticleState.h"
#include "vsim/sim/sph/QuarticKernel.h"

#include <array>
#include <vector>

namespace vsim::sim::sph {

/// The probes' x (m) on the tank's centre line y = 0.5 m: H1, H2, H3, H4.
constexpr std::array<double, 4> kDamBreakProbeXM = {0.496, 0.992, 1.488, 2.638};
constexpr double kDamBreakProbeYM = 0.5;

/// The height (m) above the floor (z = 0) of the water standing at (xM, yM): going up the vertical line from the
/// floor, the first height where the occupied fraction sum_j (m_j / rho_j) W(x - x_j) over the fluid and wall
/// particles falls to 1/2 (linear between samples a quarter spacing apart). Walls count as occupied, so the floor
/// does not halve the fraction of a thin layer on it; splashes above the first surface do not count, as they do
/// not wet a wire probe's length continuously. 0 where the floor itself is dry.
double waterHeightM(const ParticleState& particles, const QuarticKernel& kernel, double spacingM, double xM,
                    double yM);

/// The measured heights of the experiment (MARIN, SPHERIC test 2; m), every 20 ms from t = 0 (DamBreakExperiment.cpp).
struct DamBreakExperiment
{
    double intervalS = 0.02;
    std::vector<std::array<double, 4>> heightsM; ///< per sample: H1, H2, H3, H4
    /// The heights at time t (linear between samples); t within the record.
    std::array<double, 4> at(double timeS) const;
    double lastTimeS() const { return intervalS * double(heightsM.size() - 1); }
};
const DamBreakExperiment& damBreakExperiment();

} // namespace vsim::sim::sph
