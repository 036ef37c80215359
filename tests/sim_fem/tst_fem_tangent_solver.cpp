// The Newton update's linear solve (TangentSolver.h, Gmres.h) on the quadratic model's non-symmetric tangent (a
// jittered, stretched and sheared box of wall and thrombus elements under a follower pressure on one face, one
// face held): GMRES with the kept Cholesky preconditioner reaches 1e-8 and agrees with UMFPACK's LU; a kept
// preconditioner serves the next, changed tangent within its budget; near equilibrium the tangent's own symmetric
// part is factorised and the stand-in not assembled; a compressed box's indefinite tangent is preconditioned by the
// model's definite stand-in; a tangent whose symmetric part is not positive definite falls
// back to LU, and a stand-in that failed is not factorised again far from equilibrium; a static solve whose line
// search stalls gives up; near equilibrium GMRES with a multigrid V-cycle of the stand-in (no factorisation) agrees with the
// LU; held components stay 0. Three seeds.

#include "vsim/core/Error.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/Gmres.h"
#include "vsim/sim/fem/Hyperelastic.h"
#include "vsim/sim/fem/QuadraticFem.h"
#include "vsim/sim/fem/SparseDirect.h"
#include "vsim/sim/fem/StructuredMeshes.h"
#include "vsim/sim/fem/SurfaceLoads.h"
#include "vsim/sim/fem/TangentSolver.h"

#include <QtTest>

#include <random>

using namespace vsim;
using namespace vsim::sim::fem;

