#pragma once

// A CalculiX 2.20 job for the wall benchmarks (bench_fem_calculix): the input deck (mm, N, MPa) of a tetrahedral
// wall (C3D4 or C3D10, the same node order as ours) with fixed nodes and a pressure on element faces, one static
// step (linear, or NLGEOM with a follower pressure), the materials *ELASTIC (linear; St. Venant-Kirchhoff under
// NLGEOM) or *HYPERELASTIC, REDUCED POLYNOMIAL, N=2 (W = C10 (I1b - 3) + C20 (I1b - 3)^2 + (J - 1)^2 / D1); and
// reading its job.dat: nodal displacements and each element's stress tensor averaged over its integration points.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace vsim::bench {

struct CalculixJob
{
    enum class Material { Elastic, ReducedPolynomial };
    std::vector<Eigen::Vector3d> nodesMm;
    std::vector<std::vector<int>> elements; ///< 4 or 10 nodes each (0-based)
    std::vector<std::uint8_t> fixedNodes;   ///< per node, 1: all three components held
    /// (element, CalculiX face number 1..4: S1 = corners 1-2-3, S2 = 1-4-2, S3 = 2-4-3, S4 = 3-4-1)
    std::vector<std::pair<std::size_t, int>> pressureFaces;
    double pressurePa = 0.0;
    bool nlgeom = false;
    Material material = Material::Elastic;
    double youngMpa = 0.0, poisson = 0.0;              ///< *ELASTIC
    double c10Mpa = 0.0, c20Mpa = 0.0, d1PerMpa = 0.0; ///< *HYPERELASTIC
};

/// The CalculiX face number (1..4) of the element with corners `corners` whose face has corners `face`; 0: none.
int calculixFace(const std::array<int, 4>& corners, const std::array<int, 3>& face);

void writeCalculixInput(const CalculixJob& job, const std::filesystem::path& file);

struct CalculixResults
{
    Eigen::VectorXd displacementMm;   ///< 3 per node
    std::vector<double> vonMisesMpa;  ///< per element: von Mises of the mean stress tensor over its points
};
/// Reads job.dat (the last increment's blocks). Throws vsim::Error when a node or element is missing.
CalculixResults readCalculixResults(const std::filesystem::path& file, std::size_t nodes, std::size_t elements);

} // namespace vsim::bench
