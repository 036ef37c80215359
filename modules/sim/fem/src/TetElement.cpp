#include "vsim/sim/fem/TetElement.h"

#include "vsim/core/Error.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace vsim::sim::fem {

StrainMatrix strainDisplacement(const Eigen::Matrix<double, 4, 3>& g)
{
    StrainMatrix b = StrainMatrix::Zero();
    for (int a = 0; a < 4; ++a)
    {
        const int c = 3 * a;
        b(0, c) = g(a, 0);
        b(1, c + 1) = g(a, 1);
        b(2, c + 2) = g(a, 2);
        b(3, c) = g(a, 1), b(3, c + 1) = g(a, 0);
        b(4, c + 1) = g(a, 2), b(4, c + 2) = g(a, 1);
        b(5, c) = g(a, 2), b(5, c + 2) = g(a, 0);
    }
    return b;
}

TetRest restTetrahedron(const std::array<Eigen::Vector3d, 4>& rest, const ElasticMaterial& material)
{
    Eigen::Matrix3d edges;
    edges << rest[1] - rest[0], rest[2] - rest[0], rest[3] - rest[0];
    const double volume = edges.determinant() / 6.0;
    double longest = 0.0;
    for (int a = 0; a < 4; ++a)
        for (int b = a + 1; b < 4; ++b)
            longest = std::max(longest, (rest[std::size_t(a)] - rest[std::size_t(b)]).norm());
    if (!(volume > 1e-6 * longest * longest * longest))
    {
        if (volume < 0.0)
            throw Error("an element is inverted at rest (negative volume)");
        throw Error("an element is degenerate at rest (flat or zero volume)");
    }
    TetRest element;
    element.volume = volume;
    element.restEdgesInverse = edges.inverse();
    // Rows of the inverse are the gradients of N1..N3; N0 = 1 - N1 - N2 - N3.
    for (int a = 1; a < 4; ++a)
        element.gradients.row(a) = element.restEdgesInverse.row(a - 1);
    element.gradients.row(0) = -element.gradients.bottomRows<3>().colwise().sum();
    const StrainMatrix b = strainDisplacement(element.gradients);
    element.stiffness = volume * b.transpose() * material.elasticityMatrix() * b;
    return element;
}

} // namespace vsim::sim::fem
