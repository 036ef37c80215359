#pragma once

// Contacts of the wall model (thesis ch. 4.5): spring constraints that pull nodes towards anchors (the GUI's drag,
// instrument contact points; the thesis handles 128 at once on its GPU) and a rigid spherical probe that pushes
// nodes out of its volume (penalty) with Coulomb friction on their sliding (regularised below a small speed). Both
// are stiff, so their stiffness enters the implicit system as well as their forces. SI units.

#include <Eigen/Core>

#include <vector>

namespace vsim::sim::fem {

struct SpringConstraint
{
    int node = 0;
    Eigen::Vector3d anchor = Eigen::Vector3d::Zero(); ///< m
    double stiffness = 0.0;                           ///< N/m
};

struct RigidProbe
{
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();   ///< m
    Eigen::Vector3d velocity = Eigen::Vector3d::Zero(); ///< m/s, for the sliding speed
    double radius = 0.0;                                ///< m
    double stiffness = 0.0;                             ///< N/m per node in contact
    double friction = 0.0;                              ///< Coulomb coefficient
    double slipSpeed = 1e-3;                            ///< m/s below which friction is proportional to speed
};

struct Contacts
{
    std::vector<SpringConstraint> springs;
    std::vector<RigidProbe> probes;
};

/// One node's contact stiffness block (N/m) for the implicit system.
struct ContactStiffness
{
    int node;
    Eigen::Matrix3d block;
};

/// Adds the contact forces (N) at positions `x` and velocities `v` (3 per node) to `forces`, and returns the
/// stiffness blocks (springs: k I; probe: k n n^T on nodes in contact). Throws vsim::Error for a node out of range.
std::vector<ContactStiffness> addContactForces(const Contacts& contacts, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                               Eigen::VectorXd& forces);

} // namespace vsim::sim::fem