namespace {

constexpr double kCompression = 0.75; // the stretch along x of the compressed box (volume kept)
constexpr double kStallTestPa = 1e4;  // the stall case's follower pressure: its first Newton step overshoots

struct Case
{
    QuadraticTetMesh mesh;
    std::vector<std::uint8_t> held;
    std::vector<std::array<int, 6>> loaded;
};

Case boxCase()
{
    const StructuredTetMesh linear = boxTetMesh(Eigen::Vector3d(0.01, 0.012, 0.03), {3, 3, 6});
    Case c;
    c.mesh = quadraticFromLinear(linear.points, linear.tets);
    std::vector<std::uint8_t> cornersHeld(3 * linear.points.size(), 0);
    for (std::size_t n = 0; n < linear.points.size(); ++n)
        if (linear.points[n].z() < 1e-9)
            cornersHeld[3 * n] = cornersHeld[3 * n + 1] = cornersHeld[3 * n + 2] = 1;
    c.held = quadraticConstraints(c.mesh, cornersHeld);
    std::vector<std::array<int, 3>> faces;
    for (const auto& face : boundaryFaces(linear.tets))
        if (linear.points[std::size_t(face[0])].x() < 1e-9 && linear.points[std::size_t(face[1])].x() < 1e-9 &&
            linear.points[std::size_t(face[2])].x() < 1e-9)
            faces.push_back(face);
    c.loaded = quadraticFaces(c.mesh, faces);
    return c;
}

/// Wall and thrombus elements (every third) of the box.
QuadraticFem boxModel(const Case& c)
{
    std::vector<std::uint8_t> materialOf(c.mesh.elements.size(), 0);
    for (std::size_t e = 0; e < materialOf.size(); e += 3)
        materialOf[e] = 1;
    return QuadraticFem(c.mesh, {HyperelasticMaterial::raghavanVorp2000(), HyperelasticMaterial::wang2001Thrombus()},
                        materialOf);
}

/// The box stretched by `stretch` along x (and by `lateral` along y and z), sheared, each node jittered by up to
/// 0.05 mm; its element pass done.
void deform(QuadraticFem& model, const Case& c, std::mt19937& random, double stretch, double lateral = 1.0)
{
    std::uniform_real_distribution<double> jitter(-1.0, 1.0);
    Eigen::Matrix3d f = lateral * Eigen::Matrix3d::Identity();
    f(0, 0) = stretch;
    f(0, 2) = 0.05;
    for (std::size_t n = 0; n < c.mesh.points.size(); ++n)
        model.positions().segment<3>(Eigen::Index(3 * n)) =
            f * c.mesh.points[n] + 5e-5 * Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
    model.updateElements();
}

/// A uniform stretch `along` x that keeps the volume (1 / sqrt(along) across), the box in tension along x.
void stretchKeepingVolume(QuadraticFem& model, const Case& c, double along)
{
    const Eigen::Vector3d f(along, 1.0 / std::sqrt(along), 1.0 / std::sqrt(along));
    for (std::size_t n = 0; n < c.mesh.points.size(); ++n)
        model.positions().segment<3>(Eigen::Index(3 * n)) = f.cwiseProduct(c.mesh.points[n]);
    model.updateElements();
}

/// At the model's present state: the tangent with the load stiffness of `pressurePa` on the loaded face, its
/// definite part without the load, and the follower force.
struct LoadedState
{
    BlockSparseMatrix tangent, definite;
    Eigen::VectorXd force;
};
LoadedState loadedState(QuadraticFem& model, const Case& c, double pressurePa)
{
    LoadedState state{model.makeMatrix(), model.makeMatrix(), Eigen::VectorXd::Zero(model.positions().size())};
    model.assembleTangent(state.tangent, true);
    model.assembleDefiniteTangent(state.definite, true);
    subtractPressureStiffness(c.loaded, model.positions(), pressurePa, state.tangent);
    addPressureForces(c.loaded, model.positions(), pressurePa, state.force);
    return state;
}

/// The tangent (consistent + load stiffness of `pressurePa`, 50 kPa by default) at a random deformation near
/// `stretch`; the force vector.
BlockSparseMatrix deformedTangent(const Case& c, unsigned seed, double stretch, Eigen::VectorXd& force,
                                  double pressurePa = 5e4)
{
    QuadraticFem model = boxModel(c);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> jitter(-1.0, 1.0);
    deform(model, c, random, stretch);
    BlockSparseMatrix tangent = model.makeMatrix();
    model.assembleTangent(tangent, true);
    subtractPressureStiffness(c.loaded, model.positions(), pressurePa, tangent);
    force = Eigen::VectorXd::Zero(model.positions().size());
    addPressureForces(c.loaded, model.positions(), pressurePa, force);
    for (Eigen::Index i = 0; i < force.size(); ++i)
        force[i] += 1e-3 * jitter(random);
    return tangent;
}

double residualOf(const BlockSparseMatrix& a, const Eigen::VectorXd& x, const Eigen::VectorXd& b,
                  const std::vector<std::uint8_t>& held)
{
    Eigen::VectorXd ax;
    a.multiply(x, ax);
    Eigen::VectorXd r = b - ax;
    Eigen::VectorXd free = b;
    for (std::size_t i = 0; i < held.size(); ++i)
        if (held[i])
            r[Eigen::Index(i)] = free[Eigen::Index(i)] = 0.0;
    return r.norm() / free.norm();
}

bool heldStayZero(const Eigen::VectorXd& x, const std::vector<std::uint8_t>& held)
{
    for (std::size_t i = 0; i < held.size(); ++i)
        if (held[i] && x[Eigen::Index(i)] != 0.0)
            return false;
    return true;
}

/// The matrix shifted down by a third of its mean diagonal: indefinite, still regular.
BlockSparseMatrix shiftedIndefinite(BlockSparseMatrix matrix)
{
    double mean = 0.0;
    for (std::size_t n = 0; n < matrix.nodeCount(); ++n)
        mean += matrix.diagonal(n).trace() / (3.0 * double(matrix.nodeCount()));
    for (std::size_t n = 0; n < matrix.nodeCount(); ++n)
        matrix.diagonal(n) -= (mean / 3.0) * Eigen::Matrix3d::Identity();
    return matrix;
}

/// The stand-in `matrix`, counting the calls that assemble it.
TangentSolver::StandIn standInOf(const BlockSparseMatrix& matrix, int* calls = nullptr)
{
    return [&matrix, calls]() -> const BlockSparseMatrix& {
        if (calls)
            ++*calls;
        return matrix;
    };
}

} // namespace

