#include "vsim/sim/sph/ParticleState.h"

namespace vsim::sim::sph {

void ParticleState::add(const Eigen::Vector3d& positionM, double densityKgM3, double massKg, bool isWall,
                        double wallDepthM, double voidFractionOfMixture)
{
    id.push_back(int(position.size()));
    position.push_back(positionM);
    velocity.push_back(Eigen::Vector3d::Zero());
    density.push_back(densityKgM3);
    mass.push_back(massKg);
    voidFraction.push_back(voidFractionOfMixture);
    wall.push_back(isWall ? 1 : 0);
    wallDepth.push_back(isWall ? wallDepthM : -1.0);
}

void ParticleState::reorder(const NeighbourGrid& grid)
{
    grid.reorder(position);
    grid.reorder(velocity);
    grid.reorder(density);
    grid.reorder(mass);
    grid.reorder(voidFraction);
    grid.reorder(wall);
    grid.reorder(wallDepth);
    grid.reorder(id);
}

} // namespace vsim::sim::sph
