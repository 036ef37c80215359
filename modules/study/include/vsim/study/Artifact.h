#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace vsim::study {

/// What an artifact holds; decides its folder and file format in the bundle.
enum class ArtifactKind
{
    Image,    ///< CT in HU: images/<id>.nrrd
    Label,    ///< segmentation: labels/<id>.nrrd
    Surface,  ///< triangle surface: surfaces/<id>.vtp
    TetMesh,  ///< tetrahedral mesh: meshes/<id>.vtu
    Skeleton, ///< vessel graph: skeletons/<id>.json
    Network,  ///< vessel network (drug delivery), possibly with results: networks/<id>.json
    Report,   ///< a clinical report as written: reports/<id>.pdf
    Run,      ///< a simulation run: runs/<id>/run.json, its frames and series.pvd (schema 2)
    Measurement, ///< a ruler, angle or ROI drawn on a view: measurements/<id>.json
};

/// Every kind, in the order of ArtifactKind (and of the in-memory data's alternatives).
inline constexpr ArtifactKind kArtifactKinds[] = {ArtifactKind::Image,    ArtifactKind::Label,   ArtifactKind::Surface,
                                                  ArtifactKind::TetMesh,  ArtifactKind::Skeleton, ArtifactKind::Network,
                                                  ArtifactKind::Report,   ArtifactKind::Run,      ArtifactKind::Measurement};

/// A document kept as written (a report's PDF bytes).
struct Document
{
    std::string bytes;
};

/// Returns the manifest name of a kind ("image", "label", ...).
std::string kindName(ArtifactKind kind);
/// Returns the kind for a manifest name; throws vsim::Error for an unknown name.
ArtifactKind kindFromName(const std::string& name);

/// How an artifact was made: enough to make it again.
struct Provenance
{
    std::string command;                            ///< e.g. "import volume", "segment"
    std::map<std::string, std::string> parameters;  ///< values with units, e.g. {"sigma_mm", "1.5"}
    std::vector<std::string> inputs;                ///< artifact ids, or source file names for imports
    std::string time;                               ///< ISO 8601 UTC, filled in when the artifact is added
    std::string softwareVersion;                    ///< VascuSim version, filled in when the artifact is added
};

/// One entry of the study manifest.
struct Artifact
{
    std::string id;            ///< unique in the study, e.g. "image-1"
    ArtifactKind kind = ArtifactKind::Image;
    std::string name;          ///< for people, e.g. "CTA arterial phase"
    std::string file;          ///< relative to the bundle root; empty until first saved
    std::uint32_t checksum = 0; ///< CRC-32 of the file
    std::uint64_t bytes = 0;
    Provenance provenance;
    std::vector<std::string> warnings; ///< what the step that made it reported (clamped values, resampling, ...)
    /// Attributes of the source, e.g. a DICOM series' description, UIDs and dates ("series_description", ...).
    std::map<std::string, std::string> attributes;
    bool damaged = false;      ///< set on open when the file is missing or its checksum differs
    std::string damage;        ///< why it is flagged
};

} // namespace vsim::study
