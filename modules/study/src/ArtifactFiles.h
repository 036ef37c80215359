#pragma once

#include "vsim/core/ImageVolume.h"
#include "vsim/core/SkeletonGraph.h"
#include "vsim/core/SolverRun.h"
#include "vsim/core/TetMesh.h"
#include "vsim/core/TriangleMesh.h"
#include "vsim/core/VesselNetwork.h"
#include "vsim/core/ViewMeasurement.h"
#include "vsim/study/Artifact.h"

#include <filesystem>
#include <variant>

namespace vsim::study {

/// The in-memory data of an artifact, one alternative per ArtifactKind.
using ArtifactData =
    std::variant<CtVolume, LabelVolume, TriangleMesh, TetMesh, SkeletonGraph, VesselNetwork, Document, SolverRun, ViewMeasurement>;

/// Returns the kind of the data held.
ArtifactKind kindOf(const ArtifactData& data);
/// File name extension of a kind, with the dot (".nrrd", ".vtp", ...), and its bundle folder ("images", ...).
std::string fileExtension(ArtifactKind kind);
std::string folderName(ArtifactKind kind);
/// The artifact's file relative to the bundle: <folder>/<id><extension>, or runs/<id>/run.json for a run.
std::filesystem::path artifactFilePath(ArtifactKind kind, const std::string& id);

/// Writes data to `file` in its kind's format (NRRD, VTK XML, JSON) and syncs it; throws vsim::Error on failure.
void writeArtifactFile(const ArtifactData& data, const std::filesystem::path& file);
/// Reads a file of the given kind; throws vsim::Error when it cannot be read or parsed.
ArtifactData readArtifactFile(ArtifactKind kind, const std::filesystem::path& file);

/// Reads only the header of an image or label file (NRRD); throws vsim::Error when it cannot be read.
VolumeGeometry readVolumeGeometry(const std::filesystem::path& file);

} // namespace vsim::study