class FemTangentSolver : public QObject
{
    Q_OBJECT

    /// Full Newton on the quadratic box with GMRES on the Cholesky (the wall solve's settings), to 1e-8.
    static StaticSolveSettings loadedBoxSettings()
    {
        StaticSolveSettings settings;
        settings.linear = LinearSolver::CholeskyGmres;
        settings.rotationStiffness = settings.directionalLineSearch = true;
        settings.tolerance = 1e-8;
        return settings;
    }

    /// The box of `c` under kStallTestPa of follower pressure on its loaded faces, from rest.
    static StaticSolveReport solveLoadedBox(const Case& c, QuadraticFem& model, const StaticSolveSettings& settings)
    {
        const ExternalForces load = [&c](const Eigen::VectorXd& x) {
            Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
            addPressureForces(c.loaded, x, kStallTestPa, f);
            return f;
        };
        const ExternalStiffness stiffness = [&c](const Eigen::VectorXd& x, BlockSparseMatrix& tangent) {
            subtractPressureStiffness(c.loaded, x, kStallTestPa, tangent);
        };
        return solveStatic(model, load, c.held, settings, stiffness);
    }

private slots:
    void gmresWithCholeskyMatchesLu()
    {
        const Case c = boxCase();
        for (unsigned seed : {1u, 2u, 3u})
        {
            Eigen::VectorXd force;
            const BlockSparseMatrix tangent = deformedTangent(c, seed, 1.08, force);
            StaticSolveSettings gmresSettings, luSettings;
            gmresSettings.linear = LinearSolver::CholeskyGmres;
            luSettings.linear = LinearSolver::SparseLu;
            TangentSolver gmres(tangent, c.held, gmresSettings), lu(tangent, c.held, luSettings);
            Eigen::VectorXd x, reference;
            const TangentSolveResult solved = gmres.solve(tangent, force, x, true);
            const TangentSolveResult direct = lu.solve(tangent, force, reference);
            const double difference = (x - reference).norm() / reference.norm();
            qInfo("seed %u: GMRES %d iterations, residual %.1e (true %.1e); |x - x_LU| / |x_LU| = %.1e", seed,
                  solved.iterations, solved.relativeResidual, residualOf(tangent, x, force, c.held), difference);
            QVERIFY(solved.converged && direct.converged && solved.factorised);
            QVERIFY(solved.relativeResidual <= 1e-8);
            QVERIFY(residualOf(tangent, x, force, c.held) <= 2e-8);
            QVERIFY(difference < 1e-6);
            QVERIFY(heldStayZero(x, c.held));
        }
    }

    void keptPreconditionerServesTheNextTangent()
    {
        const Case c = boxCase();
        for (unsigned seed : {1u, 2u, 3u})
        {
            Eigen::VectorXd force, nextForce;
            const BlockSparseMatrix first = deformedTangent(c, seed, 1.08, force);
            const BlockSparseMatrix next = deformedTangent(c, seed, 1.082, nextForce); // a little further stretched
            StaticSolveSettings settings;
            settings.linear = LinearSolver::CholeskyGmres;
            TangentSolver solver(first, c.held, settings);
            Eigen::VectorXd x;
            solver.solve(first, force, x, true);
            QVERIFY(!solver.needsPreconditioner(0.5 * settings.reuseBelow));
            QVERIFY(solver.needsPreconditioner(2.0 * settings.reuseBelow));
            const TangentSolveResult kept = solver.solve(next, nextForce, x, false);
            qInfo("seed %u: kept preconditioner, %d iterations, residual %.1e", seed, kept.iterations,
                  kept.relativeResidual);
            QVERIFY(kept.converged && !kept.factorised);
            QVERIFY(kept.iterations > 1 && kept.iterations <= 3 * settings.reuseIterations);
            QVERIFY(residualOf(next, x, nextForce, c.held) <= 2e-8);
        }
    }

