#pragma once

// The injected drug as a homogeneous two-phase (bubbly) fluid, thesis ch. 6.2: density and viscosity are the
// void-fraction averages of the liquid and gas phases (eq. 6.2, 6.3). Phase properties default to the thesis's
// (ch. 5): plasma 1,060 kg/m^3 and 3.56 mPa s, gas 1.205 kg/m^3 and 18.6 uPa s at 37 C. SI units.

namespace vsim::sim::network {

struct PhaseProperties
{
    double liquidDensity = 1060.0;     ///< kg/m^3
    double gasDensity = 1.205;         ///< kg/m^3
    double liquidViscosity = 3.56e-3;  ///< Pa s
    double gasViscosity = 18.6e-6;     ///< Pa s
};

struct TwoPhaseMixture
{
    double voidFraction = 0.0; ///< gas volume fraction, [0, 1)
    PhaseProperties phases;

    /// rho_h = rho_l (1 - v) + rho_g v (eq. 6.2), kg/m^3.
    double density() const;
    /// mu = v mu_g + (1 - v) mu_l (eq. 6.3), Pa s.
    double viscosity() const;
    /// The liquid (drug) share of a volume flow, 1 - v.
    double liquidFraction() const { return 1.0 - voidFraction; }
    /// Throws vsim::Error for a void fraction outside [0, 1) or a phase property that is not positive.
    void validate() const;
};

/// The void fraction above which the flow is no longer bubbly (the transition to cap-bubbly / slug flow of Taitel,
/// Bornea and Dukler 1980, about 0.25): the homogeneous model, and the thesis's experiment, cover bubbly flow only.
inline constexpr double kBubblyVoidFractionLimit = 0.25;

} // namespace vsim::sim::network
