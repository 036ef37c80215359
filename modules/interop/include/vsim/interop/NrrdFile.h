#pragma once

// NRRD files (what 3D Slicer and ParaView open) for core volumes. ITK stays in the .cpp.

#include "vsim/core/ImageVolume.h"

#include <filesystem>

namespace vsim::interop {

/// Writes a volume (geometry in mm, LPS) to a NRRD file, optionally gzip-compressed.
/// Instantiated for int16 (CT), uint8 (labels) and float. Throws vsim::Error on failure.
template <typename T>
void writeNrrd(const ImageVolume<T>& volume, const std::filesystem::path& file, bool compress);

/// Reads a NRRD file of voxel type T; throws vsim::Error when it cannot be read.
template <typename T>
ImageVolume<T> readNrrd(const std::filesystem::path& file);

/// Reads the geometry from a NRRD header only (no voxels); throws vsim::Error for an unreadable or non-3D file.
VolumeGeometry readNrrdGeometry(const std::filesystem::path& file);

} // namespace vsim::interop
