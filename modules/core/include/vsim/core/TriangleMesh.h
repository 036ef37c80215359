#pragma once

#include <Eigen/Core>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace vsim {

/// A triangle surface in the patient frame (mm), e.g. a vessel lumen. Per-point scalar fields carry
/// results (stress, pressure) by name.
struct TriangleMesh
{
    std::vector<Eigen::Vector3d> points;                 ///< mm, LPS
    std::vector<std::array<int, 3>> triangles;           ///< indices into points, counter-clockwise seen from outside
    std::map<std::string, std::vector<double>> pointFields;

    /// Total area in mm^2.
    double area() const;
    /// Unit normals at the points, each the area-weighted mean of its triangles' normals (outward for an outward
    /// surface); zero at a point of no triangle.
    std::vector<Eigen::Vector3d> vertexNormals() const;
    /// Signed enclosed volume in mm^3 (positive for a closed, outward-oriented surface).
    double signedVolume() const;
    /// Throws vsim::Error for an index out of range, a degenerate index triple or a field of the wrong length.
    void validate() const;
};

} // namespace vsim
