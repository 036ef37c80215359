#include "vsim/sim/sph/ParticleState.h"

#include <type_traits>

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
    guardDepth.push_back(wallDepth.back());
    boundary.push_back(0);
    tracer.push_back(0);
    backstop.push_back(isWall ? 1 : 0);
}

void ParticleState::appendCopy(std::size_t i, const Eigen::Vector3d& positionM, int newId)
{
    forEachArray([i](auto& values) { values.push_back(typename std::decay_t<decltype(values)>::value_type(values[i])); });
    position.back() = positionM;
    id.back() = newId;
}

void ParticleState::keepOnly(const std::vector<std::uint8_t>& keep)
{
    forEachArray(
        [&keep](auto& values)
        {
            std::size_t kept = 0;
            for (std::size_t i = 0; i < values.size(); ++i)
                if (keep[i])
                    values[kept++] = values[i];
            values.resize(kept);
        });
}

void ParticleState::reorder(const NeighbourGrid& grid)
{
    forEachArray([&grid](auto& values) { grid.reorder(values); });
}

} // namespace vsim::sim::sph