    /// Near equilibrium (force residual under tangentCholeskyBelow) the tangent's own symmetric part, follower load
    /// included, is factorised and the stand-in is not even assembled: GMRES needs fewer iterations than with the
    /// stand-in (without the load stiffness). Far from it the stand-in is assembled and used. (The other cases'
    /// jittered, sheared boxes are not positive definite even without the load.)
    void tangentsOwnCholeskyNearEquilibrium()
    {
        const Case c = boxCase();
        for (unsigned seed : {1u, 2u, 3u})
        {
            // A uniform stretch along x, volume kept (the box in tension along x), the follower load on the x = 0
            // face.
            QuadraticFem model = boxModel(c);
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> stretch(1.005, 1.02), jitter(-1.0, 1.0);
            const double along = stretch(random);
            stretchKeepingVolume(model, c, along);
            auto [tangent, withoutLoad, force] = loadedState(model, c, 5e2);
            for (Eigen::Index i = 0; i < force.size(); ++i)
                force[i] += 1e-4 * jitter(random);
            StaticSolveSettings settings;
            settings.linear = LinearSolver::CholeskyGmres;
            int nearCalls = 0, farCalls = 0;
            TangentSolver near(tangent, c.held, settings), far(tangent, c.held, settings);
            Eigen::VectorXd x, y;
            const TangentSolveResult own = near.solve(tangent, force, x, true, standInOf(withoutLoad, &nearCalls),
                                                      0.5 * settings.tangentCholeskyBelow);
            const TangentSolveResult stood = far.solve(tangent, force, y, true, standInOf(withoutLoad, &farCalls),
                                                       2.0 * settings.tangentCholeskyBelow);
            qInfo("seed %u: stretch %.3f, the tangent's own Cholesky %d iterations, the stand-in's %d", seed, along,
                  own.iterations, stood.iterations);
            QVERIFY(own.converged && own.factorised && stood.converged && stood.factorised);
            QCOMPARE(nearCalls, 0);
            QCOMPARE(farCalls, 1);
            QVERIFY(own.iterations < stood.iterations);
            QVERIFY(residualOf(tangent, x, force, c.held) <= 2e-8);
            QVERIFY(residualOf(tangent, y, force, c.held) <= 2e-8);
        }
    }

    void indefiniteSymmetricPartFallsBackToLu()
    {
        const Case c = boxCase();
        for (unsigned seed : {1u, 2u, 3u})
        {
            Eigen::VectorXd force;
            const BlockSparseMatrix tangent = shiftedIndefinite(deformedTangent(c, seed, 1.08, force));
            StaticSolveSettings settings;
            settings.linear = LinearSolver::CholeskyGmres;
            TangentSolver solver(tangent, c.held, settings);
            Eigen::VectorXd x;
            const TangentSolveResult solved = solver.solve(tangent, force, x, true);
            qInfo("seed %u: indefinite, %d iterations, residual %.1e", seed, solved.iterations, solved.relativeResidual);
            QVERIFY(solved.converged && solved.factorised);
            QCOMPARE(solved.iterations, 1); // the tangent's own LU
            QVERIFY(residualOf(tangent, x, force, c.held) <= 2e-8);
            QVERIFY(heldStayZero(x, c.held));
        }
    }

