// The wall solver against CalculiX 2.20 (issue 16 item 4), linear run: the same mesh, material, fixed ends and
// lumen pressure written as a CalculiX input (C3D4, *STATIC without NLGEOM, *DLOAD on the lumen faces), `ccx`
// run, its element stresses and nodal displacements read from job.dat; our side the same linear problem
// (K u = f on the rest shape: the first Newton update from rest, where R = I and the rotations' part of the tangent
// vanishes) by SparseDirect, stresses D B u per element. Compared: displacement relative L2 difference, the 99th
// percentile of the element von Mises stress (both <= 2 %, the tolerance), and the two solve times.
//
//   bench_fem_calculix <work folder> [wall.vtu | -] [linear | nonlinear] [pressure_mmhg=120]
//
// nonlinear: St. Venant-Kirchhoff (our material_model 1) under the follower pressure by Newton's method, against
// CalculiX's NLGEOM with *ELASTIC (St. Venant-Kirchhoff there too) and its follower *DLOAD; Cauchy stresses.
//
// Without a wall file: the mesher's wall (1.5 mm, one layer of three tets per prism) around a capped cylinder of
// radius 10 mm and length 100 mm, both ends fixed. Prints one JSON object; exit 1 beyond the tolerances, 0 with
// "SKIP" when ccx is not installed (Debian package calculix-ccx).

#include "WallFixtures.h"
#include "vsim/core/Error.h"
#include "vsim/mesh/WallMesh.h"
#include "vsim/sim/fem/CorotationalFem.h"
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

