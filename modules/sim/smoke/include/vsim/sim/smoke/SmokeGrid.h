#pragma once

// The smoke solver's staggered MAC grid (Harlow & Welch 1965; thesis ch. 7): cubic cells of edge h (m), velocity
// components on the faces (u on the x faces, v on y, w on z; m/s), smoke density (kg/m^3 of particulate) and
// temperature rise above the ambient (K) at the cell centres, and which cells are solid (anatomy, a moving body)
// with the velocity of the solid there. Each face of the domain is a wall (no flow through it) or open (the
// pressure is ambient there). SI throughout; the domain's corner sits at `origin` (m).

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace vsim::sim::smoke {

enum class DomainBoundary : std::uint8_t
{
    Wall, ///< no flow through it (free slip)
    Open  ///< ambient pressure outside: flow leaves and enters
};

/// The domain's faces in the order x-, x+, y-, y+, z-, z+.
using DomainBoundaries = std::array<DomainBoundary, 6>;

/// What a cell is: fluid; solid (anatomy, a moving body: no flow through its faces); or a vent, where the pressure
/// is ambient (an insufflation port, a trocar: flow and smoke leave and enter through it, like an open face).
inline constexpr std::uint8_t kFluid = 0, kSolid = 1, kVent = 2;

struct SmokeGrid
{
    int nx = 0, ny = 0, nz = 0;
    double h = 0.0;                          ///< cell edge (m)
    Eigen::Vector3d origin = Eigen::Vector3d::Zero(); ///< the domain's lowest corner (m)
    DomainBoundaries boundaries{};           ///< all walls by default
    std::vector<float> u, v, w;              ///< face velocities (m/s)
    std::vector<float> density;              ///< smoke density at the cell centres (kg/m^3)
    std::vector<float> temperature;          ///< rise above the ambient at the cell centres (K)
    std::vector<std::uint8_t> solid;         ///< kFluid, kSolid (inside a solid) or kVent
    std::vector<Eigen::Vector3f> solidVelocity; ///< the solid's velocity in solid cells (m/s)

    /// A grid of nx x ny x nz cells of edge h, at rest, no smoke, no solid. Throws vsim::Error below 2 cells
    /// along an axis.
    static SmokeGrid make(int nx, int ny, int nz, double h, const DomainBoundaries& boundaries = {});

    std::size_t cells() const { return std::size_t(nx) * ny * nz; }
    std::size_t cell(int i, int j, int k) const { return std::size_t(i) + std::size_t(nx) * (j + std::size_t(ny) * k); }
    std::size_t uFace(int i, int j, int k) const { return std::size_t(i) + std::size_t(nx + 1) * (j + std::size_t(ny) * k); }
    std::size_t vFace(int i, int j, int k) const { return std::size_t(i) + std::size_t(nx) * (j + std::size_t(ny + 1) * k); }
    std::size_t wFace(int i, int j, int k) const { return std::size_t(i) + std::size_t(nx) * (j + std::size_t(ny) * k); }
    bool inside(int i, int j, int k) const { return i >= 0 && j >= 0 && k >= 0 && i < nx && j < ny && k < nz; }
    bool isSolid(int i, int j, int k) const { return solid[cell(i, j, k)] == kSolid; }
    bool isFluid(std::size_t c) const { return solid[c] == kFluid; }
    /// The centre of cell (i, j, k) (m).
    Eigen::Vector3d centre(int i, int j, int k) const
    {
        return origin + h * Eigen::Vector3d(i + 0.5, j + 0.5, k + 0.5);
    }

    /// A cell-centred field sampled at x (m), trilinear, the nearest cells beyond the domain's edge.
    float sampleCells(const std::vector<float>& field, const Eigen::Vector3d& x) const;
    /// The velocity at x (m), each component trilinear from its faces.
    Eigen::Vector3d velocityAt(const Eigen::Vector3d& x) const;
    /// The velocity at a cell's centre (the mean of its opposite faces).
    Eigen::Vector3d cellVelocity(int i, int j, int k) const;
    /// The largest |u| of any face component (m/s).
    double maxSpeed() const;
    /// The total smoke mass (kg): density x cell volume over the cells that are not solid.
    double smokeMass() const;
};

} // namespace vsim::sim::smoke
