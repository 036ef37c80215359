#pragma once

#include <Eigen/Core>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace vsim {

/// A linear tetrahedral mesh in the patient frame (mm), e.g. a vessel wall. Element order follows VTK
/// (positive volume when (p1-p0) x (p2-p0) . (p3-p0) > 0).
struct TetMesh
{
    std::vector<Eigen::Vector3d> points;                 ///< mm, LPS
    std::vector<std::array<int, 4>> tets;
    std::map<std::string, std::vector<double>> pointFields;
    std::map<std::string, std::vector<double>> cellFields;

    /// Signed volume of element `tet` in mm^3.
    double elementVolume(std::size_t tet) const;
    /// Sum of element volumes in mm^3.
    double totalVolume() const;
    /// Throws vsim::Error for an index out of range, an inverted or degenerate element (volume <= 0),
    /// or a field of the wrong length; the message names the element.
    void validate() const;
};

/// The face opposite corner k of a tetrahedron, ordered so that its normal points out of a positive element.
inline constexpr int kTetFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

/// Faces that belong to one element only, ordered so that their normal (p1-p0) x (p2-p0) points out of the
/// solid (the elements must be positively oriented, as TetMesh::validate requires). `owners`, when given, receives
/// each face's element.
std::vector<std::array<int, 3>> boundaryFaces(const std::vector<std::array<int, 4>>& tets,
                                              std::vector<std::size_t>* owners = nullptr);

} // namespace vsim
