// The quadratic (10-node) hyperelastic wall model of the converged analysis: the laws' tangents against central
// differences of their stress, the model's tangent (material, geometric and the follower pressure's load stiffness on
// 6-node faces) against central differences of the residual force on a box stretched, sheared, turned and jittered,
// a homogeneous deformation leaves no force on interior nodes (patch test), a pressure on a closed surface adds up to
// no force and on a flat face to p A, the small-strain shear modulus of the AAA laws, and bad input is refused.

#include "vsim/core/Error.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/Hyperelastic.h"
#include "vsim/sim/fem/QuadraticFem.h"
#include "vsim/sim/fem/StructuredMeshes.h"
#include "vsim/sim/fem/SurfaceLoads.h"

#include <Eigen/Geometry>
#include <QtTest>

#include <random>

using namespace vsim;
using namespace vsim::sim::fem;

namespace {

/// A deformation gradient near a rotation times a stretch, from `seed`.
Eigen::Matrix3d randomDeformation(std::mt19937& random, double amplitude)
{
    std::uniform_real_distribution<double> jitter(-1.0, 1.0);
    Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            f(i, j) += amplitude * jitter(random);
    return Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix() * f;
}

std::vector<std::array<int, 3>> facesWhere(const StructuredTetMesh& mesh, const std::function<bool(const Eigen::Vector3d&)>& on)
{
    std::vector<std::array<int, 3>> out;
    for (const auto& face : boundaryFaces(mesh.tets))
        if (on(mesh.points[std::size_t(face[0])]) && on(mesh.points[std::size_t(face[1])]) && on(mesh.points[std::size_t(face[2])]))
            out.push_back(face);
    return out;
}

} // namespace

class FemQuadratic : public QObject
{
    Q_OBJECT

private slots:
    void lawTangentsMatchFiniteDifferences()
    {
        const std::vector<std::pair<const char*, HyperelasticMaterial>> laws = {
            {"St. Venant-Kirchhoff", HyperelasticMaterial::stVenantKirchhoff(2e6, 0.45)},
            {"Raghavan-Vorp 2000", HyperelasticMaterial::raghavanVorp2000()},
            {"Wang 2001 thrombus", HyperelasticMaterial::wang2001Thrombus()}};
        for (const auto& [name, law] : laws)
            for (unsigned seed : {1u, 2u, 3u})
            {
                std::mt19937 random(seed);
                const Eigen::Matrix3d f = randomDeformation(random, 0.15);
                const Eigen::Matrix3d c = f.transpose() * f;
                Matrix6d tangent;
                law.stress(c, &tangent);
                // dS/dE column q by central differences of S in the Green strain E = (C - I) / 2 (engineering shear:
                // a unit shear strain moves C_ij and C_ji by 1 each).
                Matrix6d expected;
                const double h = 1e-6;
                for (int q = 0; q < 6; ++q)
                {
                    Vector6d e = Vector6d::Zero();
                    e[q] = 1.0;
                    // dC = 2 dE; fromVoigt puts the engineering shear strain gamma = 2 dE_ij off the diagonal.
                    const Eigen::Matrix3d dc = (q >= 3 ? 1.0 : 2.0) * fromVoigt(e);
                    expected.col(q) = (law.stress(c + h * dc) - law.stress(c - h * dc)) / (2.0 * h);
                }
                const double error = (tangent - expected).norm() / expected.norm();
                const double symmetry = (tangent - tangent.transpose()).norm() / tangent.norm();
                qInfo("%s, seed %u: |dS/dE - FD| / |FD| = %.2e, asymmetry %.1e", name, seed, error, symmetry);
                QVERIFY(error < 1e-6);
                QVERIFY(symmetry < 1e-12);
                // S = dW/dE as well (the stress is the energy's derivative).
                Vector6d fromEnergy;
                for (int q = 0; q < 6; ++q)
                {
                    Vector6d e = Vector6d::Zero();
                    e[q] = 1.0;
                    const Eigen::Matrix3d dc = (q >= 3 ? 1.0 : 2.0) * fromVoigt(e);
                    fromEnergy[q] = (law.energyDensity(c + h * dc) - law.energyDensity(c - h * dc)) / (2.0 * h);
                }
                QVERIFY((fromEnergy - law.stress(c)).norm() < 1e-6 * law.stress(c).norm());
            }
    }

