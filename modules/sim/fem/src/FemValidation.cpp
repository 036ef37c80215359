#include "vsim/sim/fem/FemValidation.h"

#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/sim/fem/BackwardEuler.h"
#include "vsim/sim/fem/CorotationalFem.h"
#include "vsim/sim/fem/QuadraticFem.h"
#include "vsim/sim/fem/StaticSolver.h"
#include "vsim/sim/fem/StructuredMeshes.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/TetMesh.h"
#include "vsim/sim/fem/SurfaceLoads.h"

#include <Eigen/Geometry>

#include <chrono>
#include <cmath>
#include <functional>
#include <map>

namespace vsim::sim::fem {
namespace {

using Constraints = std::vector<std::uint8_t>;

ElasticMaterial material(double young, double poisson)
{
    ElasticMaterial m;
    m.youngModulusPa = young;
    m.poissonRatio = poisson;
    m.densityKgPerM3 = 1100.0;
    return m;
}

ValidationResult patchTest(const Progress&)
{
    ValidationResult result;
    result.description = storedText("constant-strain patch: boundary nodes of a 4x4x4-cell cube (384 tets) moved by "
                                    "u = A X + c, interior solved; interior displacement and element stress against "
                                    "the exact linear field");
    const StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(1.0, 1.0, 1.0), {4, 4, 4});
    CorotationalFem model(mesh.points, mesh.tets, material(1e6, 0.3));
    Eigen::Matrix3d a;
    a << 1e-3, 2e-4, -1e-4, 2e-4, -5e-4, 3e-4, -1e-4, 3e-4, 8e-4; // symmetric: a pure strain, no rotation
    const Eigen::Vector3d c(1e-4, -2e-4, 3e-4);
    Constraints constrained(3 * model.nodeCount(), 0);
    for (int k = 0; k <= 4; ++k)
        for (int j = 0; j <= 4; ++j)
            for (int i = 0; i <= 4; ++i)
                if (i == 0 || j == 0 || k == 0 || i == 4 || j == 4 || k == 4)
                {
                    const int node = mesh.node(i, j, k);
                    model.positions().segment<3>(3 * node) += a * mesh.points[std::size_t(node)] + c;
                    for (int d = 0; d < 3; ++d)
                        constrained[std::size_t(3 * node + d)] = 1;
                }
    solveStatic(model, {}, constrained, 1e-13);
    double worst = 0.0, scale = 0.0;
    for (std::size_t n = 0; n < model.nodeCount(); ++n)
    {
        const Eigen::Vector3d exact = a * mesh.points[n] + c;
        scale = std::max(scale, exact.norm());
        worst = std::max(worst, (model.positions().segment<3>(Eigen::Index(3 * n)) - mesh.points[n] - exact).norm());
    }
    result.figures.push_back({"interior displacement error / largest displacement", worst / scale, 0.0, 1e-8, ""});
    Eigen::Matrix<double, 6, 1> strain;
    strain << a(0, 0), a(1, 1), a(2, 2), 2 * a(0, 1), 2 * a(1, 2), 2 * a(2, 0);
    const Eigen::Matrix<double, 6, 1> stress = model.material().elasticityMatrix() * strain;
    Eigen::Matrix3d exactStress;
    exactStress << stress[0], stress[3], stress[5], stress[3], stress[1], stress[4], stress[5], stress[4], stress[2];
    double stressError = 0.0;
    for (const Eigen::Matrix3d& tensor : model.elementStresses().tensors)
        stressError = std::max(stressError, (tensor - exactStress).norm() / exactStress.norm());
    result.figures.push_back({"element stress error (relative, largest)", stressError, 0.0, 1e-8, ""});
    return result;
}

ValidationResult rotationTest(const Progress&)
{
    ValidationResult result;
    result.description = storedText("a 0.1 x 0.05 x 0.05 m block (96 tets, E = 1 MPa) turned 90 degrees about z and "
                                    "moved: largest elastic force against E h^2 (h = element size)");
    const StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(0.1, 0.05, 0.05), {4, 2, 2});
    CorotationalFem model(mesh.points, mesh.tets, material(1e6, 0.3));
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (std::size_t n = 0; n < model.nodeCount(); ++n)
        model.positions().segment<3>(Eigen::Index(3 * n)) = turn * mesh.points[n] + Eigen::Vector3d(0.3, -0.2, 0.1);
    model.updateElements();
    const double forceScale = model.material().youngModulusPa * 0.025 * 0.025;
    double largest = 0.0;
    const Eigen::VectorXd forces = model.elasticForces();
    for (Eigen::Index i = 0; i < forces.size(); i += 3)
        largest = std::max(largest, forces.segment<3>(i).norm());
    result.figures.push_back({"largest elastic force / (E h^2)", largest / forceScale, 0.0, 1e-9, ""});
    return result;
}

