// The smoothed-aggregation multigrid preconditioner of the implicit step (AggregationMultigrid.h): its V-cycle is a
// symmetric positive definite operator (PCG needs that), PCG with it reaches the sparse direct solution of the
// same masked system on a tube wall and on a clamped box (random right-hand sides, seeds 1-3) in a fraction of
// block Jacobi's iterations, and a run of implicit steps ends where block Jacobi's ends.

#include "vsim/core/Error.h"
#include "vsim/sim/fem/AggregationMultigrid.h"
#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/ConjugateGradient.h"
#include "vsim/sim/fem/StructuredMeshes.h"
#include "vsim/sim/fem/SurfaceLoads.h"
#include "vsim/core/TetMesh.h"

#include <Eigen/SparseCholesky>
#include <QtTest>

#include <random>

using namespace vsim;
using namespace vsim::sim::fem;

namespace {

struct Case
{
    const char* name;
    StructuredTetMesh mesh;
    std::vector<std::uint8_t> held;
};

/// A tube wall (radius 10 mm, 1.5 mm thick, 100 mm long) with both ends held, and a 30 x 20 x 10 mm box held on
/// its x = 0 face.
std::vector<Case> cases()
{
    std::vector<Case> all;
    Case tube{"tube", tubeWallTetMesh(0.01, 0.0115, 0.1, {1, 75, 14}), {}};
    Case box{"box", boxTetMesh(Eigen::Vector3d(0.03, 0.02, 0.01), {12, 8, 4}), {}};
    for (Case* c : {&tube, &box})
    {
        c->held.assign(3 * c->mesh.points.size(), 0);
        for (std::size_t n = 0; n < c->mesh.points.size(); ++n)
        {
            const Eigen::Vector3d& p = c->mesh.points[n];
            const bool held = c == &tube ? (p.z() < 1e-9 || p.z() > 0.1 - 1e-9) : p.x() < 1e-9;
            for (int k = 0; k < 3; ++k)
                c->held[3 * n + std::size_t(k)] = held ? 1 : 0;
        }
    }
    all.push_back(std::move(tube));
    all.push_back(std::move(box));
    return all;
}

/// The implicit step's matrix (1 ms step, Rayleigh beta 0.22 s) of the case's wall at rest, and its positions.
struct AtRest
{
    BlockSparseMatrix matrix;
    Eigen::VectorXd positions;
};

AtRest atRest(const Case& c)
{
    CorotationalFem model(c.mesh.points, c.mesh.tets, ElasticMaterial{});
    model.updateElements();
    AtRest rest{model.makeMatrix(), model.positions()};
    const BackwardEulerSettings settings;
    const double h = settings.timeStep;
    model.assemble(rest.matrix, 1.0, h * settings.rayleighBeta + h * h);
    return rest;
}

Eigen::VectorXd randomMasked(std::mt19937& random, const Eigen::VectorXd& free)
{
    std::normal_distribution<double> normal;
    Eigen::VectorXd v(free.size());
    for (Eigen::Index i = 0; i < v.size(); ++i)
        v[i] = normal(random) * free[i];
    return v;
}

} // namespace

class FemMultigrid : public QObject
{
    Q_OBJECT

private slots:
    void vCycleIsSymmetricPositiveDefinite()
    {
        for (const Case& c : cases())
        {
            const AtRest rest = atRest(c);
            const BlockSparseMatrix& a = rest.matrix;
            const AggregationMultigrid multigrid(a, rest.positions, c.held);
            QVERIFY2(multigrid.levels().size() >= 2, c.name);
            for (unsigned seed : {1u, 2u, 3u})
            {
                std::mt19937 random(seed);
                const Eigen::VectorXd x = randomMasked(random, multigrid.freeMask());
                const Eigen::VectorXd y = randomMasked(random, multigrid.freeMask());
                Eigen::VectorXd mx, my;
                multigrid.apply(a, x, mx);
                multigrid.apply(a, y, my);
                const double asymmetry = std::abs(x.dot(my) - y.dot(mx)) / (x.norm() * my.norm());
                qInfo("%s seed %u: |x.My - y.Mx| / (|x| |My|) = %.2e, x.Mx / |x|^2 = %.3e", c.name, seed, asymmetry,
                      x.dot(mx) / x.squaredNorm());
                QVERIFY2(asymmetry <= 1e-10, c.name);
                QVERIFY2(x.dot(mx) > 0.0, c.name);
            }
        }
    }

    /// The set-up's poll (AggregationMultigridSettings::afterLevel, a Cancel's) is called once per coarsening, and
    /// what it throws leaves the set-up.
    void setUpPollsAfterEachLevel()
    {
        for (const Case& c : cases())
        {
            const AtRest rest = atRest(c);
            AggregationMultigridSettings settings;
            int polls = 0;
            settings.afterLevel = [&polls] { ++polls; };
            const AggregationMultigrid multigrid(rest.matrix, rest.positions, c.held, settings);
            QCOMPARE(std::size_t(polls), multigrid.levels().size() - 1);
            QVERIFY(!multigrid.settings().afterLevel); // not kept past the set-up
            settings.afterLevel = [] { throw Cancelled(); };
            QVERIFY_THROWS_EXCEPTION(Cancelled, AggregationMultigrid(rest.matrix, rest.positions, c.held, settings));
        }
    }

