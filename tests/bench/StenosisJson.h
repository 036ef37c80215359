#pragma once

// The SPH half of the stenosis cross-check as JSON (tests/bench/bench_sph_openfoam's --sph-out / --sph-in, written
// by bench_sph_cuda_stenosis on the GPU too): the sections' time averages, one array per quantity (SI) with their
// positions along the axis (mm).

#include "vsim/sim/sph/CrossSections.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <utility>
#include <vector>

namespace vsim::bench {

inline nlohmann::json sectionsJson(const std::vector<double>& arcMm, const std::vector<sim::sph::SectionFlow>& flows)
{
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [key, pick] : std::initializer_list<std::pair<const char*, double sim::sph::SectionFlow::*>>{
             {"area_m2", &sim::sph::SectionFlow::areaM2},
             {"flow_rate_m3s", &sim::sph::SectionFlow::flowRateM3S},
             {"mean_velocity_ms", &sim::sph::SectionFlow::meanVelocityMS},
             {"peak_velocity_ms", &sim::sph::SectionFlow::peakVelocityMS},
             {"mean_pressure_pa", &sim::sph::SectionFlow::meanPressurePa}})
    {
        nlohmann::json values = nlohmann::json::array();
        for (const auto& flow : flows)
            values.push_back(flow.*pick);
        out[key] = values;
    }
    out["arc_mm"] = arcMm;
    return out;
}

inline std::vector<sim::sph::SectionFlow> sectionsFrom(const nlohmann::json& in)
{
    std::vector<sim::sph::SectionFlow> flows(in.at("arc_mm").size());
    for (std::size_t k = 0; k < flows.size(); ++k)
    {
        flows[k].areaM2 = in.at("area_m2").at(k), flows[k].flowRateM3S = in.at("flow_rate_m3s").at(k);
        flows[k].meanVelocityMS = in.at("mean_velocity_ms").at(k);
        flows[k].peakVelocityMS = in.at("peak_velocity_ms").at(k);
        flows[k].meanPressurePa = in.at("mean_pressure_pa").at(k), flows[k].particles = 1;
    }
    return flows;
}

} // namespace vsim::bench