/// CalculiX's C3D4 face numbers: S1 = 1-2-3, S2 = 1-4-2, S3 = 2-4-3, S4 = 3-4-1 (local corners 0..3).
int c3d4Face(const std::array<int, 4>& tet, const std::array<int, 3>& face)
{
    static const int corners[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
    const std::set<int> wanted(face.begin(), face.end());
    for (int f = 0; f < 4; ++f)
        if (std::set<int>{tet[std::size_t(corners[f][0])], tet[std::size_t(corners[f][1])], tet[std::size_t(corners[f][2])]} == wanted)
            return f + 1;
    return 0;
}

struct Problem
{
    bool nonlinear = false; // St. Venant-Kirchhoff with a follower pressure (CalculiX: NLGEOM), else linear
    TetMesh wall; // mm
    std::vector<std::uint8_t> fixed;
    std::vector<std::array<int, 3>> lumen;
    double pressurePa = 0.0;
};

void writeCalculixInput(const Problem& problem, bool nonlinear, const fs::path& file)
{
    std::ofstream out(file);
    out.precision(12);
    out << "** VascuSim bench_fem_calculix: mm, N, MPa\n*NODE, NSET=NALL\n";
    for (std::size_t n = 0; n < problem.wall.points.size(); ++n)
        out << n + 1 << ", " << problem.wall.points[n].x() << ", " << problem.wall.points[n].y() << ", "
            << problem.wall.points[n].z() << "\n";
    out << "*ELEMENT, TYPE=C3D4, ELSET=EALL\n";
    for (std::size_t t = 0; t < problem.wall.tets.size(); ++t)
    {
        const auto& tet = problem.wall.tets[t];
        out << t + 1 << ", " << tet[0] + 1 << ", " << tet[1] + 1 << ", " << tet[2] + 1 << ", " << tet[3] + 1 << "\n";
    }
    out << "*NSET, NSET=FIXED\n";
    for (std::size_t n = 0; n < problem.wall.points.size(); ++n)
        if (problem.fixed[3 * n])
            out << n + 1 << ",\n";
    out << "*BOUNDARY\nFIXED, 1, 3\n*MATERIAL, NAME=WALL\n*ELASTIC\n" << kYoungMpa << ", " << kPoisson
        << "\n*SOLID SECTION, ELSET=EALL, MATERIAL=WALL\n"
        << (nonlinear ? "*STEP, NLGEOM, INC=200\n*STATIC\n0.25, 1.\n"
                        // Residual (R_n) and correction (C_n) criteria tightened from 0.5 % and 1 % (defaults) to 1e-7.
                        "*CONTROLS, PARAMETERS=FIELD\n1.e-7, 1.e-7\n"
                      : "*STEP\n*STATIC\n")
        << "*DLOAD\n";
    // Each lumen face belongs to one element: find it through the faces' node sets.
    std::map<std::set<int>, std::size_t> owner;
    for (std::size_t t = 0; t < problem.wall.tets.size(); ++t)
    {
        const auto& tet = problem.wall.tets[t];
        for (int skip = 0; skip < 4; ++skip)
        {
            std::set<int> face;
            for (int k = 0; k < 4; ++k)
                if (k != skip)
                    face.insert(tet[std::size_t(k)]);
            owner[face] = t;
        }
    }
    for (const auto& face : problem.lumen)
    {
        const std::size_t t = owner.at(std::set<int>(face.begin(), face.end()));
        out << t + 1 << ", P" << c3d4Face(problem.wall.tets[t], face) << ", " << problem.pressurePa * 1e-6 << "\n";
    }
    out << "*NODE PRINT, NSET=NALL\nU\n*EL PRINT, ELSET=EALL\nS\n*END STEP\n";
}

/// job.dat: "displacements (vx,vy,vz) for set NALL ..." then "node ux uy uz" lines; "stresses (elem, integ.pnt.,
/// sxx,syy,szz,sxy,sxz,syz) ..." then "element point six values" lines.
void readCalculixResults(const fs::path& file, std::size_t nodes, std::size_t elements, Eigen::VectorXd& displacementMm,
                         std::vector<double>& vonMisesMpa)
{
    std::ifstream in(file);
    if (!in)
        throw Error("CalculiX wrote no " + file.string());
    displacementMm = Eigen::VectorXd::Zero(Eigen::Index(3 * nodes));
    vonMisesMpa.assign(elements, 0.0);
    std::string line, block;
    std::size_t displacements = 0, stresses = 0;
    while (std::getline(in, line))
    {
        // NLGEOM prints every increment: each header starts the block again, the last one is the result.
        if (line.find("displacements") != std::string::npos)
            block = "u", displacements = 0;
        else if (line.find("stresses") != std::string::npos)
            block = "s", stresses = 0;
        std::istringstream fields(line);
        if (block == "u")
        {
            long node;
            double ux, uy, uz;
            if (fields >> node >> ux >> uy >> uz && node >= 1 && std::size_t(node) <= nodes)
                displacementMm.segment<3>(Eigen::Index(3 * (node - 1))) = Eigen::Vector3d(ux, uy, uz), ++displacements;
        }
        else if (block == "s")
        {
            long element, point;
            Eigen::Matrix<double, 6, 1> s;
            if (fields >> element >> point >> s[0] >> s[1] >> s[2] >> s[3] >> s[4] >> s[5] && element >= 1 &&
                std::size_t(element) <= elements)
                vonMisesMpa[std::size_t(element - 1)] = vonMises(s), ++stresses;
        }
    }
    if (displacements != nodes || stresses != elements)
        throw Error("CalculiX's results are incomplete: " + std::to_string(displacements) + " of " +
                    std::to_string(nodes) + " displacements, " + std::to_string(stresses) + " of " +
                    std::to_string(elements) + " element stresses");
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
    if (argc < 2)
    {
        std::fprintf(stderr, "usage: bench_fem_calculix <work folder> [wall.vtu | -] [linear | nonlinear] [pressure_mmhg=120]\n");
        return 2;
    }
    const fs::path work = argv[1];
    const bool nonlinear = argc > 3 && std::string(argv[3]) == "nonlinear";
    if (argc > 3 && !nonlinear && std::string(argv[3]) != "linear")
    {
        std::fprintf(stderr, "bench_fem_calculix: the third argument is linear or nonlinear, not '%s'\n", argv[3]);
        return 2;
    }
    const double pressurePa = (argc > 4 ? std::atof(argv[4]) : 120.0) * 133.322387415;
    if (std::system("command -v ccx > /dev/null 2>&1") != 0)
    {
        std::printf("{\"bench\": \"fem_calculix\", \"skipped\": \"SKIP: ccx not found (Debian package calculix-ccx)\"}\n");
        return 0;
    }
    try
    {
        Problem problem = defaultProblem(pressurePa);
        problem.nonlinear = nonlinear;
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

        // Ours (SI inside). Linear: K u = f on the rest shape, one sparse LDL^T solve, stresses D B u. Nonlinear:
        // the St. Venant-Kirchhoff model under the follower pressure by Newton's method (consistent tangent + load
        // stiffness, sparse LU) to a force residual of 1e-10, Cauchy stresses.
        const auto ourStart = std::chrono::steady_clock::now();
        std::vector<Eigen::Vector3d> rest;
        for (const auto& p : problem.wall.points)
            rest.push_back(1e-3 * p);
        ElasticMaterial material;
        material.youngModulusPa = kYoungMpa * 1e6;
        material.poissonRatio = kPoisson;
        if (problem.nonlinear)
            material.model = ElasticMaterial::Model::StVenantKirchhoff;
        CorotationalFem model(rest, problem.wall.tets, material);
        Eigen::VectorXd u;
        double linearResidual = 0.0;
        int newtonUpdates = 0;
        std::vector<double> ourVonMises(problem.wall.tets.size());
        if (problem.nonlinear)
        {
            const ExternalForces pressure = [&](const Eigen::VectorXd& x) {
                Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
                addPressureForces(problem.lumen, x, problem.pressurePa, f);
                return f;
            };
            const ExternalStiffness pressureStiffness = [&](const Eigen::VectorXd& x, BlockSparseMatrix& tangent) {
                subtractPressureStiffness(problem.lumen, x, problem.pressurePa, tangent);
            };
            StaticSolveSettings settings;
            settings.tolerance = 1e-10;
            settings.maxUpdates = 50;
            settings.linear = LinearSolver::SparseLu;
            const StaticSolveReport report = solveStatic(model, pressure, problem.fixed, settings, pressureStiffness);
            if (!report.converged)
                throw Error("our Newton solve did not converge: force residual " + std::to_string(report.forceResidual));
            linearResidual = report.worstLinearResidual;
            newtonUpdates = report.updates;
            Eigen::VectorXd x0(model.positions().size());
            for (std::size_t n = 0; n < rest.size(); ++n)
                x0.segment<3>(Eigen::Index(3 * n)) = rest[n];
            u = model.positions() - x0;
            const ElementStresses stresses = model.elementStresses();
            for (std::size_t t = 0; t < ourVonMises.size(); ++t)
                ourVonMises[t] = stresses.vonMises[t] * 1e-6; // MPa
        }
        else
        {
            model.updateElements();
            BlockSparseMatrix stiffness = model.makeMatrix();
            model.assemble(stiffness, 0.0, 1.0);
            Eigen::VectorXd force = Eigen::VectorXd::Zero(model.positions().size());
            addPressureForces(problem.lumen, model.positions(), problem.pressurePa, force);
            SparseDirect direct(stiffness, problem.fixed, SparseDirect::Kind::SymmetricLdlt);
            if (!direct.factorize(stiffness))
                throw Error("the stiffness could not be factorised");
            linearResidual = direct.solve(force, u);
            const Eigen::Matrix<double, 6, 6> d = material.elasticityMatrix();
            for (std::size_t t = 0; t < problem.wall.tets.size(); ++t)
            {
                Eigen::Matrix<double, 12, 1> ue;
                for (int a = 0; a < 4; ++a)
                    ue.segment<3>(3 * a) = u.segment<3>(3 * problem.wall.tets[t][std::size_t(a)]);
                const Eigen::Matrix<double, 6, 1> stress = d * (strainDisplacement(model.elements()[t].gradients) * ue);
                ourVonMises[t] = vonMises(stress) * 1e-6; // MPa
            }
        }
        const double ourSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - ourStart).count();

        // CalculiX on the same problem.
        fs::create_directories(work);
        writeCalculixInput(problem, problem.nonlinear, work / "job.inp");
        const auto ccxStart = std::chrono::steady_clock::now();
        const std::string command = "cd '" + work.string() + "' && OMP_NUM_THREADS=2 ccx -i job > ccx.log 2>&1";
        if (std::system(command.c_str()) != 0)
            throw Error("ccx failed: see " + (work / "ccx.log").string());
        const double ccxSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - ccxStart).count();
        Eigen::VectorXd ccxDisplacement;
        std::vector<double> ccxVonMises;
        readCalculixResults(work / "job.dat", problem.wall.points.size(), problem.wall.tets.size(), ccxDisplacement,
                            ccxVonMises);

        const double displacementDifference = (1e3 * u - ccxDisplacement).norm() / ccxDisplacement.norm();
        const double ourP99 = percentile99(ourVonMises), ccxP99 = percentile99(ccxVonMises);
        const double p99Difference = std::abs(ourP99 / ccxP99 - 1.0);
        std::printf("{\"bench\": \"fem_calculix\", \"mesh\": \"%s\", \"nodes\": %zu, \"tets\": %zu, \"element\": \"C3D4 "
                    "(linear tetrahedron), %s, E %.2f MPa, nu %.2f\", \"newton_updates\": %d, \"pressure_kpa\": %.3f, "
                    "\"displacement_relative_l2\": %.3e, \"p99_von_mises_kpa\": {\"vascusim\": %.3f, \"calculix\": %.3f}, "
                    "\"p99_relative_difference\": %.3e, \"max_displacement_mm\": {\"vascusim\": %.5f, \"calculix\": %.5f}, "
                    "\"vascusim_linear_residual\": %.1e, \"seconds\": {\"vascusim\": %.3f, \"calculix\": %.3f}}\n",
                    source.c_str(), problem.wall.points.size(), problem.wall.tets.size(),
                    nonlinear ? "St. Venant-Kirchhoff, follower pressure (CalculiX NLGEOM)" : "linear elastic", kYoungMpa,
                    kPoisson, newtonUpdates,
                    problem.pressurePa * 1e-3, displacementDifference, ourP99 * 1e3, ccxP99 * 1e3, p99Difference,
                    1e3 * largestNodal(u), largestNodal(ccxDisplacement), linearResidual, ourSeconds,
                    ccxSeconds);
        return displacementDifference <= 0.02 && p99Difference <= 0.02 ? 0 : 1;
    }
    catch (const std::exception& error)
    {
        std::fprintf(stderr, "bench_fem_calculix: %s\n", error.what());
        return 1;
    }
}
