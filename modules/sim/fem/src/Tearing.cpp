#include "vsim/sim/fem/Tearing.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace vsim::sim::fem {

std::vector<std::size_t> elementsOverStrength(const ElementStresses& stresses, double tearStressPa)
{
    std::vector<std::size_t> over;
    for (std::size_t e = 0; e < stresses.maxPrincipal.size(); ++e)
        if (stresses.maxPrincipal[e] > tearStressPa)
            over.push_back(e);
    std::sort(over.begin(), over.end(),
              [&](std::size_t a, std::size_t b) { return stresses.maxPrincipal[a] > stresses.maxPrincipal[b]; });
    return over;
}

DetachedModel detachElements(const CorotationalFem& model, const std::vector<std::size_t>& torn)
{
    const std::set<std::size_t> removed(torn.begin(), torn.end());
    std::vector<std::array<int, 4>> kept;
    std::vector<std::size_t> oldElementOf;
    for (std::size_t e = 0; e < model.elementCount(); ++e)
        if (!removed.count(e))
        {
            kept.push_back(model.tets()[e]);
            oldElementOf.push_back(e);
        }
    if (kept.empty())
        throw Error("tearing would remove every element of the wall");

    // Around each node, group the kept elements that are joined through a face containing the node.
    std::vector<std::vector<std::size_t>> around(model.nodeCount());
    for (std::size_t e = 0; e < kept.size(); ++e)
        for (int node : kept[e])
            around[std::size_t(node)].push_back(e);
    std::vector<std::array<int, 4>> renumbered = kept;
    std::vector<int> oldNodeOf;
    std::vector<int> firstCopy(model.nodeCount(), -1);
    std::size_t splitNodes = 0;
    for (std::size_t node = 0; node < model.nodeCount(); ++node)
    {
        const auto& elements = around[node];
        if (elements.empty())
            continue; // orphaned: dropped
        std::vector<int> group(elements.size(), -1);
        int groups = 0;
        for (std::size_t start = 0; start < elements.size(); ++start)
        {
            if (group[start] >= 0)
                continue;
            std::vector<std::size_t> stack{start};
            group[start] = groups;
            while (!stack.empty())
            {
                const std::size_t i = stack.back();
                stack.pop_back();
                for (std::size_t j = 0; j < elements.size(); ++j)
                {
                    if (group[j] >= 0)
                        continue;
                    // Two tets share a face through this node when they share two more nodes.
                    int shared = 0;
                    for (int a : kept[elements[i]])
                        for (int b : kept[elements[j]])
                            shared += a == b && std::size_t(a) != node;
                    if (shared >= 2)
                    {
                        group[j] = groups;
                        stack.push_back(j);
                    }
                }
            }
            ++groups;
        }
        for (int g = 0; g < groups; ++g)
        {
            const int newIndex = int(oldNodeOf.size());
            oldNodeOf.push_back(int(node));
            if (g > 0)
                ++splitNodes;
            for (std::size_t i = 0; i < elements.size(); ++i)
                if (group[i] == g)
                    for (std::size_t a = 0; a < 4; ++a)
                        if (kept[elements[i]][a] == int(node)) // compare with the old numbering
                            renumbered[elements[i]][a] = newIndex;
        }
    }
    std::vector<Eigen::Vector3d> rest(oldNodeOf.size());
    for (std::size_t n = 0; n < oldNodeOf.size(); ++n)
        rest[n] = model.restPositions()[std::size_t(oldNodeOf[n])];
    DetachedModel result{CorotationalFem(rest, renumbered, model.material()), oldNodeOf, oldElementOf, splitNodes};
    for (std::size_t n = 0; n < oldNodeOf.size(); ++n)
    {
        result.model.positions().segment<3>(Eigen::Index(3 * n)) = model.positions().segment<3>(3 * oldNodeOf[n]);
        result.model.velocities().segment<3>(Eigen::Index(3 * n)) = model.velocities().segment<3>(3 * oldNodeOf[n]);
    }
    result.model.updateElements(); // rotations of the current shape (from identity)
    return result;
}

void FractureEntropy::addTornElement(double releasedEnergyJ)
{
    m_energies.push_back(std::max(releasedEnergyJ, 0.0));
}

double FractureEntropy::value() const
{
    double total = 0.0;
    for (double e : m_energies)
        total += e;
    if (m_energies.size() < 2 || total <= 0.0)
        return 0.0;
    double entropy = 0.0;
    for (double e : m_energies)
        if (e > 0.0)
        {
            const double p = e / total;
            entropy -= p * std::log(p);
        }
    return entropy;
}

double FractureEntropy::effectiveCount() const { return std::exp(value()); }

} // namespace vsim::sim::fem
