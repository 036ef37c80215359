// The wall solver against CalculiX 2.20 (issue 16 item 4): the same mesh, material, fixed ends and lumen pressure
// written as a CalculiX input (CalculixJob.h), `ccx` run, its nodal displacements and element stresses (the mean
// over the element's integration points) read from job.dat, and ours on the same problem. Compared: displacement
// relative L2 difference, the 99th percentile of the element von Mises stress (both <= 2 %, the issue's
// tolerance), and the two solve times.
//
//   bench_fem_calculix <work folder> [wall.vtu | -] [linear | nonlinear | raghavan-vorp] [c3d4 | c3d10] [pressure_mmhg=120]
//
// linear         linear elasticity (E 4.23 MPa, nu 0.23) on the rest shape: ours K u = f, one sparse Cholesky solve
//                (for linear tets the first Newton update from rest, where R = I), stresses D B u; CalculiX *STATIC.
// nonlinear      St. Venant-Kirchhoff (the same E, nu) under the follower pressure by Newton's method (consistent
//                tangent + load stiffness, each linear solve by GMRES with the kept Cholesky / LU preconditioner of
//                TangentSolver.h, line search along the direction) to a force residual of 1e-10; CalculiX NLGEOM with *ELASTIC
//                (St. Venant-Kirchhoff there too) and its follower *DLOAD; Cauchy stresses.
// raghavan-vorp  the clinical wall law (Raghavan & Vorp 2000, nu 0.49: Hyperelastic.h) the same way; CalculiX's
//                *HYPERELASTIC, REDUCED POLYNOMIAL, N=2 with C10 = alpha, C20 = beta, D1 = 2 / kappa. C3D10 only.
// c3d4 / c3d10   linear tets (CorotationalFem) or quadratic ones (QuadraticFem: the wall mesh's tets with edge
//                midpoints; a midpoint is fixed where both its corners are).
//
// Without a wall file: the mesher's wall (1.5 mm, one layer of three tets per prism) around a capped cylinder of
// radius 10 mm and length 100 mm, both ends fixed. Prints one JSON object; exit 1 beyond the tolerances, 0 with
// "SKIP" when ccx is not installed (Debian package calculix-ccx).

#include "CalculixJob.h"
#include "WallFixtures.h"
#include "vsim/core/Error.h"
#include "vsim/mesh/WallMesh.h"
#include "vsim/sim/fem/CorotationalFem.h"
#include "vsim/sim/fem/Hyperelastic.h"
#include "vsim/sim/fem/QuadraticFem.h"
#include "vsim/sim/fem/SparseDirect.h"
#include "vsim/sim/fem/StaticSolver.h"
#include "vsim/sim/fem/SurfaceLoads.h"
#include "vsim/sim/fem/TetElement.h"
#include "vsim/study/MeshFileImport.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace vsim;
using namespace vsim::sim::fem;

namespace {

constexpr double kYoungMpa = 4.23, kPoisson = 0.23;

double vonMises(const Eigen::Matrix<double, 6, 1>& s) // xx yy zz and three shears (any order)
{
    return std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) + (s[2] - s[0]) * (s[2] - s[0])) +
                     3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

double largestNodal(const Eigen::VectorXd& displacement)
{
    double largest = 0.0;
    for (Eigen::Index n = 0; n + 2 < displacement.size(); n += 3)
        largest = std::max(largest, displacement.segment<3>(n).norm());
    return largest;
}

double percentile99(std::vector<double> values)
{
    const std::size_t k = std::size_t(std::ceil(0.99 * double(values.size()))) - 1;
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
}

enum class Law { Linear, StVenantKirchhoff, RaghavanVorp };

struct Problem
{
    Law law = Law::Linear;
    bool quadratic = false;
    TetMesh wall; // mm
    std::vector<std::uint8_t> fixed; // 3 per corner node
    std::vector<std::array<int, 3>> lumen;
    double pressurePa = 0.0;
};