    void aaaLawsHaveTheirPublishedShearModulus()
    {
        // Raghavan & Vorp 2000: W = alpha (I1 - 3) + beta (I1 - 3)^2, mu0 = 2 alpha = 348 kPa; Wang 2001 thrombus
        // mu0 = 2 c1 = 52.4 kPa; both nearly incompressible (nu 0.49 -> kappa / mu0 = 49.67).
        const HyperelasticMaterial wall = HyperelasticMaterial::raghavanVorp2000(), thrombus = HyperelasticMaterial::wang2001Thrombus();
        QCOMPARE(wall.initialShearModulus(), 348e3);
        QCOMPARE(thrombus.initialShearModulus(), 52.4e3);
        QVERIFY(std::abs(wall.bulkModulus / wall.initialShearModulus() - 2.0 * 1.49 / (3.0 * 0.02)) < 1e-9);
        // Small simple shear gamma: sigma_xy = mu0 gamma.
        const double gamma = 1e-6;
        Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
        f(0, 1) = gamma;
        for (const HyperelasticMaterial& law : {wall, thrombus})
            QVERIFY(std::abs(fromVoigt(law.stress(f.transpose() * f))(0, 1) / gamma - law.initialShearModulus()) <
                    1e-4 * law.initialShearModulus());
    }

    void modelTangentMatchesFiniteDifferences()
    {
        const StructuredTetMesh linear = boxTetMesh(Eigen::Vector3d(0.01, 0.015, 0.02), {2, 2, 3});
        const QuadraticTetMesh mesh = quadraticFromLinear(linear.points, linear.tets);
        const std::vector<std::array<int, 6>> loaded =
            quadraticFaces(mesh, facesWhere(linear, [](const Eigen::Vector3d& p) { return p.x() < 1e-9; }));
        const double pressure = 5e4; // Pa
        std::vector<std::uint8_t> materialOf(mesh.elements.size(), 0);
        for (std::size_t e = 0; e < materialOf.size(); e += 2)
            materialOf[e] = 1; // wall and thrombus mixed
        for (unsigned seed : {1u, 2u, 3u})
        {
            QuadraticFem model(mesh, {HyperelasticMaterial::raghavanVorp2000(), HyperelasticMaterial::wang2001Thrombus()},
                               materialOf);
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> jitter(-1.0, 1.0);
            const Eigen::Matrix3d f = randomDeformation(random, 0.1);
            for (std::size_t n = 0; n < mesh.points.size(); ++n)
                model.positions().segment<3>(Eigen::Index(3 * n)) =
                    f * mesh.points[n] + 2e-4 * Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
            std::size_t inverted = 0;
            const auto residual = [&](const Eigen::VectorXd& x) {
                model.positions() = x;
                inverted += model.updateElements();
                Eigen::VectorXd r = model.elasticForces();
                addPressureForces(loaded, x, pressure, r);
                return r;
            };
            const Eigen::VectorXd x0 = model.positions();
            Eigen::VectorXd v(x0.size());
            for (Eigen::Index i = 0; i < v.size(); ++i)
                v[i] = jitter(random);
            const double h = 1e-8 / v.cwiseAbs().maxCoeff();
            const Eigen::VectorXd expected = -(residual(x0 + h * v) - residual(x0 - h * v)) / (2.0 * h);
            residual(x0);
            QCOMPARE(inverted, std::size_t(0));
            BlockSparseMatrix tangent = model.makeMatrix();
            model.assembleTangent(tangent, true);
            subtractPressureStiffness(loaded, x0, pressure, tangent);
            Eigen::VectorXd product;
            tangent.multiply(v, product);
            const double error = (product - expected).norm() / expected.norm();
            qInfo("seed %u: |T v - FD| / |FD| = %.2e", seed, error);
            QVERIFY(error < 1e-6);
            // The energy's derivative is the force: dE/dx . v = -f . v.
            const auto energy = [&](const Eigen::VectorXd& x) { model.positions() = x; return model.elasticEnergy(); };
            const double slope = (energy(x0 + h * v) - energy(x0 - h * v)) / (2.0 * h);
            model.positions() = x0;
            model.updateElements();
            QVERIFY(std::abs(slope + model.elasticForces().dot(v)) < 1e-6 * std::abs(slope));
        }
    }

