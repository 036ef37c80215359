#pragma once

// Particles as a run's frame shows them (SimulationData.h): positions in mm in the patient frame (LPS) and
// per-particle fields, each with one value per particle and its unit in its name ("speed_m_s", "pressure_pa"; a
// vector as one field per component, "velocity_x_m_s"). A particle solver keeps its own state in SI and writes this.

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace vsim {

struct ParticleSet
{
    std::vector<Eigen::Vector3d> positionsMm;
    std::map<std::string, std::vector<double>> fields;

    std::size_t size() const { return positionsMm.size(); }
    /// Throws vsim::Error naming a field whose length is not the particle count.
    void validate() const;
};

} // namespace vsim