/// Our solution: displacement (m, 3 per node of the element order's mesh), element von Mises (MPa), Newton
/// updates, the worst linear residual.
struct Solution
{
    Eigen::VectorXd displacement;
    std::vector<double> vonMisesMpa;
    int newtonUpdates = 0;
    double linearResidual = 0.0;
};

std::vector<Eigen::Vector3d> inMetres(const std::vector<Eigen::Vector3d>& mm)
{
    std::vector<Eigen::Vector3d> m;
    for (const auto& p : mm)
        m.push_back(1e-3 * p);
    return m;
}

/// Newton's method to 1e-10 under the follower pressure on `faces` (3- or 6-node).
template <typename Model, typename Faces>
StaticSolveReport solveUnderPressure(Model& model, const Faces& faces, double pressurePa, const std::vector<std::uint8_t>& fixed)
{
    StaticSolveSettings settings;
    settings.tolerance = 1e-10;
    settings.maxUpdates = 50;
    settings.linear = LinearSolver::CholeskyGmres; // the clinical analysis's solver (StaticWallRun)
    settings.rotationStiffness = true;
    settings.directionalLineSearch = true;
    const FollowerPressure load = followerPressure(faces, pressurePa);
    const StaticSolveReport report = solveStatic(model, load.forces, fixed, settings, load.stiffness);
    if (!report.converged)
        throw Error("our Newton solve did not converge: force residual " + std::to_string(report.forceResidual));
    return report;
}

/// K u = f on the rest shape by sparse Cholesky; returns the solve's relative residual.
template <typename Faces>
double solveLinear(const BlockSparseMatrix& stiffness, const Faces& faces, const Eigen::VectorXd& rest, double pressurePa,
                   const std::vector<std::uint8_t>& fixed, Eigen::VectorXd& u)
{
    Eigen::VectorXd force = Eigen::VectorXd::Zero(rest.size());
    addPressureForces(faces, rest, pressurePa, force);
    SparseDirect direct(stiffness, fixed, SparseDirect::Kind::SymmetricCholesky);
    if (!direct.factorize(stiffness))
        throw Error("the stiffness could not be factorised");
    return direct.solve(force, u);
}

Solution solveLinearTets(const Problem& problem)
{
    ElasticMaterial material;
    material.youngModulusPa = kYoungMpa * 1e6;
    material.poissonRatio = kPoisson;
    if (problem.law == Law::StVenantKirchhoff)
        material.model = ElasticMaterial::Model::StVenantKirchhoff;
    CorotationalFem model(inMetres(problem.wall.points), problem.wall.tets, material);
    const Eigen::VectorXd rest = model.positions();
    Solution out;
    out.vonMisesMpa.resize(problem.wall.tets.size());
    if (problem.law == Law::Linear)
    {
        model.updateElements();
        BlockSparseMatrix stiffness = model.makeMatrix();
        model.assemble(stiffness, 0.0, 1.0);
        out.linearResidual = solveLinear(stiffness, problem.lumen, rest, problem.pressurePa, problem.fixed, out.displacement);
        const Eigen::Matrix<double, 6, 6> d = material.elasticityMatrix();
        for (std::size_t t = 0; t < problem.wall.tets.size(); ++t)
        {
            Eigen::Matrix<double, 12, 1> ue;
            for (int a = 0; a < 4; ++a)
                ue.segment<3>(3 * a) = out.displacement.segment<3>(3 * problem.wall.tets[t][std::size_t(a)]);
            out.vonMisesMpa[t] = vonMises(d * (strainDisplacement(model.elements()[t].gradients) * ue)) * 1e-6;
        }
        return out;
    }
    const StaticSolveReport report = solveUnderPressure(model, problem.lumen, problem.pressurePa, problem.fixed);
    out.newtonUpdates = report.updates, out.linearResidual = report.worstLinearResidual;
    out.displacement = model.positions() - rest;
    const ElementStresses stresses = model.elementStresses();
    for (std::size_t t = 0; t < out.vonMisesMpa.size(); ++t)
        out.vonMisesMpa[t] = stresses.vonMises[t] * 1e-6;
    return out;
}

