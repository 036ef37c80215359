#pragma once

#include <Eigen/Core>

#include <vector>

namespace vsim {

/// Particles of a meshfree solver, structure of arrays so that CPU loops and GPU copies stay contiguous.
/// SI units (solvers convert from the patient frame in mm at their boundary).
struct ParticleSet
{
    std::vector<Eigen::Vector3d> positions;  ///< m
    std::vector<Eigen::Vector3d> velocities; ///< m/s
    std::vector<double> masses;              ///< kg
    std::vector<double> densities;           ///< kg/m^3

    std::size_t size() const { return positions.size(); }
    /// Resizes every array; new particles are at rest at the origin with zero mass and density.
    void resize(std::size_t count);
    /// Total mass in kg.
    double totalMass() const;
    /// Throws vsim::Error when the arrays differ in length or a value is not finite or a mass is negative.
    void validate() const;
};

} // namespace vsim