/// Adds `total` (N) spread over the nodes of the face x = length of a box mesh by tributary area.
void addTipLoad(const StructuredTetMesh& mesh, const Eigen::Vector3d& total, Eigen::VectorXd& forces)
{
    const int i = mesh.cells[0], ny = mesh.cells[1], nz = mesh.cells[2];
    double weights = 0.0;
    std::vector<std::pair<int, double>> shares;
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
        {
            const double w = (j == 0 || j == ny ? 0.5 : 1.0) * (k == 0 || k == nz ? 0.5 : 1.0);
            shares.push_back({mesh.node(i, j, k), w});
            weights += w;
        }
    for (const auto& [node, w] : shares)
        forces.segment<3>(3 * node) += total * (w / weights);
}

Constraints clampedAtXZero(const StructuredTetMesh& mesh)
{
    Constraints constrained(3 * mesh.points.size(), 0);
    for (int k = 0; k <= mesh.cells[2]; ++k)
        for (int j = 0; j <= mesh.cells[1]; ++j)
            for (int d = 0; d < 3; ++d)
                constrained[std::size_t(3 * mesh.node(0, j, k) + d)] = 1;
    return constrained;
}

ValidationResult cantileverTest(const Progress&)
{
    ValidationResult result;
    const double length = 0.5, side = 0.1, young = 1e6, poisson = 0.0;
    const StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(length, side, side), {70, 14, 14});
    // nu = 0: beam theory ignores the Poisson contraction that a clamped 3D root prevents. Linear tets are stiff
    // in bending: 14 cells across the section keep the error near 2 % (6 cells: 11 %).
    result.description = storedText(Pattern{"clamped 0.5 x 0.1 x 0.1 m beam (70 x 14 x 14 cells, %1 tets, E = 1 MPa, "
                                            "nu = 0) with a tip load: mean tip deflection against Timoshenko theory "
                                            "P L^3 / (3 E I) + P L / (k G A), k = 10 (1 + nu) / (12 + 11 nu)",
                                            {std::to_string(mesh.tets.size())}});
    CorotationalFem model(mesh.points, mesh.tets, material(young, poisson));
    const double inertia = side * side * side * side / 12.0, area = side * side;
    const double shearModulus = young / (2.0 * (1.0 + poisson)), shearFactor = 10.0 * (1.0 + poisson) / (12.0 + 11.0 * poisson);
    const double load = 1e-3 * 3.0 * young * inertia / (length * length * length); // a deflection of about L / 1000
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(Eigen::Index(3 * model.nodeCount()));
    addTipLoad(mesh, Eigen::Vector3d(0.0, 0.0, -load), forces);
    solveStatic(model, forces, clampedAtXZero(mesh), 1e-8);
    double deflection = 0.0;
    int count = 0;
    for (int k = 0; k <= mesh.cells[2]; ++k)
        for (int j = 0; j <= mesh.cells[1]; ++j, ++count)
        {
            const int node = mesh.node(mesh.cells[0], j, k);
            deflection += mesh.points[std::size_t(node)].z() - model.positions()[3 * node + 2];
        }
    deflection /= count;
    const double theory = load * length * length * length / (3.0 * young * inertia) +
                          load * length / (shearFactor * shearModulus * area);
    result.figures.push_back({"tip deflection", deflection * 1e3, theory * 1e3, 0.03 * theory * 1e3, "mm"});
    return result;
}

