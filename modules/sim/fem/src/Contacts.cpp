#include "vsim/sim/fem/Contacts.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <string>

namespace vsim::sim::fem {

std::vector<ContactStiffness> addContactForces(const Contacts& contacts, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                               Eigen::VectorXd& forces)
{
    std::vector<ContactStiffness> stiffness;
    const int nodes = int(x.size() / 3);
    for (const SpringConstraint& spring : contacts.springs)
    {
        if (spring.node < 0 || spring.node >= nodes)
            throw Error(Pattern{"a spring constraint names node %1 of %2",
                                {std::to_string(spring.node), std::to_string(nodes)}});
        forces.segment<3>(3 * spring.node) -= spring.stiffness * (x.segment<3>(3 * spring.node) - spring.anchor);
        stiffness.push_back({spring.node, spring.stiffness * Eigen::Matrix3d::Identity()});
    }
    for (const RigidProbe& probe : contacts.probes)
        for (int node = 0; node < nodes; ++node)
        {
            const Eigen::Vector3d offset = x.segment<3>(3 * node) - probe.centre;
            const double distance = offset.norm();
            if (distance >= probe.radius || distance == 0.0)
                continue;
            const Eigen::Vector3d normal = offset / distance;
            const Eigen::Vector3d push = probe.stiffness * (probe.radius - distance) * normal;
            Eigen::Vector3d sliding = v.segment<3>(3 * node) - probe.velocity;
            sliding -= sliding.dot(normal) * normal;
            const double speed = sliding.norm();
            // Coulomb: |friction| = mu |normal force| against the sliding, scaled down linearly below slipSpeed.
            Eigen::Vector3d friction = Eigen::Vector3d::Zero();
            if (speed > 0.0)
                friction = -probe.friction * push.norm() * std::min(1.0, speed / probe.slipSpeed) * (sliding / speed);
            forces.segment<3>(3 * node) += push + friction;
            stiffness.push_back({node, probe.stiffness * normal * normal.transpose()});
        }
    return stiffness;
}

} // namespace vsim::sim::fem
