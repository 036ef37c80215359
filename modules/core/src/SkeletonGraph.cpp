#include "vsim/core/SkeletonGraph.h"

#include "vsim/core/Error.h"

#include <string>

namespace vsim {

double SkeletonGraph::Edge::length() const
{
    double total = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i)
        total += (points[i] - points[i - 1]).norm();
    return total;
}

int SkeletonGraph::degree(int node) const
{
    int count = 0;
    for (const Edge& edge : edges)
        count += (edge.from == node) + (edge.to == node);
    return count;
}

std::vector<int> SkeletonGraph::endpoints() const
{
    std::vector<int> result;
    for (int node = 0; node < static_cast<int>(nodes.size()); ++node)
        if (degree(node) == 1)
            result.push_back(node);
    return result;
}

std::vector<int> SkeletonGraph::junctions() const
{
    std::vector<int> result;
    for (int node = 0; node < static_cast<int>(nodes.size()); ++node)
        if (degree(node) >= 3)
            result.push_back(node);
    return result;
}

void SkeletonGraph::validate() const
{
    const int nodeCount = static_cast<int>(nodes.size());
    for (std::size_t e = 0; e < edges.size(); ++e)
    {
        const Edge& edge = edges[e];
        const Error::Context where{{"edge", std::to_string(e)}};
        if (edge.from < 0 || edge.from >= nodeCount || edge.to < 0 || edge.to >= nodeCount)
            throw Error("skeleton edge refers to a missing node", where);
        if (edge.points.size() < 2)
            throw Error("skeleton edge has fewer than two points", where);
        if (edge.voxels.size() != edge.points.size() || edge.radii.size() != edge.points.size())
            throw Error("skeleton edge has point, voxel and radius lists of different lengths", where);
        for (double radius : edge.radii)
            if (!(radius > 0.0))
                throw Error("skeleton edge has a radius that is not positive", where);
    }
}

} // namespace vsim