ValidationResult lameTest(const Progress&)
{
    ValidationResult result;
    const double a = 0.01, b = 0.02, pressure = 1e3, young = 1e6, poisson = 0.45;
    const StructuredTetMesh mesh = annulusSectorTetMesh(a, b, 0.5 * M_PI, 0.001, {16, 48, 1});
    result.description = storedText(Pattern{"quarter of a thick-walled tube (a = 10 mm, b = 20 mm, %1 tets, E = 1 MPa, "
                                            "nu = 0.45) under 1 kPa inside, plane strain and symmetry planes: radial "
                                            "displacement and hoop stress against Lame's solution",
                                            {std::to_string(mesh.tets.size())}});
    CorotationalFem model(mesh.points, mesh.tets, material(young, poisson));
    Constraints constrained(3 * model.nodeCount(), 0);
    for (int k = 0; k <= mesh.cells[2]; ++k)
        for (int j = 0; j <= mesh.cells[1]; ++j)
            for (int i = 0; i <= mesh.cells[0]; ++i)
            {
                const int node = mesh.node(i, j, k);
                constrained[std::size_t(3 * node + 2)] = 1; // plane strain
                if (j == 0)
                    constrained[std::size_t(3 * node + 1)] = 1; // y = 0 plane: u_y = 0
                if (j == mesh.cells[1])
                    constrained[std::size_t(3 * node)] = 1; // x = 0 plane: u_x = 0
            }
    std::vector<std::array<int, 3>> inner;
    for (const auto& face : boundaryFaces(mesh.tets))
    {
        bool onInner = true;
        for (int node : face)
            onInner = onInner && std::abs(mesh.points[std::size_t(node)].head<2>().norm() - a) < 1e-9;
        if (onInner)
            inner.push_back(face);
    }
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(Eigen::Index(3 * model.nodeCount()));
    addPressureForces(inner, model.positions(), pressure, forces);
    solveStatic(model, forces, constrained, 1e-10);

    const double k = pressure * a * a / (b * b - a * a);
    auto radialTheory = [&](double r) { return (1.0 + poisson) * k / young * ((1.0 - 2.0 * poisson) * r + b * b / r); };
    for (int i : {0, mesh.cells[0]})
    {
        double sum = 0.0;
        int count = 0;
        for (int j = 0; j <= mesh.cells[1]; ++j, ++count)
        {
            const int node = mesh.node(i, j, 0);
            const Eigen::Vector2d rest = mesh.points[std::size_t(node)].head<2>();
            sum += (model.positions().segment<2>(3 * node) - rest).dot(rest.normalized());
        }
        const double r = i == 0 ? a : b, theory = radialTheory(r);
        result.figures.push_back({i == 0 ? "radial displacement at r = a" : "radial displacement at r = b",
                                  1e6 * sum / count, 1e6 * theory, 0.02 * 1e6 * theory, "um"});
    }
    // Constant-stress tets near incompressibility scatter about the true stress; the six tets of each structured
    // cell are averaged (volume-weighted) and compared at the cell's centroid.
    const ElementStresses stresses = model.elementStresses();
    double errorSum = 0.0, innerMeasured = 0.0, innerTheory = 0.0;
    int innerCount = 0;
    const std::size_t cellCount = mesh.tets.size() / 6;
    const double ringWidth = (b - a) / mesh.cells[0];
    for (std::size_t cell = 0; cell < cellCount; ++cell)
    {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
        double volume = 0.0;
        for (std::size_t t = 6 * cell; t < 6 * cell + 6; ++t)
        {
            const double v = model.elements()[t].volume;
            for (int node : mesh.tets[t])
                centroid += 0.25 * v * mesh.points[std::size_t(node)];
            tensor += v * stresses.tensors[t];
            volume += v;
        }
        centroid /= volume;
        tensor /= volume;
        const double r = centroid.head<2>().norm();
        const Eigen::Vector3d hoop(-centroid.y() / r, centroid.x() / r, 0.0);
        const double measured = hoop.dot(tensor * hoop), theory = k * (1.0 + b * b / (r * r));
        errorSum += std::abs(measured - theory) / theory;
        if (r < a + ringWidth)
            innerMeasured += measured, innerTheory += theory, ++innerCount;
    }
    result.figures.push_back({"hoop stress, mean relative error over the cells", errorSum / double(cellCount),
                              0.0, 0.05, ""});
    result.figures.push_back({"hoop stress in the innermost ring of cells", innerMeasured / innerCount,
                              innerTheory / innerCount, 0.05 * innerTheory / innerCount, "Pa"});
    return result;
}

