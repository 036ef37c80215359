#pragma once

// The sph-stenosis validation case's problem (issue 18), public so that the OpenFOAM cross-check
// (tests/bench/bench_sph_openfoam) solves the same one: a rigid pipe of radius R0 narrowed by a cosine stenosis
// R(x) = R0 (1 - 0.25 (1 + cos(pi (x - throat) / half length))) to R0 / 2 (50 % in diameter, area ratio 4), a
// parabolic inflow of the given mean speed, a pressure outlet at 0 Pa, blood as a Newtonian fluid. Sections every
// step along the axis, each a slab two lattice spacings thick, hold the time-averaged flow (CrossSections.h).
// Pulsatile (pulsatile()): the inflow times 1 + a sin(2 pi t / T), averaged over one whole cycle after the flow has
// settled, and over the systole (a tenth of the cycle about the inflow's peak) for the peak-systolic figures.
// mm for the geometry (the patient frame's unit), SI for the flow.

#include "vsim/core/Parameters.h"
#include "vsim/core/ParticleSet.h"
#include "vsim/core/Progress.h"
#include "vsim/sim/sph/CrossSections.h"
#include "vsim/sim/sph/OpenBoundary.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/StenosisFigures.h"
#include "vsim/sim/sph/WallShear.h"

#include <map>
#include <string>
#include <vector>

namespace vsim::sim::sph {

struct StenosisPipe
{
    double spacingMm = 0.1;                           ///< the particle lattice (R0 is 8 spacings)
    double radiusMm = 0.8;                            ///< R0
    double lengthMm = 5.6;                            ///< inlet at x = 0, outlet at x = length
    double throatAtMm = 2.4, halfLengthMm = 0.8;      ///< the narrowing's centre and half its length
    double meanSpeedMS = 0.05;                        ///< the inflow's mean (Re 24 upstream, 48 in the throat)
    double rampS = 0.010;                             ///< the inflow's rise from rest (over 4 L / c0 = 6.4 ms)
    double averageFromS = 0.015, endTimeS = 0.025;    ///< the settled flow's window
    double soundSpeedMS = 4.0;                        ///< the numerical sound speed c0 (80 x the throat's mean)
    double densityKgM3 = 1060.0, viscosityPaS = 3.5e-3; ///< blood
    double smoothingRatio = 2.0;                      ///< the solver's smoothing_ratio h / spacing (the buffers: 2h)
    double particleShifting = 0.0;                    ///< the solver's particle_shifting A (0: off; SphRates.h)
    /// With shifting, the solver's shifting_speed_m_s is the throat's mean speed (throatMeanSpeedMS): with |v|
    /// alone the slow separation zone past the throat clumped (relaxed runs at 0.05 mm stopped at 34-40 ms of 42,
    /// 3 % below the rest density; 2026-12-04, RESULTS.md), with it no particle came within a tenth of a spacing
    /// of another.
    bool shiftCorrection = false;                     ///< the solver's shift_correction (SphRates.h)
    bool densitySummation = false;                    ///< the solver's density_summation (SphRates.h)
    double densityRelaxationS = 0.0;                  ///< the solver's density_relaxation_s (SphRates.h; 0: off)
    double cfl = kStenosisCfl;                        ///< the Courant number (atFlow lowers it for faster jets)
    double wallRepulsion = 0.0;                       ///< the solver's wall_repulsion (the walls' backstop; 0: off)
    double compareMm = 1.6;                           ///< the compared sections' distance from the throat (2 R0)
    double sectionStepMm = 0.2;
    Waveform inflowWaveform;                          ///< multiplies the inflow (empty: steady)
    PhaseWindow systole;                              ///< the sections' systolic window (empty: steady)

