#include "WallFlips.h"

#include "vsim/mesh/WallMesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>

namespace vsim::mesh::detail {
namespace {

constexpr int kFlipSweeps = 4;
using Tet = std::array<int, 4>;

double volume6(const TetMesh& mesh, const Tet& t)
{
    const auto& p = mesh.points;
    const Eigen::Vector3d a = p[std::size_t(t[0])];
    return (p[std::size_t(t[1])] - a).cross(p[std::size_t(t[2])] - a).dot(p[std::size_t(t[3])] - a);
}

double angleOf(const TetMesh& mesh, const Tet& t)
{
    const auto& p = mesh.points;
    return minDihedralAngle(p[std::size_t(t[0])], p[std::size_t(t[1])], p[std::size_t(t[2])], p[std::size_t(t[3])]);
}

Eigen::Vector3d centroid(const TetMesh& mesh, const Tet& t)
{
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int v : t)
        c += mesh.points[std::size_t(v)];
    return 0.25 * c;
}

std::uint64_t edgeKey(int a, int b)
{
    return (std::uint64_t(std::uint32_t(std::min(a, b))) << 32) | std::uint32_t(std::max(a, b));
}

/// The ring of edge (a, b) from its four elements: the four other nodes in cyclic order (each element holds two
/// consecutive ones); empty when they do not close a cycle (an edge on the boundary).
std::vector<int> ringOf(const TetMesh& mesh, const std::vector<std::size_t>& elements, int a, int b)
{
    std::vector<std::array<int, 2>> pairs;
    for (std::size_t t : elements)
    {
        std::array<int, 2> pair{-1, -1};
        int found = 0;
        for (int v : mesh.tets[t])
            if (v != a && v != b && found < 2)
                pair[std::size_t(found++)] = v;
        if (found != 2)
            return {};
        pairs.push_back(pair);
    }
    std::vector<int> ring{pairs[0][0], pairs[0][1]};
    std::vector<bool> used(pairs.size(), false);
    used[0] = true;
    while (ring.size() < pairs.size())
    {
        bool extended = false;
        for (std::size_t n = 0; n < pairs.size() && !extended; ++n)
            if (!used[n] && (pairs[n][0] == ring.back() || pairs[n][1] == ring.back()))
            {
                const int next = pairs[n][0] == ring.back() ? pairs[n][1] : pairs[n][0];
                if (std::find(ring.begin(), ring.end(), next) != ring.end())
                    return {};
                ring.push_back(next), used[n] = true, extended = true;
            }
        if (!extended)
            return {};
    }
    for (std::size_t n = 0; n < pairs.size(); ++n) // the last pair closes the cycle
        if (!used[n] && !((pairs[n][0] == ring.back() && pairs[n][1] == ring.front()) ||
                          (pairs[n][1] == ring.back() && pairs[n][0] == ring.front())))
            return {};
    return ring;
}

/// Orients an element positively (its last two nodes swapped if needed); false when it is flat.
bool oriented(const TetMesh& mesh, Tet& t)
{
    if (volume6(mesh, t) < 0.0)
        std::swap(t[2], t[3]);
    return volume6(mesh, t) > 0.0;
}

} // namespace

std::size_t flipEdgesOfFour(TetMesh& mesh, const std::vector<double>& material, double targetDeg)
{
    std::size_t flips = 0;
    std::vector<double> angle(mesh.tets.size());
    for (std::size_t t = 0; t < mesh.tets.size(); ++t)
        angle[t] = angleOf(mesh, mesh.tets[t]);
    for (int sweep = 0; sweep < kFlipSweeps; ++sweep)
    {
        std::unordered_map<std::uint64_t, std::vector<std::size_t>> around;
        for (std::size_t t = 0; t < mesh.tets.size(); ++t)
            for (int i = 0; i < 4; ++i)
                for (int j = i + 1; j < 4; ++j)
                    around[edgeKey(mesh.tets[t][std::size_t(i)], mesh.tets[t][std::size_t(j)])].push_back(t);
        std::vector<std::size_t> poor;
        for (std::size_t t = 0; t < mesh.tets.size(); ++t)
            if (angle[t] < targetDeg)
                poor.push_back(t);
        std::sort(poor.begin(), poor.end(), [&](std::size_t x, std::size_t y) { return angle[x] < angle[y]; });
        std::vector<bool> touched(mesh.tets.size(), false); // changed this sweep: the edge map is stale around it
        const std::size_t before = flips;
        for (std::size_t t : poor)
            for (int i = 0; i < 4 && !touched[t]; ++i)
                for (int j = i + 1; j < 4 && !touched[t]; ++j)
                {
                    const int a = mesh.tets[t][std::size_t(i)], b = mesh.tets[t][std::size_t(j)];
                    const std::vector<std::size_t>& elements = around[edgeKey(a, b)];
                    if (elements.size() != 4 ||
                        std::any_of(elements.begin(), elements.end(), [&](std::size_t e) {
                            return touched[e] || (!material.empty() && material[e] != material[elements[0]]);
                        }))
                        continue;
                    const std::vector<int> ring = ringOf(mesh, elements, a, b);
                    if (ring.size() != 4)
                        continue;
                    double old = 180.0;
                    for (std::size_t e : elements)
                        old = std::min(old, angle[e]);
                    // Edge (a, b) gives way to a diagonal of its ring, (ring[0], ring[2]) or (ring[1], ring[3]): the
                    // better of the two.
                    std::array<Tet, 4> fresh;
                    double worst = -1.0;
                    for (int start : {0, 1})
                    {
                        const int r0 = ring[std::size_t(start)], r1 = ring[std::size_t(start + 1)],
                                  r2 = ring[std::size_t(start + 2)], r3 = ring[std::size_t((start + 3) % 4)];
                        std::array<Tet, 4> candidate{Tet{r0, r1, r2, a}, Tet{r0, r1, r2, b}, Tet{r0, r2, r3, a},
                                                     Tet{r0, r2, r3, b}};
                        double smallest = 180.0;
                        for (Tet& f : candidate)
                            smallest = oriented(mesh, f) ? std::min(smallest, angleOf(mesh, f)) : -1.0;
                        if (smallest > worst)
                            worst = smallest, fresh = candidate;
                    }
                    if (!(worst > old + 1e-9))
                        continue;
                    // Each new element into the free slot whose old centroid is nearest.
                    std::vector<std::size_t> slots(elements.begin(), elements.end());
                    std::vector<Eigen::Vector3d> oldCentre;
                    for (std::size_t e : slots)
                        oldCentre.push_back(centroid(mesh, mesh.tets[e]));
                    std::vector<bool> taken(4, false);
                    for (const Tet& f : fresh)
                    {
                        const Eigen::Vector3d c = centroid(mesh, f);
                        std::size_t best = 4;
                        for (std::size_t s = 0; s < 4; ++s)
                            if (!taken[s] && (best == 4 || (oldCentre[s] - c).squaredNorm() < (oldCentre[best] - c).squaredNorm()))
                                best = s;
                        taken[best] = true;
                        mesh.tets[slots[best]] = f;
                        angle[slots[best]] = angleOf(mesh, f);
                        touched[slots[best]] = true;
                    }
                    ++flips;
                }
        if (flips == before)
            break;
    }
    return flips;
}

} // namespace vsim::mesh::detail