ValidationResult lameQuadraticTest(const Progress&)
{
    ValidationResult result;
    const double a = 0.01, b = 0.02, pressure = 1e3, young = 1e6, poisson = 0.49;
    const StructuredTetMesh linear = annulusSectorTetMesh(a, b, 0.5 * M_PI, 0.001, {8, 32, 1});
    QuadraticFem model(quadraticFromLinear(linear.points, linear.tets),
                       {HyperelasticMaterial::stVenantKirchhoff(young, poisson)});
    const QuadraticTetMesh& mesh = model.mesh();
    result.description = storedText(Pattern{
        "quarter of a thick-walled tube (a = 10 mm, b = 20 mm, %1 quadratic tets, E = 1 MPa, nu = 0.49, nearly "
        "incompressible) under 1 kPa inside (follower), plane strain and symmetry planes, Newton to 1e-8: radial "
        "displacement and the elements' hoop stress (mean of the 4 quadrature points, no averaging over cells) against "
        "Lame's solution",
        {std::to_string(mesh.elements.size())}});
    Constraints constrained(3 * model.nodeCount(), 0);
    for (std::size_t n = 0; n < model.nodeCount(); ++n)
    {
        const Eigen::Vector3d& p = mesh.points[n];
        constrained[3 * n + 2] = 1; // plane strain
        if (std::abs(p.y()) < 1e-12)
            constrained[3 * n + 1] = 1;
        if (std::abs(p.x()) < 1e-12)
            constrained[3 * n] = 1;
    }
    std::vector<std::array<int, 3>> inner;
    for (const auto& face : boundaryFaces(linear.tets))
    {
        bool onInner = true;
        for (int node : face)
            onInner = onInner && std::abs(linear.points[std::size_t(node)].head<2>().norm() - a) < 1e-9;
        if (onInner)
            inner.push_back(face);
    }
    const std::vector<std::array<int, 6>> faces = quadraticFaces(mesh, inner);
    StaticSolveSettings settings;
    settings.tolerance = 1e-8; // near incompressibility round-off floors the residual at about 5e-10
    settings.linear = LinearSolver::SparseLu;
    settings.rotationStiffness = true;
    const FollowerPressure load = followerPressure(faces, pressure);
    const StaticSolveReport report = solveStatic(model, load.forces, constrained, settings, load.stiffness);
    result.figures.push_back({"force residual after " + std::to_string(report.updates) + " Newton updates",
                              report.forceResidual, 0.0, 1e-8, ""});

    const double k = pressure * a * a / (b * b - a * a);
    auto radialTheory = [&](double r) { return (1.0 + poisson) * k / young * ((1.0 - 2.0 * poisson) * r + b * b / r); };
    for (const double r : {a, b})
    {
        double sum = 0.0;
        int count = 0;
        for (std::size_t n = 0; n < mesh.cornerCount; ++n)
            if (const Eigen::Vector2d rest = mesh.points[n].head<2>(); std::abs(rest.norm() - r) < 1e-9)
                sum += (model.positions().segment<2>(Eigen::Index(3 * n)) - rest).dot(rest.normalized()), ++count;
        const double theory = radialTheory(r);
        result.figures.push_back({r == a ? "radial displacement at r = a" : "radial displacement at r = b",
                                  1e6 * sum / count, 1e6 * theory, 0.02 * 1e6 * theory, "um"});
    }
    const ElementStresses stresses = model.elementStresses();
    double errorSum = 0.0, worst = 0.0;
    for (std::size_t e = 0; e < mesh.elements.size(); ++e)
    {
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (int c = 0; c < 4; ++c)
            centroid += 0.25 * mesh.points[std::size_t(mesh.elements[e][std::size_t(c)])];
        const double r = centroid.head<2>().norm();
        const Eigen::Vector3d hoop(-centroid.y() / r, centroid.x() / r, 0.0);
        const double error = std::abs(hoop.dot(stresses.tensors[e] * hoop) - k * (1.0 + b * b / (r * r))) / (k * (1.0 + b * b / (r * r)));
        errorSum += error;
        worst = std::max(worst, error);
    }
    result.figures.push_back({"hoop stress, mean relative error over the elements",
                              errorSum / double(mesh.elements.size()), 0.0, 0.02, ""});
    result.figures.push_back({"hoop stress, largest relative error of an element", worst, 0.0, 0.05, ""});
    return result;
}