    /// The same narrowing at another mean inflow speed (m/s) and pipe length (mm; the throat stays 2.4 mm from the
    /// inlet, so a longer pipe gives the jet room to recover before the outlet), with the sound speed at the same
    /// ratio to the speed, the ramp as long against the pipe's quarter-wave period 4 L / c0 and the window after 1.5 to
    /// 2.5 jet transits ((length - throat) / the throat's mean speed) past the ramp, and the Courant number
    /// scaled by min(1, this pipe's throat Re / the new one's) (from kStenosisCfl at Re 48): at a throat Re of 97 the jet blew up at 0.1 (the density 3 %
    /// off on the axis at the throat within 0.5 ms of the ramp's end, at c0 80 and 160 times the mean speed, with
    /// and without particle shifting) and held at 0.05 (within 0.18 % to 21 ms; 2026-11-30, RESULTS.md); at Re 48
    /// 0.2 blew up and 0.1 holds (sph-stenosis). A faster jet than this pipe's also gets the walls' backstop
    /// (wall_repulsion 0.01): at a throat Re of 200 the fluid crossed the first wall layer at the throat without
    /// it at 0.05 and 0.1 mm, and with it ran to its end (2026-11-30, RESULTS.md).
    StenosisPipe atFlow(double meanSpeed, double length) const;
    /// The same pipe with its inflow pulsing as 1 + amplitude sin(2 pi t / period) (amplitude in [0, 1): the flow
    /// never reverses; 64 linear pieces a cycle), the averaging window the first whole cycle that starts after the
    /// steady window's start, the systole the tenth of the cycle about the inflow's peak (T / 4), and the sound speed,
    /// the Courant number and the walls' backstop those of atFlow at the peak's speed (the peak's Mach number that of
    /// the steady run). Throws vsim::Error for a period <= 0 or an amplitude outside [0, 1).
    StenosisPipe pulsatile(double periodS, double amplitude) const;
    /// The inflow's factor at time t: the ramp from rest times the waveform (OpenBoundaries::prescribedFlowRate).
    double inflowFactor(double timeS) const;
    /// The Womersley number R0 sqrt(2 pi / T rho / mu) of a pulsatile inflow (0 when steady).
    double womersleyNumber() const;
    /// The Reynolds number of the throat's mean flow: rho 4 U R0 / mu (its diameter R0, its mean speed 4 U).
    double throatReynolds() const;
    /// The throat's mean speed 4 U (m/s; area ratio 4), of the inflow's mean over a cycle.
    double throatMeanSpeedMS() const { return 4.0 * meanSpeedMS; }
    /// The lumen's radius at x (mm).
    double radiusAtMm(double xMm) const;
    /// The sections' positions along the axis (mm), two steps in from each end.
    std::vector<double> sectionArcsMm() const;
    double sectionThicknessMm() const { return 2.0 * spacingMm; }
    double flowRateM3S() const; ///< the mean speed times the unnarrowed lumen's area
    /// Points on the wall every `stepMm` from the first section to the last, `around` of them on each ring, with
    /// their normals into the lumen (m).
    std::vector<WallPoint> wallPoints(double stepMm, int around) const;
};

struct StenosisPipeFlow
{
    std::vector<double> arcMm;       ///< the sections' positions
    std::vector<SectionFlow> flows;  ///< their time averages over the settled flow
    StenosisFigures figures;
    std::map<std::string, double> metrics; ///< the run's (steps, particles, largest_density_variation, ...)
    /// The wall's rings every 0.05 mm: their positions (mm), time-averaged WSS (TAWSS) and pressure, each the mean
    /// over the ring's 8 points (WallShear.h).
    std::vector<double> wallArcMm, wallShearPa, wallPressurePa;
    double throatWallShearPa = 0.0; ///< the rings' TAWSS in the throat's section slab, averaged
    /// Pulsatile: the sections averaged over the systole of the averaged cycle (peak-systolic velocities) and their
    /// figures (the peak-systolic velocity ratio); empty when steady.
    std::vector<SectionFlow> systolicFlows;
    StenosisFigures systolicFigures;
};

/// The problem for another stepper (the GPU's, cuda/sph): the solver's parameters (the stenosis Courant number, 25
/// ms), the particles (the pipe's lattice, walls and the two ends' buffers), and the open ends, sections (sampled
/// every `sectionEvery` steps) and wall points (every `wallEvery` steps) set on `solver` before its initialize().
ParameterSet stenosisPipeParameters(const StenosisPipe& pipe);
ParticleSet stenosisPipeParticles(const StenosisPipe& pipe);
class SphSolver;
void configureStenosisPipe(const StenosisPipe& pipe, SphSolver& solver, int sectionEvery = 1, int wallEvery = 10);
/// The figures from the time averages of a run (its sections and wall loads) and the run's metrics.
StenosisPipeFlow stenosisPipeFlow(const StenosisPipe& pipe, const SectionSeries& sections,
                                  const WallLoadSeries& wallLoads, std::map<std::string, double> metrics);

/// Runs the SPH case on the CPU (the stenosis Courant number, 25 ms, averaged from 15 ms; at the default 0.1 mm
/// about 26,600 particles and 5,400 steps; the wall loads sampled every 10th step). Throws vsim::Error when the run
/// stops early (a guard) and vsim::Cancelled when cancelled.
StenosisPipeFlow runStenosisPipe(const StenosisPipe& pipe = {}, const Progress& progress = {});

} // namespace vsim::sim::sph
