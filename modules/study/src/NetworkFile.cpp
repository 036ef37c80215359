#include "vsim/study/NetworkFile.h"

#include "BundleFiles.h"
#include "vsim/core/Error.h"
#include "vsim/core/Units.h"

#include <nlohmann/json.hpp>

#include <fstream>

namespace vsim::study {
namespace {

using nlohmann::json;

json point(const Eigen::Vector3d& p) { return json::array({p.x(), p.y(), p.z()}); }

Eigen::Vector3d pointFrom(const json& value)
{
    if (!value.is_array() || value.size() != 3)
        throw Error("a position must be [x, y, z] in mm");
    return {value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>()};
}

} // namespace

std::string networkToJsonText(const VesselNetwork& network)
{
    json nodes = json::array(), segments = json::array(), outlets = json::array();
    for (const VesselNetwork::Node& node : network.nodes)
    {
        json entry{{"position_mm", point(node.positionMm)}};
        if (!node.name.empty())
            entry["name"] = node.name;
        nodes.push_back(entry);
    }
    for (const VesselNetwork::Segment& segment : network.segments)
    {
        json entry{{"from", segment.from},
                   {"to", segment.to},
                   {"start_radius_mm", segment.startRadiusMm},
                   {"end_radius_mm", segment.endRadiusMm},
                   {"length_mm", segment.lengthMm}};
        if (!segment.name.empty())
            entry["name"] = segment.name;
        if (segment.resistance > 0.0)
            entry["resistance_mmhg_min_per_ml"] = segment.resistance / kPaSPerM3PerMmHgMinPerMl;
        if (!segment.pathMm.empty())
        {
            json path = json::array();
            for (const Eigen::Vector3d& p : segment.pathMm)
                path.push_back(point(p));
            entry["path_mm"] = path;
        }
        segments.push_back(entry);
    }
    for (const VesselNetwork::Outlet& outlet : network.outlets)
    {
        json entry{{"node", outlet.node}, {"pressure_mmhg", units::paToMmHg(outlet.pressurePa)}};
        if (outlet.type == VesselNetwork::Outlet::Type::Resistance)
            entry["resistance_mmhg_min_per_ml"] = outlet.resistance / kPaSPerM3PerMmHgMinPerMl;
        outlets.push_back(entry);
    }
    json document{{"format", "vascusim-network"}, {"version", 1},       {"root", network.root},
                  {"nodes", nodes},                {"segments", segments}, {"outlets", outlets}};
    if (!network.segmentFields.empty())
        document["segment_fields"] = network.segmentFields;
    return document.dump(1);
}

VesselNetwork networkFromJsonText(const std::string& text)
{
    VesselNetwork network;
    try
    {
        const json document = json::parse(text);
        if (document.value("format", "") != "vascusim-network")
            throw Error("not a vascusim network file (\"format\": \"vascusim-network\" is missing)");
        if (document.value("version", 0) != 1)
            throw Error("unsupported network file version (this build reads version 1)");
        for (const json& node : document.at("nodes"))
            network.nodes.push_back({pointFrom(node.at("position_mm")), node.value("name", std::string())});
        std::size_t index = 0;
        for (const json& entry : document.at("segments"))
        {
            VesselNetwork::Segment segment;
            try
            {
                segment.from = entry.at("from").get<int>();
                segment.to = entry.at("to").get<int>();
                segment.startRadiusMm = entry.at("start_radius_mm").get<double>();
                segment.endRadiusMm = entry.at("end_radius_mm").get<double>();
                segment.lengthMm = entry.at("length_mm").get<double>();
                segment.resistance = entry.value("resistance_mmhg_min_per_ml", 0.0) * kPaSPerM3PerMmHgMinPerMl;
                segment.name = entry.value("name", std::string());
                if (entry.contains("path_mm"))
                    for (const json& p : entry.at("path_mm"))
                        segment.pathMm.push_back(pointFrom(p));
            }
            catch (const json::exception& exception)
            {
                throw Error(Pattern{"segment %1 of the network file: %2", {std::to_string(index), exception.what()}},
                            {{"segment", std::to_string(index)}});
            }
            network.segments.push_back(std::move(segment));
            ++index;
        }
        if (document.contains("outlets"))
            for (const json& entry : document.at("outlets"))
            {
                VesselNetwork::Outlet outlet;
                outlet.node = entry.at("node").get<int>();
                outlet.pressurePa = units::mmHgToPa(entry.value("pressure_mmhg", 0.0));
                outlet.type = entry.contains("resistance_mmhg_min_per_ml") ? VesselNetwork::Outlet::Type::Resistance
                                                                           : VesselNetwork::Outlet::Type::Pressure;
                outlet.resistance = entry.value("resistance_mmhg_min_per_ml", 0.0) * kPaSPerM3PerMmHgMinPerMl;
                network.outlets.push_back(outlet);
            }
        network.root = document.value("root", -1);
        if (document.contains("segment_fields"))
            network.segmentFields = document.at("segment_fields").get<std::map<std::string, std::vector<double>>>();
    }
    catch (const json::exception& exception)
    {
        throw Error(Pattern{"cannot read the network file: %1", {exception.what()}});
    }
    network.validate();
    return network;
}

VesselNetwork readNetworkFile(const std::filesystem::path& file)
{
    if (!std::filesystem::exists(file))
        throw Error("network file not found", {{"file", file.string()}});
    return networkFromJsonText(readTextFile(file));
}

void writeNetworkFile(const VesselNetwork& network, const std::filesystem::path& file)
{
    std::ofstream stream(file, std::ios::trunc);
    stream << networkToJsonText(network);
    if (!stream.flush())
        throw Error("cannot write the network file", {{"file", file.string()}});
}

} // namespace vsim::study
