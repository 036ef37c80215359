#include "vsim/core/SimulationData.h"

#include "vsim/core/Error.h"

#include <cmath>

namespace vsim {
namespace {

struct KindName
{
    std::string operator()(const TetMesh&) const { return detail::kindOf<TetMesh>(); }
    std::string operator()(const VesselNetwork&) const { return detail::kindOf<VesselNetwork>(); }
    std::string operator()(const GridFields&) const { return detail::kindOf<GridFields>(); }
    std::string operator()(const ParticleSet&) const { return detail::kindOf<ParticleSet>(); }
};

template <class Points>
std::optional<std::string> nonFinitePoint(const Points& points, const char* what)
{
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite())
            return std::string(what) + " " + std::to_string(i) + "'s position";
    return std::nullopt;
}

std::optional<std::string> nonFiniteField(const std::map<std::string, std::vector<double>>& fields, const char* kind,
                                          const char* element)
{
    for (const auto& [name, values] : fields)
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!std::isfinite(values[i]))
                return std::string(kind) + " " + name + " at " + element + " " + std::to_string(i);
    return std::nullopt;
}

struct NonFinite
{
    std::optional<std::string> operator()(const TetMesh& mesh) const
    {
        if (auto where = nonFinitePoint(mesh.points, "point"))
            return where;
        if (auto where = nonFiniteField(mesh.pointFields, "point field", "point"))
            return where;
        return nonFiniteField(mesh.cellFields, "cell field", "element");
    }
    std::optional<std::string> operator()(const VesselNetwork& network) const
    {
        for (std::size_t i = 0; i < network.nodes.size(); ++i)
            if (!network.nodes[i].positionMm.allFinite())
                return "node " + std::to_string(i) + "'s position";
        return nonFiniteField(network.segmentFields, "segment field", "segment");
    }
    std::optional<std::string> operator()(const GridFields& grid) const
    {
        const VolumeGeometry& g = grid.geometry;
        for (const auto& [name, volume] : grid.fields)
            for (std::size_t index = 0; index < volume.size(); ++index)
                if (!std::isfinite(volume.data()[index]))
                {
                    const std::size_t nx = std::size_t(g.dims[0]), ny = std::size_t(g.dims[1]);
                    return name + " at voxel (" + std::to_string(index % nx) + ", " + std::to_string(index / nx % ny) +
                           ", " + std::to_string(index / (nx * ny)) + ")";
                }
        return std::nullopt;
    }
    std::optional<std::string> operator()(const ParticleSet& particles) const
    {
        if (auto where = nonFinitePoint(particles.positionsMm, "particle"))
            return where;
        return nonFiniteField(particles.fields, "particle field", "particle");
    }
};

} // namespace


std::string dataKindName(const SimulationData& data)
{
    return std::visit(KindName{}, data);
}

std::optional<std::string> firstNonFinite(const SimulationData& data)
{
    return std::visit(NonFinite{}, data);
}

namespace detail {
void throwBadInput(const std::string& role, const SimulationInput& input, const std::string& wanted)
{
    const auto found = input.data.find(role);
    if (found == input.data.end())
        throw Error(Pattern{"the solver needs a %1 as its input '%2', and none was given", {wanted, role}});
    throw Error(Pattern{"the solver's input '%1' must be a %2, not a %3", {role, wanted, dataKindName(found->second)}});
}
} // namespace detail

} // namespace vsim
