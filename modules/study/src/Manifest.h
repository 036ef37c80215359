#pragma once

#include "vsim/study/Artifact.h"

#include <map>
#include <string>
#include <vector>

namespace vsim::study {

/// Everything study.json holds.
struct Manifest
{
    std::string name;
    std::map<std::string, std::string> metadata;
    std::vector<Artifact> artifacts;
    int nextArtifactNumber = 1; ///< ids are "<kind>-<number>", numbers never reused
};

/// Serialises a manifest (schema kSchemaVersion, with the writing software's version).
std::string manifestToText(const Manifest& manifest);
/// Parses study.json; migrates older schemas. Throws vsim::Error for malformed JSON, a missing field or a
/// schema newer than this build understands.
Manifest manifestFromText(const std::string& text);

} // namespace vsim::study
