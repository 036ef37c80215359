// Building blocks of the wall solver: the element stiffness is symmetric with the six rigid-body modes in its null
// space, lumped masses add up to rho V, the rotation extraction recovers a known rotation, boundary faces of a box
// are its 2 x 6 x n^2 outward triangles, a pressure on a closed surface sums to zero force, and bad input is refused.

#include "vsim/core/Error.h"
#include "vsim/sim/fem/CorotationalFem.h"
#include "vsim/sim/fem/RotationExtraction.h"
#include "vsim/sim/fem/StaticSolver.h"
#include "vsim/sim/fem/StructuredMeshes.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/SurfaceLoads.h"
#include "vsim/sim/fem/Tearing.h"

#include <Eigen/Eigenvalues>
#include <QtTest>

#include <random>
#include <tuple>

using namespace vsim;
using namespace vsim::sim::fem;

class FemModel : public QObject
{
    Q_OBJECT

private slots:
    void elementStiffnessHasRigidModes()
    {
        const std::array<Eigen::Vector3d, 4> corners{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.01, 0.001, 0),
                                                     Eigen::Vector3d(0.002, 0.012, 0.001), Eigen::Vector3d(0.001, 0.002, 0.009)};
        const TetRest rest = restTetrahedron(corners, ElasticMaterial{});
        QVERIFY((rest.stiffness - rest.stiffness.transpose()).norm() <= 1e-9 * rest.stiffness.norm());
        const Eigen::SelfAdjointEigenSolver<Matrix12d> eigen(rest.stiffness);
        const auto values = eigen.eigenvalues();
        for (int i = 0; i < 6; ++i)
            QVERIFY(std::abs(values[i]) <= 1e-9 * values[11]); // 3 translations + 3 rotations
        QVERIFY(values[6] > 1e-6 * values[11]);
        QCOMPARE(rest.volume, Eigen::Matrix3d((Eigen::Matrix3d() << corners[1] - corners[0], corners[2] - corners[0],
                                                corners[3] - corners[0]).finished()).determinant() / 6.0);
    }

    void lumpedMassAddsUp()
    {
        const StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(0.02, 0.03, 0.01), {3, 4, 2});
        ElasticMaterial material;
        const CorotationalFem model(mesh.points, mesh.tets, material);
        QCOMPARE(model.elementCount(), std::size_t(6 * 24));
        const double total = model.lumpedMass().sum() / 3.0;
        QVERIFY(std::abs(total - material.densityKgPerM3 * 0.02 * 0.03 * 0.01) < 1e-12);
    }

    void rotationExtractionRecoversAKnownRotation()
    {
        std::mt19937 random(5);
        std::normal_distribution<double> normal;
        for (int trial = 0; trial < 20; ++trial)
        {
            const Eigen::Quaterniond truth = Eigen::Quaterniond(normal(random), normal(random), normal(random), normal(random)).normalized();
            Eigen::Matrix3d stretch = Eigen::Matrix3d::Identity();
            stretch(0, 0) = 1.3, stretch(1, 1) = 0.8, stretch(0, 1) = stretch(1, 0) = 0.1; // symmetric positive
            Eigen::Quaterniond estimate = Eigen::Quaterniond::Identity();
            extractRotation(truth.toRotationMatrix() * stretch, estimate, 100);
            QVERIFY2((estimate.toRotationMatrix() - truth.toRotationMatrix()).norm() < 1e-9, qPrintable(QString::number(trial)));
        }
    }

    void boundaryFacesPointOutAndPressureBalances()
    {
        const StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(1.0, 1.0, 1.0), {3, 3, 3});
        const auto faces = boundaryFaces(mesh.tets);
        QCOMPARE(faces.size(), std::size_t(2 * 6 * 9));
        Eigen::VectorXd positions(Eigen::Index(3 * mesh.points.size()));
        for (std::size_t n = 0; n < mesh.points.size(); ++n)
            positions.segment<3>(Eigen::Index(3 * n)) = mesh.points[n];
        for (const auto& face : faces)
        {
            const Eigen::Vector3d p0 = mesh.points[std::size_t(face[0])];
            const Eigen::Vector3d normal = (mesh.points[std::size_t(face[1])] - p0).cross(mesh.points[std::size_t(face[2])] - p0);
            const Eigen::Vector3d centre = (p0 + mesh.points[std::size_t(face[1])] + mesh.points[std::size_t(face[2])]) / 3.0;
            QVERIFY(normal.dot(centre - Eigen::Vector3d(0.5, 0.5, 0.5)) > 0.0);
        }
        // 1 kPa on the closed surface: no net force, and the force on the face x = 1 is -1 kN along x.
        Eigen::VectorXd forces = Eigen::VectorXd::Zero(positions.size());
        addPressureForces(faces, positions, 1e3, forces);
        Eigen::Vector3d net = Eigen::Vector3d::Zero(), onRight = Eigen::Vector3d::Zero();
        for (std::size_t n = 0; n < mesh.points.size(); ++n)
            net += forces.segment<3>(Eigen::Index(3 * n));
        QVERIFY(net.norm() < 1e-9);
        std::vector<std::array<int, 3>> right;
        for (const auto& face : faces)
            if (mesh.points[std::size_t(face[0])].x() > 0.999 && mesh.points[std::size_t(face[1])].x() > 0.999 &&
                mesh.points[std::size_t(face[2])].x() > 0.999)
                right.push_back(face);
        forces.setZero();
        addPressureForces(right, positions, 1e3, forces);
        for (std::size_t n = 0; n < mesh.points.size(); ++n)
            onRight += forces.segment<3>(Eigen::Index(3 * n));
        QVERIFY((onRight - Eigen::Vector3d(-1e3, 0, 0)).norm() < 1e-9);
    }

    /// The Newton tangent of the static solver against central differences of the residual force: a box
    /// (1 x 1.5 x 2 cm) stretched, sheared and turned by 50 degrees, with a follower pressure on its faces x = 0.
    /// Without the rotations' derivative R K R^T alone is off by the stress-dependent part; with it (and the
    /// pressure's load stiffness) the products agree to rounding, on three seeds.
    void newtonTangentMatchesFiniteDifferences()
    {
        const StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(0.01, 0.015, 0.02), {2, 3, 4});
        std::vector<std::array<int, 3>> loaded;
        for (const auto& face : boundaryFaces(mesh.tets))
            if (mesh.points[std::size_t(face[0])].x() < 1e-9 && mesh.points[std::size_t(face[1])].x() < 1e-9 &&
                mesh.points[std::size_t(face[2])].x() < 1e-9)
                loaded.push_back(face);
        const double pressure = 2e5; // Pa
        for (unsigned seed : {1u, 2u, 3u})
        {
            CorotationalFem model(mesh.points, mesh.tets, ElasticMaterial{});
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> jitter(-1.0, 1.0);
            const Eigen::Matrix3d turn = Eigen::AngleAxisd(50.0 * M_PI / 180.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
            Eigen::Matrix3d strain;
            strain << 1.1, 0.05, 0.0, 0.0, 0.95, 0.08, 0.02, 0.0, 1.05;
            for (std::size_t n = 0; n < mesh.points.size(); ++n)
                model.positions().segment<3>(Eigen::Index(3 * n)) =
                    turn * strain * mesh.points[n] + 1e-4 * Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
            const auto residual = [&](const Eigen::VectorXd& x) {
                model.positions() = x;
                model.updateElements();
                Eigen::VectorXd f = model.elasticForces();
                addPressureForces(loaded, x, pressure, f);
                return f;
            };
            const Eigen::VectorXd x0 = model.positions();
            Eigen::VectorXd v(x0.size());
            for (Eigen::Index i = 0; i < v.size(); ++i)
                v[i] = jitter(random);
            const double h = 1e-8 / v.cwiseAbs().maxCoeff(); // the largest move 10 nm
            const Eigen::VectorXd expected = -(residual(x0 + h * v) - residual(x0 - h * v)) / (2.0 * h);
            residual(x0);
            BlockSparseMatrix tangent = model.makeMatrix();
            model.assemble(tangent, 0.0, 1.0);
            subtractPressureStiffness(loaded, x0, pressure, tangent);
            Eigen::VectorXd approximate(v.size()), full(v.size());
            tangent.multiply(v, approximate);
            model.addRotationStiffness(tangent);
            tangent.multiply(v, full);
            const double withoutRotation = (approximate - expected).norm() / expected.norm();
            const double error = (full - expected).norm() / expected.norm();
            qInfo("seed %u: |T v - FD| / |FD| = %.2e with the rotations' derivative, %.2e without", seed, error,
                  withoutRotation);
            QVERIFY(error < 1e-6);
            QVERIFY(withoutRotation > 1e-3); // the test can tell the two apart
        }
    }

    // A crack along a shared edge: the two cells left touch only along that edge, so its two nodes split.
    void detachingSplitsTheNodesAFractureSeparates()
    {
        const StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(0.02, 0.02, 0.01), {2, 2, 1});
        CorotationalFem model(mesh.points, mesh.tets, ElasticMaterial{});
        model.positions().array() += 1e-4; // a moved state is carried over
        std::vector<std::size_t> torn;
        for (std::size_t cell : {1u, 2u}) // cells (1, 0) and (0, 1)
            for (std::size_t t = 6 * cell; t < 6 * cell + 6; ++t)
                torn.push_back(t);
        const DetachedModel detached = detachElements(model, torn);
        QCOMPARE(detached.model.elementCount(), std::size_t(12));
        QCOMPARE(detached.splitNodes, std::size_t(2)); // the edge x = y = 10 mm, at z = 0 and 10 mm
        // The outer corner edge of each removed cell is orphaned (2 x 2 nodes): 18 - 4 + 2 copies.
        QCOMPARE(detached.model.nodeCount(), std::size_t(16));
        for (std::size_t n = 0; n < detached.model.nodeCount(); ++n)
            QVERIFY((detached.model.positions().segment<3>(Eigen::Index(3 * n)) -
                     model.positions().segment<3>(3 * detached.oldNodeOf[n])).norm() == 0.0);
        // The two halves no longer share a node: mass splits evenly.
        QVERIFY(std::abs(detached.model.lumpedMass().sum() - 0.5 * model.lumpedMass().sum()) < 1e-15);
        QVERIFY_THROWS_EXCEPTION(Error, detachElements(model, std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10,
                                                                                      11, 12, 13, 14, 15, 16, 17, 18, 19,
                                                                                      20, 21, 22, 23}));
    }

    void fractureEntropyCountsEffectiveTears()
    {
        FractureEntropy entropy;
        entropy.addTornElement(2.0);
        QCOMPARE(entropy.value(), 0.0);
        entropy.addTornElement(2.0);
        QVERIFY(std::abs(entropy.value() - std::log(2.0)) < 1e-12);
        for (int k = 0; k < 6; ++k)
            entropy.addTornElement(2.0);
        QVERIFY(std::abs(entropy.effectiveCount() - 8.0) < 1e-9);
        entropy.addTornElement(1e-9); // a tear that released almost nothing barely counts
        QVERIFY(std::abs(entropy.effectiveCount() - 8.0) < 1e-6);
    }

    // St. Venant-Kirchhoff: no force under a rigid 90-degree rotation, and a bar (nu = 0) stretched by 30 % pulls
    // with P A0 = lambda E (lambda^2 - 1) / 2 A0 (44.85 N here, where linear elasticity would give 30 N); at 0.1 %
    // both models give E eps A0.
    void stVenantKirchhoffRotationAndStretch()
    {
        const StructuredTetMesh bar = boxTetMesh(Eigen::Vector3d(0.1, 0.01, 0.01), {10, 2, 2});
        ElasticMaterial svk;
        svk.youngModulusPa = 1e6;
        svk.poissonRatio = 0.0;
        svk.model = ElasticMaterial::Model::StVenantKirchhoff;
        {
            CorotationalFem model(bar.points, bar.tets, svk);
            const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
            for (std::size_t n = 0; n < model.nodeCount(); ++n)
                model.positions().segment<3>(Eigen::Index(3 * n)) = turn * bar.points[n];
            model.updateElements();
            QVERIFY(model.elasticForces().cwiseAbs().maxCoeff() < 1e-9 * svk.youngModulusPa * 0.005 * 0.005);
        }
        for (const auto& [stretch, material, expected] :
             std::vector<std::tuple<double, ElasticMaterial::Model, double>>{
                 {1.3, ElasticMaterial::Model::StVenantKirchhoff, 1.3 * 1e6 * (1.3 * 1.3 - 1.0) / 2.0 * 1e-4},
                 {1.001, ElasticMaterial::Model::StVenantKirchhoff, 1.001 * 1e6 * (1.001 * 1.001 - 1.0) / 2.0 * 1e-4},
                 {1.001, ElasticMaterial::Model::CorotationalLinear, 1e6 * 0.001 * 1e-4}})
        {
            ElasticMaterial chosen = svk;
            chosen.model = material;
            CorotationalFem model(bar.points, bar.tets, chosen);
            std::vector<std::uint8_t> fixed(3 * model.nodeCount(), 0);
            for (std::size_t n = 0; n < model.nodeCount(); ++n)
            {
                fixed[3 * n + 1] = fixed[3 * n + 2] = 1; // nu = 0: no lateral motion anyway; no rigid modes
                if (bar.points[n].x() < 1e-12 || bar.points[n].x() > 0.1 - 1e-12)
                    fixed[3 * n] = 1;
                if (bar.points[n].x() > 0.1 - 1e-12)
                    model.positions()[Eigen::Index(3 * n)] = 0.1 * stretch;
            }
            // Only the end is moved; the interior must be found (Newton with the consistent tangent).
            const StaticSolveReport report = solveStatic(model, {}, fixed, 1e-10);
            QVERIFY(report.converged);
            model.updateElements();
            const Eigen::VectorXd forces = model.elasticForces();
            double pull = 0.0;
            for (std::size_t n = 0; n < model.nodeCount(); ++n)
                if (bar.points[n].x() > 0.1 - 1e-12)
                    pull -= forces[Eigen::Index(3 * n)]; // the elastic force pulls the end back
            qInfo("%s, stretch %.3f: end force %.5f N (expected %.5f N), %d linearised solves",
                  material == ElasticMaterial::Model::StVenantKirchhoff ? "St. Venant-Kirchhoff" : "co-rotational",
                  stretch, pull, expected, report.updates);
            QVERIFY(std::abs(pull / expected - 1.0) < 0.005);
        }
    }

    void badInputIsRefused()
    {
        StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(1.0, 1.0, 1.0), {1, 1, 1});
        ElasticMaterial bad;
        bad.poissonRatio = 0.5;
        QVERIFY_THROWS_EXCEPTION(Error, CorotationalFem(mesh.points, mesh.tets, bad));
        std::swap(mesh.tets[0][1], mesh.tets[0][2]); // inverted
        QVERIFY_THROWS_EXCEPTION(Error, CorotationalFem(mesh.points, mesh.tets, ElasticMaterial{}));
        mesh = boxTetMesh(Eigen::Vector3d(1.0, 1.0, 1.0), {1, 1, 1});
        mesh.tets[2][3] = 99;
        QVERIFY_THROWS_EXCEPTION(Error, CorotationalFem(mesh.points, mesh.tets, ElasticMaterial{}));
    }
};

QTEST_GUILESS_MAIN(FemModel)
#include "tst_fem_model.moc"
