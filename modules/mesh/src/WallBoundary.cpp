#include "vsim/mesh/WallBoundary.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace vsim::mesh {
namespace {

using Face = std::array<int, 3>;
using Edge = std::pair<int, int>;

Edge edgeOf(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

const std::vector<double>& pointArray(const TetMesh& mesh, const std::string& name, const char* option)
{
    const auto found = mesh.pointFields.find(name);
    if (found == mesh.pointFields.end())
    {
        std::string names;
        for (const auto& [key, values] : mesh.pointFields)
            names += (names.empty() ? "" : ", ") + key;
        throw Error(Pattern{"the mesh has no point-data array '%1' for %2 (its arrays: %3)",
                            {name, option, (names.empty() ? "none" : names)}},
                    {{"array", name}});
    }
    return found->second;
}

/// The boundary faces with their outward unit normals, centroids and edge neighbours.
struct Boundary
{
    std::vector<Face> faces;
    std::vector<Eigen::Vector3d> normals, centroids;
    std::map<Edge, std::vector<std::size_t>> facesOfEdge;

    explicit Boundary(const TetMesh& mesh) : faces(boundaryFaces(mesh.tets))
    {
        for (std::size_t f = 0; f < faces.size(); ++f)
        {
            const Eigen::Vector3d& a = mesh.points[std::size_t(faces[f][0])];
            const Eigen::Vector3d& b = mesh.points[std::size_t(faces[f][1])];
            const Eigen::Vector3d& c = mesh.points[std::size_t(faces[f][2])];
            normals.push_back((b - a).cross(c - a).normalized());
            centroids.push_back((a + b + c) / 3.0);
            for (int k = 0; k < 3; ++k)
                facesOfEdge[edgeOf(faces[f][std::size_t(k)], faces[f][std::size_t((k + 1) % 3)])].push_back(f);
        }
    }

    /// The faces reached from `seed` across edges where the normals turn by less than `angleDeg`.
    std::vector<bool> smoothPatch(std::size_t seed, double angleDeg) const
    {
        const double cosine = std::cos(angleDeg * M_PI / 180.0);
        std::vector<bool> in(faces.size(), false);
        std::vector<std::size_t> stack{seed};
        in[seed] = true;
        while (!stack.empty())
        {
            const std::size_t f = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k)
                for (std::size_t g : facesOfEdge.at(edgeOf(faces[f][std::size_t(k)], faces[f][std::size_t((k + 1) % 3)])))
                    if (!in[g] && normals[f].dot(normals[g]) >= cosine)
                        in[g] = true, stack.push_back(g);
        }
        return in;
    }
};

/// The pressure faces: from the array, or the smooth patch of the nearest face that faces the lumen point.
std::vector<bool> pressureFaces(const TetMesh& mesh, const Boundary& boundary, const WallBoundarySelection& selection)
{
    std::vector<bool> loaded(boundary.faces.size(), false);
    if (!selection.pressureArray.empty())
    {
        const std::vector<double>& marked = pointArray(mesh, selection.pressureArray, "--pressure-array");
        for (std::size_t f = 0; f < boundary.faces.size(); ++f)
            loaded[f] = std::all_of(boundary.faces[f].begin(), boundary.faces[f].end(),
                                    [&](int node) { return marked[std::size_t(node)] != 0.0; });
        return loaded;
    }
    const Eigen::Vector3d& point = *selection.lumenPointMm;
    std::size_t nearest = boundary.faces.size();
    double best = 1e300;
    for (std::size_t f = 0; f < boundary.faces.size(); ++f)
    {
        const Eigen::Vector3d toPoint = point - boundary.centroids[f];
        // An inner-surface face's outward normal (out of the solid) points into the lumen, towards the point.
        if (toPoint.dot(boundary.normals[f]) > 0.0 && toPoint.norm() < best)
            best = toPoint.norm(), nearest = f;
    }
    if (nearest == boundary.faces.size())
        throw Error("no boundary face of the mesh faces the lumen point; give a point inside the vessel's lumen");
    return boundary.smoothPatch(nearest, selection.featureAngleDeg);
}

} // namespace

