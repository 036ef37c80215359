#include "Manifest.h"

#include "vsim/core/Error.h"
#include "vsim/core/Version.h"
#include "vsim/study/Study.h"

#include <nlohmann/json.hpp>

namespace vsim::study {
namespace {

using nlohmann::json;

json provenanceToJson(const Provenance& provenance)
{
    return {{"command", provenance.command},       {"parameters", provenance.parameters},
            {"inputs", provenance.inputs},         {"time", provenance.time},
            {"software_version", provenance.softwareVersion}};
}

Provenance provenanceFromJson(const json& value)
{
    Provenance provenance;
    provenance.command = value.at("command").get<std::string>();
    provenance.parameters = value.at("parameters").get<std::map<std::string, std::string>>();
    provenance.inputs = value.at("inputs").get<std::vector<std::string>>();
    provenance.time = value.at("time").get<std::string>();
    provenance.softwareVersion = value.at("software_version").get<std::string>();
    return provenance;
}

} // namespace

std::string manifestToText(const Manifest& manifest)
{
    json artifacts = json::array();
    for (const Artifact& artifact : manifest.artifacts)
        artifacts.push_back({{"id", artifact.id},
                             {"kind", kindName(artifact.kind)},
                             {"name", artifact.name},
                             {"file", artifact.file},
                             {"crc32", artifact.checksum},
                             {"bytes", artifact.bytes},
                             {"provenance", provenanceToJson(artifact.provenance)},
                             {"warnings", artifact.warnings},
                             {"attributes", artifact.attributes}});
    const json document = {{"format", "vascusim-study"},
                           {"schema_version", kSchemaVersion},
                           {"software_version", kVersion},
                           {"name", manifest.name},
                           {"metadata", manifest.metadata},
                           {"next_artifact_number", manifest.nextArtifactNumber},
                           {"artifacts", artifacts}};
    return document.dump(2) + "\n";
}

Manifest manifestFromText(const std::string& text)
{
    try
    {
        const json document = json::parse(text);
        if (document.value("format", "") != "vascusim-study")
            throw Error("study.json is not a VascuSim study manifest");
        const int schema = document.at("schema_version").get<int>();
        if (schema > kSchemaVersion)
            throw Error(Pattern{"the study was written by a newer VascuSim (schema %1); this build reads schema %2 "
                                "and older",
                                {std::to_string(schema), std::to_string(kSchemaVersion)}},
                        {{"software_version", document.value("software_version", "unknown")}});
        // Schema 2 only adds the run kind: a schema 1 manifest reads as it is. Migrations go here as they appear.
        Manifest manifest;
        manifest.name = document.at("name").get<std::string>();
        manifest.metadata = document.at("metadata").get<std::map<std::string, std::string>>();
        manifest.nextArtifactNumber = document.at("next_artifact_number").get<int>();
        for (const json& entry : document.at("artifacts"))
        {
            Artifact artifact;
            artifact.id = entry.at("id").get<std::string>();
            artifact.kind = kindFromName(entry.at("kind").get<std::string>());
            artifact.name = entry.at("name").get<std::string>();
            artifact.file = entry.at("file").get<std::string>();
            artifact.checksum = entry.at("crc32").get<std::uint32_t>();
            artifact.bytes = entry.at("bytes").get<std::uint64_t>();
            artifact.provenance = provenanceFromJson(entry.at("provenance"));
            artifact.warnings = entry.at("warnings").get<std::vector<std::string>>();
            // Optional since VascuSim 0.2 (additive, schema 1 unchanged).
            artifact.attributes =
                entry.value("attributes", std::map<std::string, std::string>{});
            manifest.artifacts.push_back(std::move(artifact));
        }
        return manifest;
    }
    catch (const nlohmann::json::exception& exception)
    {
        throw Error("study.json is malformed", {{"reason", exception.what()}});
    }
}

} // namespace vsim::study