    void preconditionedSolveMatchesDirectSolve()
    {
        for (const Case& c : cases())
        {
            const AtRest rest = atRest(c);
            const BlockSparseMatrix& a = rest.matrix;
            const AggregationMultigrid multigrid(a, rest.positions, c.held);
            // The reference: the masked system S A S + (I - S) by a sparse Cholesky factorisation.
            const Eigen::VectorXd& free = multigrid.freeMask();
            std::vector<Eigen::Triplet<double>> entries;
            for (std::size_t row = 0; row < a.nodeCount(); ++row)
                for (std::uint32_t s = a.rowStart()[row]; s < a.rowStart()[row + 1]; ++s)
                    for (int r = 0; r < 3; ++r)
                        for (int k = 0; k < 3; ++k)
                        {
                            const int i = int(3 * row) + r, j = int(3 * a.columns()[s]) + k;
                            entries.emplace_back(i, j, free[i] * free[j] * a.block(s)(r, k));
                        }
            for (Eigen::Index i = 0; i < free.size(); ++i)
                if (free[i] == 0.0)
                    entries.emplace_back(int(i), int(i), 1.0);
            Eigen::SparseMatrix<double> masked(free.size(), free.size());
            masked.setFromTriplets(entries.begin(), entries.end());
            const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct(masked);
            QVERIFY(direct.info() == Eigen::Success);
            for (unsigned seed : {1u, 2u, 3u})
            {
                std::mt19937 random(seed);
                const Eigen::VectorXd b = randomMasked(random, free);
                const Eigen::VectorXd truth = direct.solve(b);
                Eigen::VectorXd xJacobi = Eigen::VectorXd::Zero(b.size()), xMultigrid = xJacobi;
                const ConjugateGradientResult jacobi = solveConjugateGradient(a, b, xJacobi, c.held, 1e-10, 20000);
                const ConjugateGradientResult cycled =
                    solveConjugateGradient(a, b, xMultigrid, c.held, 1e-10, 20000, &multigrid);
                const double error = (xMultigrid - truth).norm() / truth.norm();
                qInfo("%s seed %u: PCG to 1e-10 in %d iterations (block Jacobi %d), |x - x_direct| / |x_direct| = %.2e",
                      c.name, seed, cycled.iterations, jacobi.iterations, error);
                QVERIFY2(cycled.converged && jacobi.converged, c.name);
                QVERIFY2(error <= 1e-8, c.name);
                QVERIFY2(4 * cycled.iterations <= jacobi.iterations, c.name);
            }
        }
    }

    void stepsEndWhereBlockJacobiEnds()
    {
        const Case tube = cases().front();
        std::vector<std::array<int, 3>> inner;
        for (const auto& face : boundaryFaces(tube.mesh.tets))
        {
            bool onInner = true;
            for (int node : face)
                onInner = onInner && tube.mesh.points[std::size_t(node)].head<2>().norm() < 0.01 + 1e-9;
            if (onInner)
                inner.push_back(face);
        }
        Eigen::VectorXd ends[3];
        int iterations[3] = {0, 0, 0}, setUps[3] = {0, 0, 0};
        for (int run = 0; run < 3; ++run) // block Jacobi, multigrid, multigrid set up every second step
        {
            BackwardEulerSettings settings;
            settings.cgTolerance = 1e-10, settings.cgMaxIterations = 20000;
            settings.preconditioner = run == 0 ? CgPreconditioner::BlockJacobi : CgPreconditioner::Multigrid;
            settings.multigridSetUpAgainFactor = run == 2 ? 0.0 : 2.0;
            CorotationalFem model(tube.mesh.points, tube.mesh.tets, ElasticMaterial{});
            BackwardEuler integrator(model, settings);
            const Eigen::VectorXd start = model.positions();
            Eigen::VectorXd forces(model.positions().size());
            for (int k = 0; k < 10; ++k)
            {
                forces.setZero();
                addPressureForces(inner, model.positions(), 16e3, forces);
                const StepReport report = integrator.step(model, forces, tube.held);
                QVERIFY(report.cgConverged);
                iterations[run] += report.cgIterations;
            }
            ends[run] = model.positions() - start;
            setUps[run] = integrator.multigridSetUps();
        }
        const double difference = (ends[1] - ends[0]).norm() / ends[0].norm();
        const double everyStep = (ends[2] - ends[0]).norm() / ends[0].norm();
        qInfo("10 steps at 16 kPa: displacements %.2e relative apart (%.2e with a set-up every second step); PCG iterations "
              "block Jacobi %d, multigrid %d (%d set-ups), %d (%d set-ups)",
              difference, everyStep, iterations[0], iterations[1], setUps[1], iterations[2], setUps[2]);
        QVERIFY(difference <= 1e-7 && everyStep <= 1e-7);
        QVERIFY(4 * iterations[1] <= iterations[0]);
        QCOMPARE(setUps[1], 1);
        QCOMPARE(setUps[2], 5);
    }
};

QTEST_GUILESS_MAIN(FemMultigrid)
#include "tst_fem_multigrid.moc"
