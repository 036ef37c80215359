#pragma once

// What a solver reads and what its frames hold, in one type the run driver (sim/common), the Run artifact's writer
// (study) and the time player share: a tetrahedral mesh with point and cell fields (the wall), a vessel network with
// segment fields (the drug network), named real fields on one voxel grid (the template solver; the smoke grid to come)
// or particles with per-particle fields (SPH blood flow). Geometry in mm
// in the patient frame, as the study keeps it; each field names its unit in its key ("temperature_rise_k").

#include "vsim/core/ImageVolume.h"
#include "vsim/core/ParticleSet.h"
#include "vsim/core/TetMesh.h"
#include "vsim/core/VesselNetwork.h"

#include <map>
#include <optional>
#include <string>
#include <variant>

namespace vsim {

/// Real fields on one voxel grid (every field's geometry is `geometry`).
struct GridFields
{
    VolumeGeometry geometry;
    std::map<std::string, RealVolume> fields;
};

using SimulationData = std::variant<TetMesh, VesselNetwork, GridFields, ParticleSet>;

/// "tet mesh", "vessel network", "voxel grid", "particle set": for messages.
std::string dataKindName(const SimulationData& data);

/// The first value that is not finite, for the driver's guard: e.g. "temperature_rise_k at voxel (3, 4, 5)" or
/// "point field displacement_mm at point 12"; nothing when every value (coordinates included) is finite.
std::optional<std::string> firstNonFinite(const SimulationData& data);

/// A solver's inputs by role ("wall", "network"), with the artifact each came from for the provenance.
struct SimulationInput
{
    std::map<std::string, SimulationData> data;
    std::map<std::string, std::string> sources; ///< role -> artifact id (or file name)

    /// The input of `role` as T; throws vsim::Error naming the role when it is missing or of another kind.
    template <class T>
    const T& get(const std::string& role) const;
};

namespace detail {
[[noreturn]] void throwBadInput(const std::string& role, const SimulationInput& input, const std::string& wanted);
template <class T> constexpr const char* kindOf();
template <> constexpr const char* kindOf<TetMesh>() { return "tet mesh"; }
template <> constexpr const char* kindOf<VesselNetwork>() { return "vessel network"; }
template <> constexpr const char* kindOf<GridFields>() { return "voxel grid"; }
template <> constexpr const char* kindOf<ParticleSet>() { return "particle set"; }
} // namespace detail

template <class T>
const T& SimulationInput::get(const std::string& role) const
{
    const auto found = data.find(role);
    if (found == data.end() || !std::holds_alternative<T>(found->second))
        detail::throwBadInput(role, *this, detail::kindOf<T>());
    return std::get<T>(found->second);
}

} // namespace vsim