HyperelasticMaterial quadraticLaw(Law law)
{
    return law == Law::RaghavanVorp ? HyperelasticMaterial::raghavanVorp2000(0.49)
                                    : HyperelasticMaterial::stVenantKirchhoff(kYoungMpa * 1e6, kPoisson);
}

Solution solveQuadraticTets(const Problem& problem, const QuadraticTetMesh& mesh, const std::vector<std::uint8_t>& fixed)
{
    const HyperelasticMaterial law = quadraticLaw(problem.law);
    QuadraticTetMesh metres = mesh;
    for (Eigen::Vector3d& p : metres.points)
        p *= 1e-3;
    QuadraticFem model(metres, {law});
    const std::vector<std::array<int, 6>> faces = quadraticFaces(mesh, problem.lumen);
    const Eigen::VectorXd rest = model.positions();
    Solution out;
    out.vonMisesMpa.resize(mesh.elements.size());
    if (problem.law == Law::Linear)
    {
        model.updateElements();
        BlockSparseMatrix stiffness = model.makeMatrix();
        model.assembleTangent(stiffness, true); // at rest: the linear elastic stiffness
        out.linearResidual = solveLinear(stiffness, faces, rest, problem.pressurePa, fixed, out.displacement);
        // Linear stress D eps per quadrature point, averaged over the element's four.
        Matrix6d d;
        law.stress(Eigen::Matrix3d::Identity(), &d);
        for (std::size_t e = 0; e < mesh.elements.size(); ++e)
        {
            const auto& element = mesh.elements[e];
            Eigen::Matrix3d edges;
            for (int c = 1; c < 4; ++c)
                edges.col(c - 1) = rest.segment<3>(3 * element[std::size_t(c)]) - rest.segment<3>(3 * element[0]);
            Eigen::Matrix<double, 4, 3> g;
            g.bottomRows<3>() = edges.inverse();
            g.row(0) = -g.bottomRows<3>().colwise().sum();
            Eigen::Matrix3d mean = Eigen::Matrix3d::Zero();
            for (const Eigen::Vector4d& l : tetQuadraturePoints())
            {
                const Eigen::Matrix<double, 10, 3> grads = quadraticShapeGradients(g, l);
                Eigen::Matrix3d gradU = Eigen::Matrix3d::Zero();
                for (int a = 0; a < 10; ++a)
                    gradU += out.displacement.segment<3>(3 * element[std::size_t(a)]) * grads.row(a);
                const Eigen::Matrix3d strain = 0.5 * (gradU + gradU.transpose());
                Vector6d engineering = toVoigt(strain);
                engineering.tail<3>() *= 2.0;
                mean += 0.25 * fromVoigt(d * engineering);
            }
            out.vonMisesMpa[e] = vonMisesOf(mean) * 1e-6;
        }
        return out;
    }
    const StaticSolveReport report = solveUnderPressure(model, faces, problem.pressurePa, fixed);
    out.newtonUpdates = report.updates, out.linearResidual = report.worstLinearResidual;
    out.displacement = model.positions() - rest;
    const ElementStresses stresses = model.elementStresses();
    for (std::size_t e = 0; e < out.vonMisesMpa.size(); ++e)
        out.vonMisesMpa[e] = stresses.vonMises[e] * 1e-6;
    return out;
}

Problem defaultProblem(double pressurePa)
{
    const double radius = 10.0, length = 100.0;
    const std::vector<mesh::VesselEnd> ends{{Eigen::Vector3d(0, 0, 0), -Eigen::Vector3d::UnitZ(), radius},
                                            {Eigen::Vector3d(0, 0, length), Eigen::Vector3d::UnitZ(), radius}};
    Problem problem;
    problem.wall = mesh::buildWallMesh(test::cappedCylinder(radius, length, 64), ends, 1.5).mesh;
    problem.pressurePa = pressurePa;
    return problem;
}

} // namespace