    /// The model's tangent (`material`, what the Cholesky would precondition with) not positive definite: the
    /// preconditioner is the LU of the tangent itself, not of that matrix (before 2026-11-28 it was, and GMRES stayed
    /// at 7.5e-8 after 200 iterations on an AAA wall).
    void indefiniteModelTangentTakesTheTangentsLu()
    {
        const Case c = boxCase();
        for (unsigned seed : {1u, 2u, 3u})
        {
            Eigen::VectorXd force;
            const BlockSparseMatrix tangent = deformedTangent(c, seed, 1.08, force);
            const BlockSparseMatrix model = shiftedIndefinite(tangent);
            StaticSolveSettings settings;
            settings.linear = LinearSolver::CholeskyGmres;
            TangentSolver solver(tangent, c.held, settings);
            Eigen::VectorXd x;
            // Far from equilibrium (force residual 2): the stand-in is what the Cholesky is tried on.
            const TangentSolveResult solved = solver.solve(tangent, force, x, true, standInOf(model), 2.0);
            qInfo("seed %u: indefinite model tangent, %d iterations, residual %.1e", seed, solved.iterations,
                  solved.relativeResidual);
            QVERIFY(solved.converged && solved.factorised);
            QCOMPARE(solved.iterations, 1);
            QVERIFY(residualOf(tangent, x, force, c.held) <= 2e-8);
        }
    }
    /// GMRES preconditioned by one smoothed-aggregation V-cycle of the model's definite stand-in, no factorisation
    /// (LinearSolver::MultigridGmres, the candidate for the GPU): near equilibrium (the box stretched along x with
    /// its volume kept, 500 Pa follower load) the same solution as the LU; the hierarchy is set up at the first
    /// solve and kept for the next, changed tangent. (On the sheared boxes of the other cases the stand-in is far
    /// from the indefinite tangent: even its Cholesky leaves GMRES short of 1e-8 after 200 iterations there.)
    void gmresWithMultigridMatchesLu()
    {
        const Case c = boxCase();
        for (unsigned seed : {1u, 2u, 3u})
        {
            QuadraticFem model = boxModel(c);
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> stretchOf(1.005, 1.02);
            BlockSparseMatrix tangent = model.makeMatrix(), definite = model.makeMatrix();
            StaticSolveSettings settings, luSettings;
            settings.linear = LinearSolver::MultigridGmres;
            settings.gmresMaxIterations = 500;
            luSettings.linear = LinearSolver::SparseLu;
            TangentSolver solver(tangent, c.held, settings, &model.positions()), lu(tangent, c.held, luSettings);
            for (int solve = 0; solve < 2; ++solve)
            {
                const double along = stretchOf(random);
                stretchKeepingVolume(model, c, along);
                model.assembleTangent(tangent, true);
                subtractPressureStiffness(c.loaded, model.positions(), 5e2, tangent);
                model.assembleDefiniteTangent(definite, true);
                Eigen::VectorXd force = Eigen::VectorXd::Zero(model.positions().size());
                addPressureForces(c.loaded, model.positions(), 5e2, force);
                Eigen::VectorXd x, reference;
                const TangentSolveResult solved = solver.solve(tangent, force, x, true, standInOf(definite));
                const TangentSolveResult direct = lu.solve(tangent, force, reference);
                const double difference = (x - reference).norm() / reference.norm();
                qInfo("seed %u, stretch %.3f: GMRES with the V-cycle %d iterations, residual %.1e, set up %d; "
                      "|x - x_LU| / |x_LU| = %.1e", seed, along, solved.iterations, solved.relativeResidual,
                      int(solved.factorised), difference);
                QVERIFY(solved.converged && direct.converged);
                QCOMPARE(solved.factorised, solve == 0); // set up at the first solve, kept for the second
                QVERIFY(solved.iterations > 1 && solved.iterations < settings.gmresMaxIterations);
                QVERIFY(residualOf(tangent, x, force, c.held) <= 2e-8);
                QVERIFY(difference < 1e-6);
                QVERIFY(heldStayZero(x, c.held));
            }
        }
    }
    void multigridGmresNeedsThePositions()
    {
        const Case c = boxCase();
        const QuadraticFem model = boxModel(c);
        StaticSolveSettings settings;
        settings.linear = LinearSolver::MultigridGmres;
        QVERIFY_THROWS_EXCEPTION(vsim::Error, TangentSolver(model.makeMatrix(), c.held, settings));
    }

