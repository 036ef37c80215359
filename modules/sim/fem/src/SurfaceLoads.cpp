#include "vsim/sim/fem/SurfaceLoads.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/fem/QuadraticTet.h"

#include <Eigen/Geometry>

namespace vsim::sim::fem {

void addPressureForces(const std::vector<std::array<int, 3>>& faces, const Eigen::VectorXd& positions,
                       double pressurePa, Eigen::VectorXd& forces)
{
    for (const auto& face : faces)
    {
        const Eigen::Vector3d p0 = positions.segment<3>(3 * face[0]);
        // (p1 - p0) x (p2 - p0) = 2 A n
        const Eigen::Vector3d areaNormal =
            0.5 * (positions.segment<3>(3 * face[1]) - p0).cross(positions.segment<3>(3 * face[2]) - p0);
        const Eigen::Vector3d share = -pressurePa * areaNormal / 3.0;
        for (int node : face)
            forces.segment<3>(3 * node) += share;
    }
}

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
    Eigen::Matrix3d m;
    m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
    return m;
}

/// The face's 6 node positions as columns.
Eigen::Matrix<double, 3, 6> facePositions(const std::array<int, 6>& face, const Eigen::VectorXd& positions)
{
    Eigen::Matrix<double, 3, 6> x;
    for (int a = 0; a < 6; ++a)
        x.col(a) = positions.segment<3>(3 * face[std::size_t(a)]);
    return x;
}

} // namespace

void subtractPressureStiffness(const std::vector<std::array<int, 3>>& faces, const Eigen::VectorXd& positions,
                               double pressurePa, BlockSparseMatrix& tangent)
{
    for (const auto& face : faces)
    {
        const Eigen::Vector3d x0 = positions.segment<3>(3 * face[0]), x1 = positions.segment<3>(3 * face[1]),
                              x2 = positions.segment<3>(3 * face[2]);
        const std::array<Eigen::Matrix3d, 3> block{skew(x2 - x1), skew(x0 - x2), skew(x1 - x0)};
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                tangent.block(tangent.slotOf(std::size_t(face[std::size_t(a)]), std::size_t(face[std::size_t(b)]))) +=
                    (pressurePa / 6.0) * block[std::size_t(b)];
    }
}

namespace {

/// The 6-node faces' forces and load stiffness with face f under `pressureOf(f)` (Pa).
template <class PressureOf>
void addQuadraticPressureForces(const std::vector<std::array<int, 6>>& faces, const Eigen::VectorXd& positions,
                                const PressureOf& pressureOf, Eigen::VectorXd& forces)
{
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
        const std::array<int, 6>& face = faces[f];
        const double pressurePa = pressureOf(f);
        const Eigen::Matrix<double, 3, 6> x = facePositions(face, positions);
        for (const Eigen::Vector3d& q : triangleQuadraturePoints())
        {
            const QuadraticTriangleShape shape = quadraticTriangleShape(q.x(), q.y());
            const Eigen::Vector3d areaNormal = (x * shape.dXi).cross(x * shape.dEta);
            for (int a = 0; a < 6; ++a)
                forces.segment<3>(3 * face[std::size_t(a)]) -= pressurePa * q.z() * shape.n[a] * areaNormal;
        }
    }
}

template <class PressureOf>
void subtractQuadraticPressureStiffness(const std::vector<std::array<int, 6>>& faces,
                                        const Eigen::VectorXd& positions, const PressureOf& pressureOf,
                                        BlockSparseMatrix& tangent)
{
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
        const std::array<int, 6>& face = faces[f];
        const double pressurePa = pressureOf(f);
        const Eigen::Matrix<double, 3, 6> x = facePositions(face, positions);
        std::array<Eigen::Matrix3d, 36> blocks;
        blocks.fill(Eigen::Matrix3d::Zero());
        for (const Eigen::Vector3d& q : triangleQuadraturePoints())
        {
            const QuadraticTriangleShape shape = quadraticTriangleShape(q.x(), q.y());
            const Eigen::Matrix3d xXi = skew(x * shape.dXi), xEta = skew(x * shape.dEta);
            for (int a = 0; a < 6; ++a)
                for (int b = 0; b < 6; ++b)
                    blocks[std::size_t(6 * a + b)] +=
                        (pressurePa * q.z() * shape.n[a]) * (shape.dEta[b] * xXi - shape.dXi[b] * xEta);
        }
        for (int a = 0; a < 6; ++a)
            for (int b = 0; b < 6; ++b)
                tangent.block(tangent.slotOf(std::size_t(face[std::size_t(a)]), std::size_t(face[std::size_t(b)]))) +=
                    blocks[std::size_t(6 * a + b)];
    }
}

} // namespace

void addPressureForces(const std::vector<std::array<int, 6>>& faces, const Eigen::VectorXd& positions,
                       double pressurePa, Eigen::VectorXd& forces)
{
    addQuadraticPressureForces(faces, positions, [pressurePa](std::size_t) { return pressurePa; }, forces);
}

void subtractPressureStiffness(const std::vector<std::array<int, 6>>& faces, const Eigen::VectorXd& positions,
                               double pressurePa, BlockSparseMatrix& tangent)
{
    subtractQuadraticPressureStiffness(faces, positions, [pressurePa](std::size_t) { return pressurePa; }, tangent);
}

namespace {

template <std::size_t N>
FollowerPressure followerPressureOn(const std::vector<std::array<int, N>>& faces, double pressurePa)
{
    FollowerPressure load;
    load.forces = [faces, pressurePa](const Eigen::VectorXd& x) {
        Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
        addPressureForces(faces, x, pressurePa, f);
        return f;
    };
    load.stiffness = [faces, pressurePa](const Eigen::VectorXd& x, BlockSparseMatrix& tangent) {
        subtractPressureStiffness(faces, x, pressurePa, tangent);
    };
    return load;
}

} // namespace

FollowerPressure followerPressure(const std::vector<std::array<int, 3>>& faces, double pressurePa)
{
    return followerPressureOn(faces, pressurePa);
}

FollowerPressure followerPressure(const std::vector<std::array<int, 6>>& faces, double pressurePa)
{
    return followerPressureOn(faces, pressurePa);
}

FollowerPressure followerPressure(const std::vector<std::array<int, 6>>& faces,
                                  const std::vector<double>& facePressuresPa)
{
    if (facePressuresPa.size() != faces.size())
        throw Error(Pattern{"%1 face pressures for %2 pressure faces",
                            {std::to_string(facePressuresPa.size()), std::to_string(faces.size())}});
    const auto pressureOf = [facePressuresPa](std::size_t f) { return facePressuresPa[f]; };
    FollowerPressure load;
    load.forces = [faces, pressureOf](const Eigen::VectorXd& x) {
        Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
        addQuadraticPressureForces(faces, x, pressureOf, f);
        return f;
    };
    load.stiffness = [faces, pressureOf](const Eigen::VectorXd& x, BlockSparseMatrix& tangent) {
        subtractQuadraticPressureStiffness(faces, x, pressureOf, tangent);
    };
    return load;
}

void addGravityForces(const Eigen::VectorXd& mass, const Eigen::Vector3d& gravity, Eigen::VectorXd& forces)
{
    for (Eigen::Index i = 0; i < mass.size(); i += 3)
        forces.segment<3>(i) += mass.segment<3>(i).cwiseProduct(gravity);
}

} // namespace vsim::sim::fem