int main(int argc, char** argv)
{
    const char* usage = "usage: bench_fem_calculix <work folder> [wall.vtu | -] [linear | nonlinear | raghavan-vorp] "
                        "[c3d4 | c3d10] [pressure_mmhg=120]\n";
    if (argc < 2)
    {
        std::fprintf(stderr, "%s", usage);
        return 2;
    }
    const fs::path work = argv[1];
    const std::string lawName = argc > 3 ? argv[3] : "linear", elementName = argc > 4 ? argv[4] : "c3d4";
    const std::map<std::string, Law> laws{{"linear", Law::Linear}, {"nonlinear", Law::StVenantKirchhoff},
                                          {"raghavan-vorp", Law::RaghavanVorp}};
    if (!laws.count(lawName) || (elementName != "c3d4" && elementName != "c3d10") ||
        (lawName == "raghavan-vorp" && elementName == "c3d4"))
    {
        std::fprintf(stderr, "bench_fem_calculix: '%s %s' is not a run (raghavan-vorp needs c3d10)\n%s", lawName.c_str(),
                     elementName.c_str(), usage);
        return 2;
    }
    const double pressurePa = (argc > 5 ? std::atof(argv[5]) : 120.0) * 133.322387415;
    if (std::system("command -v ccx > /dev/null 2>&1") != 0)
    {
        std::printf("{\"bench\": \"fem_calculix\", \"skipped\": \"SKIP: ccx not found (Debian package calculix-ccx)\"}\n");
        return 0;
    }
    try
    {
        Problem problem = defaultProblem(pressurePa);
        problem.law = laws.at(lawName);
        problem.quadratic = elementName == "c3d10";
        std::string source = "mesher wall around a capped cylinder r 10 mm, 100 mm";
        if (argc > 2 && std::string(argv[2]) != "-")
        {
            problem.wall = study::readTetMeshFile(argv[2]);
            source = argv[2];
        }
        const auto& endSet = problem.wall.pointFields.at("end_set");
        problem.fixed.assign(3 * problem.wall.points.size(), 0);
        for (std::size_t n = 0; n < endSet.size(); ++n)
            if (endSet[n] > 0.0)
                problem.fixed[3 * n] = problem.fixed[3 * n + 1] = problem.fixed[3 * n + 2] = 1;
        problem.lumen = mesh::lumenFaces(problem.wall);

        // The job, both sides on the same nodes (quadratic: the corners, then the edge midpoints).
        bench::CalculixJob job;
        QuadraticTetMesh quadratic;
        std::vector<std::uint8_t> fixed = problem.fixed;
        if (problem.quadratic)
        {
            quadratic = quadraticFromLinear(problem.wall.points, problem.wall.tets);
            fixed = quadraticConstraints(quadratic, problem.fixed);
            job.nodesMm = quadratic.points;
            for (const auto& element : quadratic.elements)
                job.elements.emplace_back(element.begin(), element.end());
        }
        else
        {
            job.nodesMm = problem.wall.points;
            for (const auto& tet : problem.wall.tets)
                job.elements.emplace_back(tet.begin(), tet.end());
        }
        for (std::size_t n = 0; n < job.nodesMm.size(); ++n)
            job.fixedNodes.push_back(fixed[3 * n]);
        std::map<std::set<int>, std::size_t> owner; // each lumen face belongs to one element
        for (std::size_t t = 0; t < problem.wall.tets.size(); ++t)
            for (int skip = 0; skip < 4; ++skip)
            {
                std::set<int> face;
                for (int k = 0; k < 4; ++k)
                    if (k != skip)
                        face.insert(problem.wall.tets[t][std::size_t(k)]);
                owner[face] = t;
            }
        for (const auto& face : problem.lumen)
        {
            const std::size_t t = owner.at(std::set<int>(face.begin(), face.end()));
            job.pressureFaces.push_back({t, bench::calculixFace(problem.wall.tets[t], face)});
        }
        job.pressurePa = pressurePa;
        job.nlgeom = problem.law != Law::Linear;
        if (problem.law == Law::RaghavanVorp)
        {
            const HyperelasticMaterial law = quadraticLaw(problem.law);
            job.material = bench::CalculixJob::Material::ReducedPolynomial;
            job.c10Mpa = law.c10 * 1e-6, job.c20Mpa = law.c20 * 1e-6, job.d1PerMpa = 2.0 / (law.bulkModulus * 1e-6);
        }
        else
            job.youngMpa = kYoungMpa, job.poisson = kPoisson;

        const auto ourStart = std::chrono::steady_clock::now();
        const Solution ours = problem.quadratic ? solveQuadraticTets(problem, quadratic, fixed) : solveLinearTets(problem);
        const double ourSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - ourStart).count();

        fs::create_directories(work);
        bench::writeCalculixInput(job, work / "job.inp");
        const auto ccxStart = std::chrono::steady_clock::now();
        const std::string command = "cd '" + work.string() + "' && OMP_NUM_THREADS=2 ccx -i job > ccx.log 2>&1";
        if (std::system(command.c_str()) != 0)
            throw Error("ccx failed: see " + (work / "ccx.log").string());
        const double ccxSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - ccxStart).count();
        const bench::CalculixResults ccx = bench::readCalculixResults(work / "job.dat", job.nodesMm.size(), job.elements.size());

        const double displacementDifference = (1e3 * ours.displacement - ccx.displacementMm).norm() / ccx.displacementMm.norm();
        const double ourP99 = percentile99(ours.vonMisesMpa), ccxP99 = percentile99(ccx.vonMisesMpa);
        const double p99Difference = std::abs(ourP99 / ccxP99 - 1.0);
        const char* lawText = problem.law == Law::Linear ? "linear elastic, E 4.23 MPa, nu 0.23"
                              : problem.law == Law::StVenantKirchhoff
                                  ? "St. Venant-Kirchhoff, E 4.23 MPa, nu 0.23, follower pressure (CalculiX NLGEOM)"
                                  : "Raghavan-Vorp 2000, nu 0.49, follower pressure (CalculiX NLGEOM, REDUCED POLYNOMIAL N=2)";
        std::printf("{\"bench\": \"fem_calculix\", \"mesh\": \"%s\", \"nodes\": %zu, \"elements\": %zu, \"element\": \"%s\", "
                    "\"material\": \"%s\", \"newton_updates\": %d, \"pressure_kpa\": %.3f, "
                    "\"displacement_relative_l2\": %.3e, \"p99_von_mises_kpa\": {\"vascusim\": %.3f, \"calculix\": %.3f}, "
                    "\"p99_relative_difference\": %.3e, \"max_displacement_mm\": {\"vascusim\": %.5f, \"calculix\": %.5f}, "
                    "\"vascusim_linear_residual\": %.1e, \"seconds\": {\"vascusim\": %.3f, \"calculix\": %.3f}}\n",
                    source.c_str(), job.nodesMm.size(), job.elements.size(),
                    problem.quadratic ? "C3D10 (quadratic tetrahedron)" : "C3D4 (linear tetrahedron)", lawText,
                    ours.newtonUpdates, pressurePa * 1e-3, displacementDifference, ourP99 * 1e3, ccxP99 * 1e3,
                    p99Difference, 1e3 * largestNodal(ours.displacement), largestNodal(ccx.displacementMm),
                    ours.linearResidual, ourSeconds, ccxSeconds);
        return displacementDifference <= 0.02 && p99Difference <= 0.02 ? 0 : 1;
    }
    catch (const std::exception& error)
    {
        std::fprintf(stderr, "bench_fem_calculix: %s\n", error.what());
        return 1;
    }
}
