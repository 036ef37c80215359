// The direct solve (SparseDirect.h) under a Cancel: a factorisation run with a poll leaves within the poll's 50 ms
// when the poll throws, not when the factorisation ends, and the same object factorises again to the plain solve.

#include "vsim/core/Error.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/Hyperelastic.h"
#include "vsim/sim/fem/QuadraticFem.h"
#include "vsim/sim/fem/SparseDirect.h"
#include "vsim/sim/fem/StructuredMeshes.h"

#include <QElapsedTimer>
#include <QtTest>

using namespace vsim;
using namespace vsim::sim::fem;

class FemSparseDirect : public QObject
{
    Q_OBJECT

private slots:
    /// A Cancel during a factorisation leaves within the 50 ms poll, not when the factorisation ends (seconds on a
    /// clinical wall): the quadratic box refined to 8 x 8 x 32 cells (about 57,000 free unknowns), its stiffness at
    /// rest factorised three times, each by CHOLMOD: plainly; with a poll that cancels (vsim::Cancelled within
    /// 0.15 s, against the plain factorisation's time); and, on the same object, with a poll that does not (the
    /// factors then give the plain one's solution to rounding).
    void aCancelledFactorisationLeavesAtOnce()
    {
        const StructuredTetMesh linear = boxTetMesh(Eigen::Vector3d(0.01, 0.01, 0.04), {8, 8, 32});
        const QuadraticTetMesh mesh = quadraticFromLinear(linear.points, linear.tets);
        std::vector<std::uint8_t> cornersHeld(3 * linear.points.size(), 0);
        for (std::size_t n = 0; n < linear.points.size(); ++n)
            if (linear.points[n].z() < 1e-9)
                cornersHeld[3 * n] = cornersHeld[3 * n + 1] = cornersHeld[3 * n + 2] = 1;
        const std::vector<std::uint8_t> held = quadraticConstraints(mesh, cornersHeld);
        QuadraticFem model(mesh, {HyperelasticMaterial::raghavanVorp2000()},
                           std::vector<std::uint8_t>(mesh.elements.size(), 0));
        model.updateElements();
        BlockSparseMatrix stiffness = model.makeMatrix();
        model.assembleDefiniteTangent(stiffness, true);
        Eigen::VectorXd force = Eigen::VectorXd::Ones(model.positions().size());

        SparseDirect plain(stiffness, held, SparseDirect::Kind::SymmetricCholesky);
        QElapsedTimer clock;
        clock.start();
        QVERIFY(plain.factorize(stiffness));
        const double plainSeconds = 1e-3 * double(clock.elapsed());
        Eigen::VectorXd expected;
        QVERIFY(plain.solve(force, expected) <= 1e-8); // the direct solves' own check (TangentSolver)

        SparseDirect cancelled(stiffness, held, SparseDirect::Kind::SymmetricCholesky);
        int polls = 0;
        clock.restart();
        QVERIFY_THROWS_EXCEPTION(Cancelled, cancelled.factorize(stiffness, [&polls] {
            ++polls;
            throw Cancelled();
        }));
        const double cancelSeconds = 1e-3 * double(clock.elapsed());
        qInfo("%zu free unknowns: the factorisation %.3f s; cancelled after %.3f s (%d poll)", plain.freeCount(),
              plainSeconds, cancelSeconds, polls);
        QVERIFY2(plainSeconds > 0.2, "the factorisation is too quick to show a Cancel's latency");
        QCOMPARE(polls, 1);
        QVERIFY(cancelSeconds <= 0.15);

        polls = 0;
        QVERIFY(cancelled.factorize(stiffness, [&polls] { ++polls; }));
        Eigen::VectorXd x;
        QVERIFY(cancelled.solve(force, x) <= 1e-8);
        QVERIFY(polls >= 1);
        QVERIFY((x - expected).norm() <= 1e-12 * expected.norm());
    }
};

QTEST_GUILESS_MAIN(FemSparseDirect)
#include "tst_fem_sparse_direct.moc"