MarkedWall markWallBoundary(TetMesh mesh, const WallBoundarySelection& selection)
{
    if (selection.pressureArray.empty() && !selection.lumenPointMm)
        throw Error("say where the blood pressure acts: --pressure-array NAME (point data, nonzero on the lumen "
                    "surface) or --lumen-point x,y,z (a point inside the lumen, mm)");
    if (selection.fixedArray.empty() && !selection.fixOpenEnds)
        throw Error("say which nodes are held: --fixed-array NAME (point data, nonzero on held nodes) or "
                    "--fix-open-ends (the end cuts at the lumen surface's open ends)");
    mesh.validate();
    const Boundary boundary(mesh);
    MarkedWall marked;
    marked.boundaryFaces = boundary.faces.size();
    const std::vector<bool> loaded = pressureFaces(mesh, boundary, selection);
    marked.pressureFaces = std::size_t(std::count(loaded.begin(), loaded.end(), true));
    if (marked.pressureFaces == 0)
        throw Error("no boundary face is selected for the pressure: the wall would carry no load");
    if (marked.pressureFaces == marked.boundaryFaces)
        throw Error("the pressure would act on the whole boundary (inner, outer and end faces): the lumen surface "
                    "is not parted from the rest by sharp edges; give --pressure-array");

    std::vector<double> layer(mesh.points.size(), 1.0), ends(mesh.points.size(), 0.0);
    for (std::size_t f = 0; f < boundary.faces.size(); ++f)
        if (loaded[f])
            for (int node : boundary.faces[f])
                layer[std::size_t(node)] = 0.0;

    // The pressure surface's open loops: its edges that only one of its faces uses.
    std::vector<Edge> loopEdges;
    for (const auto& [edge, faces] : boundary.facesOfEdge)
        if (std::count_if(faces.begin(), faces.end(), [&](std::size_t f) { return loaded[f]; }) == 1)
            loopEdges.push_back(edge);
    {
        std::map<int, int> parent; // union-find over the loop edges' nodes: one set per loop
        auto find = [&](int node) {
            while (parent.at(node) != node)
                node = parent[node] = parent.at(parent.at(node));
            return node;
        };
        for (const Edge& edge : loopEdges)
            parent.emplace(edge.first, edge.first), parent.emplace(edge.second, edge.second);
        for (const Edge& edge : loopEdges)
            parent[find(edge.first)] = find(edge.second);
        for (const auto& [node, up] : parent)
            marked.openLoops += find(node) == node;
    }

    if (!selection.fixedArray.empty())
    {
        const std::vector<double>& held = pointArray(mesh, selection.fixedArray, "--fixed-array");
        for (std::size_t i = 0; i < ends.size(); ++i)
            ends[i] = held[i] != 0.0 ? 1.0 : 0.0;
    }
    else
    {
        if (loopEdges.empty())
            throw Error("the pressure surface is closed (no open ends): give the held nodes with --fixed-array");
        std::vector<bool> endFaces(boundary.faces.size(), false);
        for (const Edge& edge : loopEdges)
            for (std::size_t f : boundary.facesOfEdge.at(edge))
                if (!loaded[f] && !endFaces[f])
                {
                    const std::vector<bool> cut = boundary.smoothPatch(f, selection.featureAngleDeg);
                    for (std::size_t g = 0; g < cut.size(); ++g)
                        endFaces[g] = endFaces[g] || (cut[g] && !loaded[g]);
                }
        for (std::size_t f = 0; f < boundary.faces.size(); ++f)
            if (endFaces[f])
                for (int node : boundary.faces[f])
                    ends[std::size_t(node)] = 1.0;
    }
    marked.fixedNodes = std::size_t(std::count(ends.begin(), ends.end(), 1.0));
    if (marked.fixedNodes == 0)
        throw Error("no node is held: the wall would float free");

    // WallSimulation loads every boundary face whose three nodes are on the lumen side: say so if that differs.
    std::size_t implied = 0;
    for (const Face& face : boundary.faces)
        implied += std::all_of(face.begin(), face.end(), [&](int node) { return layer[std::size_t(node)] == 0.0; });
    if (implied != marked.pressureFaces)
        marked.warnings.push_back(storedText(Pattern{
            "%1 boundary faces outside the selection have all their nodes on the lumen surface and carry the pressure "
            "too (a wall one element thick there)",
            {std::to_string(implied - marked.pressureFaces)}}));
    mesh.pointFields["wall_layer"] = layer;
    mesh.pointFields["end_set"] = ends;
    marked.wall = std::move(mesh);
    return marked;
}

} // namespace vsim::mesh