    /// A box compressed to 0.75 along x (volume kept): the consistent tangent is indefinite (its Cholesky fails);
    /// the definite stand-in (stress and material tangent projected per quadrature point) factorises and
    /// preconditions GMRES on the tangent to 1e-8 within its budget, without the LU; at rest the two are the same
    /// matrix. (At 0.9 the tangent is nearly singular and GMRES needs the LU whatever the preconditioner.)
    /// Once the tangent's own Cholesky has failed (the compressed box at a force residual of 0.5), it is not tried
    /// again above a quarter of that residual (0.3: the stand-in is assembled and factorised), and is tried again
    /// below it (0.1, the stretched box's definite tangent: it factorises, the stand-in is not assembled, and GMRES
    /// needs fewer iterations than with the stand-in).
    void tangentsOwnCholeskyTriedAgainWellBelowWhereItFailed()
    {
        const Case c = boxCase();
        for (unsigned seed : {1u, 2u, 3u})
        {
            QuadraticFem model = boxModel(c);
            std::mt19937 random(seed);
            BlockSparseMatrix compressed = model.makeMatrix(), compressedDefinite = model.makeMatrix();
            deform(model, c, random, kCompression, 1.0 / std::sqrt(kCompression)); // volume kept
            model.assembleTangent(compressed, true);
            model.assembleDefiniteTangent(compressedDefinite, true);
            Eigen::VectorXd compressedForce = Eigen::VectorXd::Zero(model.positions().size());
            addPressureForces(c.loaded, model.positions(), 5e4, compressedForce);

            std::uniform_real_distribution<double> stretchOf(1.005, 1.02);
            const double along = stretchOf(random);
            stretchKeepingVolume(model, c, along);
            auto [stretched, stretchedDefinite, force] = loadedState(model, c, 5e2);

            StaticSolveSettings settings;
            settings.linear = LinearSolver::CholeskyGmres;
            TangentSolver solver(compressed, c.held, settings);
            int failedCalls = 0, aboveCalls = 0, belowCalls = 0;
            Eigen::VectorXd x, y, z;
            const TangentSolveResult failed =
                solver.solve(compressed, compressedForce, x, true, standInOf(compressedDefinite, &failedCalls), 0.5);
            const TangentSolveResult above =
                solver.solve(stretched, force, y, true, standInOf(stretchedDefinite, &aboveCalls), 0.3);
            const TangentSolveResult below =
                solver.solve(stretched, force, z, true, standInOf(stretchedDefinite, &belowCalls), 0.1);
            qInfo("seed %u: after the failure at 0.5, the stand-in at 0.3 %d iterations, the tangent's own at 0.1 %d",
                  seed, above.iterations, below.iterations);
            QVERIFY(failed.converged && above.converged && below.converged);
            QVERIFY(above.factorised && below.factorised);
            QCOMPARE(failedCalls, 1); // the tangent's own failed, then the stand-in
            QCOMPARE(aboveCalls, 1);  // not tried again at 0.3 > 0.25 x 0.5
            QCOMPARE(belowCalls, 0);  // tried again at 0.1, and it factorised
            QVERIFY(below.iterations < above.iterations);
            QVERIFY(residualOf(stretched, z, force, c.held) <= 2e-8);
        }
    }

