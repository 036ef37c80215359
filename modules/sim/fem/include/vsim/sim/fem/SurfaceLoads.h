#pragma once

// Loads on the wall model (SI): a pressure acting on a set of boundary faces (a follower load: it acts along the
// current normals), and gravity on the lumped masses.

#include "vsim/sim/fem/BlockSparseMatrix.h"
#include "vsim/sim/fem/StaticSolver.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace vsim::sim::fem {

/// (The boundary faces of a mesh: vsim::boundaryFaces in vsim/core/TetMesh.h.)

/// Adds the nodal forces (N) of a uniform pressure `pressurePa` on `faces` at the current `positions` (m, 3 per
/// node) to `forces`: -p A n / 3 per corner, with n the face's outward unit normal (a positive pressure pushes
/// into the solid, as blood pressure on the lumen side of the wall does).
void addPressureForces(const std::vector<std::array<int, 3>>& faces, const Eigen::VectorXd& positions,
                       double pressurePa, Eigen::VectorXd& forces);

/// Subtracts the pressure forces' derivative d f / d x (the load stiffness of the follower pressure, not
/// symmetric face by face) from `tangent`, whose pattern holds every face's node pairs: block (a, b) of a face
/// gains (p / 6) [e_b]x with e_0 = x2 - x1, e_1 = x0 - x2, e_2 = x1 - x0 (f_a = -p (x1 - x0) x (x2 - x0) / 6).
void subtractPressureStiffness(const std::vector<std::array<int, 3>>& faces, const Eigen::VectorXd& positions,
                               double pressurePa, BlockSparseMatrix& tangent);

/// The same on 6-node (quadratic) faces (corners, then the midpoints of edges 01, 12, 20), integrated on the
/// current, curved face: f_a = -p int N_a (x_xi x x_eta) dxi deta (6-point rule of degree 4: exact for straight
/// edges, where the integrand is quadratic in (xi, eta) times N_a).
void addPressureForces(const std::vector<std::array<int, 6>>& faces, const Eigen::VectorXd& positions,
                       double pressurePa, Eigen::VectorXd& forces);
/// Its load stiffness: block (a, b) gains p int N_a (dN_b/deta [x_xi]x - dN_b/dxi [x_eta]x).
void subtractPressureStiffness(const std::vector<std::array<int, 6>>& faces, const Eigen::VectorXd& positions,
                               double pressurePa, BlockSparseMatrix& tangent);

/// A follower pressure on `faces` (3- or 6-node) as the static solver's load and its load stiffness (StaticSolver.h);
/// the faces are copied.
struct FollowerPressure
{
    ExternalForces forces;
    ExternalStiffness stiffness;
};
FollowerPressure followerPressure(const std::vector<std::array<int, 3>>& faces, double pressurePa);
FollowerPressure followerPressure(const std::vector<std::array<int, 6>>& faces, double pressurePa);
/// The same with face f under its own pressure `facePressuresPa[f]` (Pa; a pressure that varies over the lumen, as a
/// blood-flow run's wall pressure does). Throws vsim::Error when the counts differ.
FollowerPressure followerPressure(const std::vector<std::array<int, 6>>& faces,
                                  const std::vector<double>& facePressuresPa);

/// Adds m g to `forces` for lumped masses `mass` (kg per component) and gravity `gravity` (m/s^2).
void addGravityForces(const Eigen::VectorXd& mass, const Eigen::Vector3d& gravity, Eigen::VectorXd& forces);

} // namespace vsim::sim::fem