ValidationResult dampingTest(const Progress& progress)
{
    ValidationResult result;
    result.description = storedText("a 0.2 m cantilever (240 tets) bent by a tip load, released without load; backward "
                                    "Euler, h = 1 ms, 300 steps, Rayleigh beta = 0.22 s (thesis) and 0.005 s: total "
                                    "energy (kinetic + elastic) must never rise");
    const StructuredTetMesh mesh = boxTetMesh(Eigen::Vector3d(0.2, 0.02, 0.02), {10, 2, 2});
    const Constraints clamped = clampedAtXZero(mesh);
    int stage = 0;
    for (double beta : {0.22, 0.005})
    {
        CorotationalFem model(mesh.points, mesh.tets, material(1e6, 0.3));
        Eigen::VectorXd load = Eigen::VectorXd::Zero(Eigen::Index(3 * model.nodeCount()));
        addTipLoad(mesh, Eigen::Vector3d(0.0, 0.0, -0.05), load);
        solveStatic(model, load, clamped, 1e-10);
        BackwardEulerSettings settings;
        settings.timeStep = 1e-3;
        settings.rayleighBeta = beta;
        settings.cgMaxIterations = 1000;
        settings.cgTolerance = 1e-10;
        BackwardEuler integrator(model, settings);
        const double initial = model.elasticEnergy() + model.kineticEnergy();
        double previous = initial;
        int rises = 0;
        for (int step = 0; step < 300; ++step)
        {
            integrator.step(model, {}, clamped);
            const double energy = model.elasticEnergy() + model.kineticEnergy();
            rises += energy > previous * (1.0 + 1e-9);
            previous = energy;
        }
        const std::string tag = " (beta = " + std::string(beta > 0.1 ? "0.22" : "0.005") + " s)";
        result.figures.push_back({"steps where the energy rose" + tag, double(rises), 0.0, 0.5, ""});
        result.figures.push_back({"energy left after 0.3 s / initial" + tag, previous / initial, 0.0, 0.9, ""});
        progress.report(++stage / 2.0, localized("vsim::Progress", "damping"));
    }
    return result;
}

const std::map<std::string, std::function<ValidationResult(const Progress&)>>& cases()
{
    static const std::map<std::string, std::function<ValidationResult(const Progress&)>> all{
        {"fem-patch", patchTest},         {"fem-rotation", rotationTest}, {"fem-cantilever", cantileverTest},
        {"fem-lame", lameTest},           {"fem-lame-quadratic", lameQuadraticTest},
        {"fem-damping", dampingTest}};
    return all;
}

} // namespace

std::vector<std::string> femValidationCases()
{
    return {"fem-patch", "fem-rotation", "fem-cantilever", "fem-lame", "fem-lame-quadratic", "fem-damping"};
}

ValidationConfiguration femValidationConfiguration()
{
    // solveStatic's default cap (StaticSolver.h); the loosest tolerance is the cantilever's 1e-8.
    return {"cpu", 20000, 1e-8,
            "on the CPU; static solves to relative residuals of 1e-8 to 1e-13 with up to 20,000 PCG iterations per "
            "solve, the damping case 1,000 per step to 1e-10"};
}

ValidationResult runFemValidation(const std::string& name, const Progress& progress)
{
    const auto found = cases().find(name);
    if (found == cases().end())
    {
        std::string known;
        for (const std::string& c : femValidationCases())
            known += (known.empty() ? "" : ", ") + c;
        throw Error(Pattern{"unknown validation case '%1' (known: %2)", {name, known}});
    }
    const auto start = std::chrono::steady_clock::now();
    ValidationResult result = found->second(progress);
    result.name = name;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace vsim::sim::fem