    void definiteTangentWhereTheCompressedTangentIsNot()
    {
        const Case c = boxCase();
        for (unsigned seed : {1u, 2u, 3u})
        {
            QuadraticFem model = boxModel(c);
            BlockSparseMatrix tangent = model.makeMatrix(), definite = model.makeMatrix();
            model.updateElements();
            model.assembleTangent(tangent, true);
            model.assembleDefiniteTangent(definite, true);
            double difference = 0.0, largest = 0.0;
            for (std::size_t s = 0; s < tangent.blockCount(); ++s)
            {
                difference = std::max(difference, (tangent.block(std::uint32_t(s)) - definite.block(std::uint32_t(s))).norm());
                largest = std::max(largest, tangent.block(std::uint32_t(s)).norm());
            }
            qInfo("seed %u: at rest the stand-in differs from the tangent by %.1e of its largest block", seed,
                  difference / largest);
            QVERIFY(difference <= 1e-12 * largest); // rounding: the rest state's material tangent is definite
            std::mt19937 random(seed);
            deform(model, c, random, kCompression, 1.0 / std::sqrt(kCompression)); // volume kept
            model.assembleTangent(tangent, true);
            model.assembleDefiniteTangent(definite, true);
            SparseDirect cholesky(tangent, c.held, SparseDirect::Kind::SymmetricCholesky);
            QVERIFY(!cholesky.factorize(tangent));
            QVERIFY(cholesky.factorize(definite));
            Eigen::VectorXd force = Eigen::VectorXd::Zero(model.positions().size());
            addPressureForces(c.loaded, model.positions(), 5e4, force);
            StaticSolveSettings settings;
            settings.linear = LinearSolver::CholeskyGmres;
            TangentSolver solver(tangent, c.held, settings);
            Eigen::VectorXd x;
            const TangentSolveResult solved = solver.solve(tangent, force, x, true, standInOf(definite), 2.0);
            qInfo("seed %u: compressed to %.2f, GMRES with the definite stand-in: %d iterations, residual %.1e", seed,
                  kCompression, solved.iterations, solved.relativeResidual);
            QVERIFY(solved.converged && solved.factorised);
            QVERIFY(solved.iterations > 1 && solved.iterations <= settings.gmresMaxIterations); // not the LU
            QVERIFY(residualOf(tangent, x, force, c.held) <= 2e-8);
        }
    }

    /// A stand-in that failed to precondition GMRES in this solve is not factorised again while the force
    /// residual is over tangentCholeskyBelow: the next update goes straight to the LU (on the demo AAA wall each
    /// failed attempt cost 200 iterations, about 20 s). Under it, the stand-in is tried again. The stand-in here is
    /// the tangent at rest, far from the sheared box's, with a budget of 5 iterations.
    void failedStandInIsNotFactorisedAgainFarFromEquilibrium()
    {
        const Case c = boxCase();
        for (unsigned seed : {1u, 2u, 3u})
        {
            QuadraticFem model = boxModel(c);
            BlockSparseMatrix atRest = model.makeMatrix();
            model.updateElements();
            model.assembleDefiniteTangent(atRest, true);
            Eigen::VectorXd force;
            const BlockSparseMatrix tangent = deformedTangent(c, seed, 1.08, force);
            StaticSolveSettings settings;
            settings.linear = LinearSolver::CholeskyGmres;
            settings.gmresMaxIterations = 5;
            TangentSolver solver(tangent, c.held, settings);
            int calls = 0;
            const TangentSolver::StandIn standIn = standInOf(atRest, &calls);
            Eigen::VectorXd x;
            const TangentSolveResult first = solver.solve(tangent, force, x, true, standIn, 2.0);
            const TangentSolveResult second = solver.solve(tangent, force, x, true, standIn, 1.5);
            const int callsFar = calls;
            const TangentSolveResult near = solver.solve(tangent, force, x, true, standIn, 0.5);
            qInfo("seed %u: stand-in at rest: %d iterations (then the LU), next update %d, stand-in assembled %d "
                  "times far from equilibrium and %d in all", seed, first.iterations, second.iterations, callsFar, calls);
            QVERIFY(first.converged && second.converged && near.converged);
            QCOMPARE(first.iterations, settings.gmresMaxIterations + 1); // the stand-in's 5, then the LU's 1
            QCOMPARE(second.iterations, 1);                              // the LU straight away
            QCOMPARE(callsFar, 1);
            QCOMPARE(calls, 2); // tried again under tangentCholeskyBelow
            QVERIFY(residualOf(tangent, x, force, c.held) <= 2e-8);
        }
    }