    void homogeneousDeformationLeavesInteriorNodesFree()
    {
        const StructuredTetMesh linear = boxTetMesh(Eigen::Vector3d(0.02, 0.02, 0.02), {3, 3, 3});
        QuadraticFem model(quadraticFromLinear(linear.points, linear.tets), {HyperelasticMaterial::raghavanVorp2000()});
        Eigen::Matrix3d f;
        f << 1.08, 0.03, -0.02, 0.01, 0.95, 0.04, -0.03, 0.02, 1.02;
        for (std::size_t n = 0; n < model.nodeCount(); ++n)
            model.positions().segment<3>(Eigen::Index(3 * n)) = f * model.mesh().points[n];
        QCOMPARE(model.updateElements(), std::size_t(0));
        const Eigen::VectorXd forces = model.elasticForces();
        double interior = 0.0, boundary = 0.0;
        for (std::size_t n = 0; n < model.nodeCount(); ++n)
        {
            const Eigen::Vector3d& p = model.mesh().points[n];
            const bool inside = (p.array() > 1e-9).all() && (p.array() < 0.02 - 1e-9).all();
            (inside ? interior : boundary) = std::max(inside ? interior : boundary, forces.segment<3>(Eigen::Index(3 * n)).norm());
        }
        qInfo("largest force on an interior node %.2e N, on a boundary node %.2e N", interior, boundary);
        QVERIFY(boundary > 0.0);
        QVERIFY(interior < 1e-9 * boundary);
        // Every element carries the one Cauchy stress F S F^T / J.
        const Eigen::Matrix3d s = fromVoigt(HyperelasticMaterial::raghavanVorp2000().stress(f.transpose() * f));
        const Eigen::Matrix3d sigma = f * s * f.transpose() / f.determinant();
        for (const Eigen::Matrix3d& t : model.elementStresses().tensors)
            QVERIFY((t - sigma).norm() < 1e-9 * sigma.norm());
    }

    void pressureOnQuadraticFacesAddsUp()
    {
        const StructuredTetMesh linear = boxTetMesh(Eigen::Vector3d(0.01, 0.02, 0.03), {2, 3, 2});
        const QuadraticTetMesh mesh = quadraticFromLinear(linear.points, linear.tets);
        Eigen::VectorXd x(Eigen::Index(3 * mesh.points.size()));
        std::mt19937 random(7);
        std::uniform_real_distribution<double> jitter(-1.0, 1.0);
        for (std::size_t n = 0; n < mesh.points.size(); ++n)
            x.segment<3>(Eigen::Index(3 * n)) = mesh.points[n] + 5e-4 * Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
        Eigen::VectorXd closed = Eigen::VectorXd::Zero(x.size());
        addPressureForces(quadraticFaces(mesh, boundaryFaces(linear.tets)), x, 1e4, closed);
        Eigen::Vector3d total = Eigen::Vector3d::Zero();
        for (Eigen::Index i = 0; i < closed.size(); i += 3)
            total += closed.segment<3>(i);
        QVERIFY(total.norm() < 1e-12 * closed.norm()); // a closed (curved) surface: no net force
        // The flat face x = 0 at rest: the forces add up to p A along +x (pushing into the solid), the corners
        // carry none (the consistent load of the 6-node triangle).
        Eigen::VectorXd flat = Eigen::VectorXd::Zero(x.size());
        Eigen::VectorXd rest(x.size());
        for (std::size_t n = 0; n < mesh.points.size(); ++n)
            rest.segment<3>(Eigen::Index(3 * n)) = mesh.points[n];
        addPressureForces(quadraticFaces(mesh, facesWhere(linear, [](const Eigen::Vector3d& p) { return p.x() < 1e-9; })),
                          rest, 1e4, flat);
        double sum = 0.0, onCorners = 0.0;
        for (std::size_t n = 0; n < mesh.points.size(); ++n)
        {
            sum += flat[Eigen::Index(3 * n)];
            if (n < mesh.cornerCount)
                onCorners += std::abs(flat[Eigen::Index(3 * n)]);
        }
        QVERIFY(std::abs(sum - 1e4 * 0.02 * 0.03) < 1e-12);
        QVERIFY(onCorners < 1e-12);
    }

    void refusesBadInput()
    {
        const StructuredTetMesh linear = boxTetMesh(Eigen::Vector3d(0.01, 0.01, 0.01), {1, 1, 1});
        QuadraticTetMesh mesh = quadraticFromLinear(linear.points, linear.tets);
        QVERIFY_THROWS_EXCEPTION(Error, QuadraticFem(mesh, {}));
        QVERIFY_THROWS_EXCEPTION(Error, QuadraticFem(mesh, {HyperelasticMaterial::raghavanVorp2000()}, {0, 1}));
        HyperelasticMaterial soft = HyperelasticMaterial::raghavanVorp2000();
        soft.bulkModulus = 0.0;
        QVERIFY_THROWS_EXCEPTION(Error, QuadraticFem(mesh, {soft}));
        std::swap(mesh.elements[0][1], mesh.elements[0][2]); // inverted
        QVERIFY_THROWS_EXCEPTION(Error, QuadraticFem(mesh, {HyperelasticMaterial::raghavanVorp2000()}));
    }
};

QTEST_GUILESS_MAIN(FemQuadratic)
#include "tst_fem_quadratic.moc"
