#pragma once

// How much of a laparoscope's view the smoke hides (issue 21): each pixel's ray from the camera is marched through
// the smoke density until it meets a solid (the tissue it looks at) or leaves the domain, and its light is
// attenuated by Beer-Lambert, T = exp(-K_m integral rho ds), with K_m the smoke's mass extinction coefficient
// (8.7 m^2/g for flaming combustion smoke at 633 nm: Mulholland & Croarkin 2000, Fire and Materials 24:227; a
// tissue-smoke value is not published). A pixel is obscured when its transmittance falls below the visibility
// threshold (0.5 by default: half the light from the scene lost). The camera is the workstation's endoscope
// camera (a pinhole looking along `direction`), in the grid's frame, SI.

#include "vsim/sim/smoke/SmokeGrid.h"

#include <Eigen/Core>

#include <vector>

namespace vsim::sim::smoke {

struct SmokeCamera
{
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m
    Eigen::Vector3d direction = Eigen::Vector3d::UnitX(); ///< where it looks (unit)
    Eigen::Vector3d up = Eigen::Vector3d::UnitZ();        ///< the picture's up (unit, across `direction`)
    double fieldOfViewDeg = 70.0;                         ///< across the picture's width (a laparoscope: 70-80)
    int width = 64, height = 48;                          ///< rays
};

/// The mass extinction coefficient of smoke (m^2/kg): 8.7 m^2/g (Mulholland & Croarkin 2000).
inline constexpr double kSmokeMassExtinction = 8700.0;

struct ObscurationView
{
    int width = 0, height = 0;
    std::vector<float> transmittance; ///< per pixel, row by row (0 opaque .. 1 clear)
    double obscuredFraction = 0.0;    ///< share of the pixels below the visibility threshold
    double meanTransmittance = 0.0;
};

/// The view through the smoke. Throws vsim::Error for a camera outside the domain or inside a solid.
ObscurationView obscuration(const SmokeGrid& grid, const SmokeCamera& camera,
                            double massExtinctionM2PerKg = kSmokeMassExtinction, double visibleTransmittance = 0.5);

/// When a curve of (time, obscured fraction) first reaches `level` (linear between samples), or a negative
/// value when it never does.
double firstTimeReaching(const std::vector<std::pair<double, double>>& curve, double level, double fromS = 0.0);

} // namespace vsim::sim::smoke