    /// solveStatic gives up once a line search's step is under stallStep (StaticSolveSettings): from rest under
    /// 10 kPa the box's first Newton step overshoots (the line search takes 4 % of it), so with stallStep 1 the solve stops after that update,
    /// not converged and marked stalled, its residual recorded; with 0 (never) the same solve converges.
    void stalledSolveGivesUp()
    {
        const Case c = boxCase();
        for (const double stallStep : {1.0, 0.0})
        {
            QuadraticFem model = boxModel(c);
            StaticSolveSettings settings = loadedBoxSettings();
            settings.stallStep = stallStep;
            const StaticSolveReport report = solveLoadedBox(c, model, settings);
            qInfo("stallStep %.0f: %d updates, smallest step %.3f, force residual %.1e, %s", stallStep, report.updates,
                  report.smallestStep, report.forceResidual, report.stalled ? "stalled" : "not stalled");
            if (stallStep > 0.0)
            {
                QVERIFY(report.stalled && !report.converged && !report.abandonedFirstSolve);
                QCOMPARE(report.updates, 1);
                QCOMPARE(report.residualHistory.size(), std::size_t(2));
                QCOMPARE(report.residualHistory.back(), report.forceResidual);
                QVERIFY(report.smallestStep < 1.0);
            }
            else
                QVERIFY(report.converged && !report.stalled && report.forceResidual <= 1e-8);
        }
    }

    void firstSolveOverItsBudgetGivesUp()
    {
        // The first update's GMRES on the stand-in's Cholesky (the box at rest, without the pressure's stiffness)
        // cannot reach 1e-8 in one iteration: the solve gives up there, the model untouched, no LU; with room (or no
        // budget of its own) the same solve converges to the same state.
        const Case c = boxCase();
        Eigen::VectorXd reference;
        for (const int budget : {1, 0, 100})
        {
            QuadraticFem model = boxModel(c);
            const Eigen::VectorXd rest = model.positions();
            StaticSolveSettings settings = loadedBoxSettings();
            settings.firstSolveBudget = budget;
            const StaticSolveReport report = solveLoadedBox(c, model, settings);
            qInfo("firstSolveBudget %d: %d updates, %d factorisations, %d GMRES iterations, force residual %.1e%s", budget,
                  report.updates, report.factorisations, report.cgIterations, report.forceResidual,
                  report.abandonedFirstSolve ? ", abandoned" : "");
            if (budget == 1)
            {
                QVERIFY(report.abandonedFirstSolve && report.stalled && !report.converged);
                QCOMPARE(report.updates, 0);
                QCOMPARE(report.factorisations, 1); // the stand-in's Cholesky only: no LU after it
                QCOMPARE(report.cgIterations, 1);
                QVERIFY(report.linearResiduals.empty()); // not a linear solve's result
                QCOMPARE(report.residualHistory.size(), std::size_t(1)); // the residual at rest, nothing after
                QCOMPARE(report.forceResidual, report.residualHistory.front());
                QVERIFY(model.positions() == rest);
                continue;
            }
            QVERIFY(report.converged && !report.stalled && !report.abandonedFirstSolve);
            QVERIFY(report.forceResidual <= 1e-8);
            QVERIFY(report.linearIterations.front() > 1);
            if (reference.size() == 0)
                reference = model.positions();
            else
                QVERIFY(model.positions() == reference); // the same iteration with or without the budget
        }
    }

    void gmresWithoutPreconditionerOnASmallSystem()
    {
        // Restarts every 3 vectors, no preconditioner: the budget holds and the residual reported is the true one.
        const Case c = boxCase();
        Eigen::VectorXd force;
        const BlockSparseMatrix tangent = deformedTangent(c, 4u, 1.0, force);
        Eigen::VectorXd x;
        const GmresResult none = solveGmres(tangent, force, x, c.held,
                                            [](const Eigen::VectorXd& r, Eigen::VectorXd& z) { z = r; }, 1e-12, 20, 3);
        QVERIFY(!none.converged); // 20 iterations are far from 1e-12 unpreconditioned: the budget is kept
        QCOMPARE(none.iterations, 20);
        const double trueResidual = residualOf(tangent, x, force, c.held);
        QVERIFY(none.relativeResidual < 1.0);
        QVERIFY(std::abs(none.relativeResidual - trueResidual) <= 1e-9 * trueResidual); // the reported one is true
        QVERIFY(heldStayZero(x, c.held));
    }
};

QTEST_GUILESS_MAIN(FemTangentSolver)
#include "tst_fem_tangent_solver.moc"
