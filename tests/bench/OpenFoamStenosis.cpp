#include "OpenFoamStenosis.h"

#include "vsim/core/Error.h"

#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <numbers>
#include <numeric>
#include <regex>
#include <sstream>

namespace vsim::bench {
namespace fs = std::filesystem;
namespace {

constexpr const char* kMarker = "VASCUSIM-OPENFOAM-CASE";
constexpr const char* kSolvedKey = "VASCUSIM-OPENFOAM-SOLVED"; // the case solved here (caseKey), written last
constexpr const char* kSolvedSeconds = "VASCUSIM-OPENFOAM-SECONDS";
constexpr int kWritesPerCycle = 40; // a pulsatile run's writes a cycle: five in its systole (a tenth of the cycle)

/// What the solution depends on: the pipe's geometry and flow and the mesh (not the particles' spacing, which sets
/// only the sections the fields are read through).
std::string caseKey(const sim::sph::StenosisPipe& pipe, const OpenFoamMesh& mesh)
{
    std::ostringstream key;
    key.precision(17);
    key << "radius_mm " << pipe.radiusMm << " length_mm " << pipe.lengthMm << " throat_mm " << pipe.throatAtMm
        << " half_length_mm " << pipe.halfLengthMm << " mean_speed_m_s " << pipe.meanSpeedMS << " density "
        << pipe.densityKgM3 << " viscosity " << pipe.viscosityPaS << " axial " << mesh.axialCells << " radial "
        << mesh.radialCells << " grading " << mesh.wallGrading << " wedge " << mesh.wedgeDegrees << " classic "
        << mesh.classicSimple;
    if (mesh.transient) // from rest: the ramp and the averaging window matter too
    {
        key << " transient ramp_s " << pipe.rampS << " average_from_s " << pipe.averageFromS << " end_time_s "
            << pipe.endTimeS << " waveform";
        for (const auto& [time, factor] : pipe.inflowWaveform.points)
            key << ' ' << time << ' ' << factor;
        key << " systole " << pipe.systole.fromS << ' ' << pipe.systole.toS << " one cycle past the end";
    }
    key << "\n";
    return key.str();
}

std::string header(const std::string& type, const std::string& object)
{
    return "FoamFile { version 2.0; format ascii; class " + type + "; object " + object + "; }\n";
}

void write(const fs::path& file, const std::string& text)
{
    fs::create_directories(file.parent_path());
    std::ofstream out(file);
    out << text;
    if (!out)
        throw Error("cannot write " + file.string());
}

std::string read(const fs::path& file)
{
    std::ifstream in(file);
    if (!in)
        throw Error("cannot read " + file.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

void run(const fs::path& directory, const std::string& command, const std::string& log)
{
    const std::string line = "cd '" + directory.string() + "' && " + command + " > " + log + " 2>&1";
    if (std::system(line.c_str()) != 0)
        throw Error("OpenFOAM's '" + command + "' failed: see " + (directory / log).string());
}

std::string number(double value)
{
    std::ostringstream text;
    text.precision(12);
    text << value;
    return text.str();
}

/// The list a field file gives for its internal field (`patch` empty) or for a patch's "value" entry: `width` numbers
/// per entry (1 for scalars, 3 for vectors), "uniform" expanded to `uniformCount` entries.
std::vector<double> readList(const fs::path& file, int width, const std::string& patch = "", std::size_t uniformCount = 0)
{
    const std::string text = read(file);
    std::size_t at = std::string::npos;
    if (patch.empty())
        at = text.find("internalField");
    else
    {
        std::smatch match;
        const std::string tail = text.substr(text.find("boundaryField"));
        if (std::regex_search(tail, match, std::regex("\\b" + patch + "\\s*\\{")))
            at = text.find("boundaryField") + std::size_t(match.position(0));
        if (at != std::string::npos)
            at = text.find("value", at);
    }
    if (at == std::string::npos)
        throw Error(file.string() + " has no " + (patch.empty() ? "internal field" : "value for " + patch));
    std::vector<double> values;
    const char* p = text.c_str() + at;
    const auto skipTo = [&p](const char* set) {
        while (*p && !std::strchr(set, *p))
            ++p;
    };
    skipTo(" \t\n");
    skipTo("un"); // the keyword's value: "uniform" or "nonuniform"
    if (*p == 'u')
    {
        skipTo("0123456789-.(");
        double entry[3] = {0.0, 0.0, 0.0};
        for (int k = 0; k < width; ++k)
        {
            skipTo("0123456789-.");
            entry[k] = std::strtod(p, const_cast<char**>(&p));
        }
        for (std::size_t i = 0; i < uniformCount; ++i)
            values.insert(values.end(), entry, entry + width);
        return values;
    }
    skipTo(">");
    ++p;
    const long count = std::strtol(p, const_cast<char**>(&p), 10);
    skipTo("(");
    ++p;
    values.reserve(std::size_t(count) * std::size_t(width));
    for (long i = 0; i < count * width; ++i)
    {
        skipTo("0123456789-.");
        values.push_back(std::strtod(p, const_cast<char**>(&p)));
    }
    return values;
}

fs::path latestTime(const fs::path& directory)
{
    fs::path latest;
    double latestValue = 0.0;
    for (const auto& entry : fs::directory_iterator(directory))
    {
        const std::string name = entry.path().filename().string();
        char* end = nullptr;
        const double value = std::strtod(name.c_str(), &end);
        if (entry.is_directory() && end && *end == '\0' && value > latestValue)
            latest = entry.path(), latestValue = value;
    }
    if (latest.empty())
        throw Error("OpenFOAM wrote no time directory in " + directory.string());
    return latest;
}

void writeCase(const sim::sph::StenosisPipe& pipe, const OpenFoamMesh& mesh, const fs::path& directory)
{
    // One block: vertices 0, 1 on the axis at the inlet and the outlet, 2 / 3 (outlet / inlet) on the wall at minus
    // half the wedge angle, 4 / 5 (inlet / outlet) at plus; the wall edges are polyLines through R(x) at every axial
    // cell. (One block per axial cell, which keeps every cross-section face in a plane, did not converge at the finer
    // mesh; blockMesh spaces a polyLine by arc length, so the cells by the wall lean a little in the narrowing.)
    const double half = 0.5 * mesh.wedgeDegrees * std::numbers::pi / 180.0, c = std::cos(half), s = std::sin(half);
    const double length = pipe.lengthMm, radius = pipe.radiusMm;
    std::ostringstream edges;
    for (int side : {-1, 1})
    {
        edges << "polyLine " << (side < 0 ? "3 2" : "4 5") << " (";
        for (int i = 1; i < mesh.axialCells; ++i)
        {
            const double x = length * i / mesh.axialCells, r = pipe.radiusAtMm(x);
            edges << " (" << number(x) << ' ' << number(r * c) << ' ' << number(side * r * s) << ')';
        }
        edges << " )\n";
    }
    const std::string rc = number(radius * c), rs = number(radius * s), l = number(length);
    write(directory / "system/blockMeshDict",
          header("dictionary", "blockMeshDict") + "convertToMeters 0.001;\n" +
              "vertices ( (0 0 0) (" + l + " 0 0) (" + l + ' ' + rc + " -" + rs + ") (0 " + rc + " -" + rs + ") (0 " +
              rc + ' ' + rs + ") (" + l + ' ' + rc + ' ' + rs + ") );\n" +
              "blocks ( hex (0 1 2 3 0 1 5 4) (" + std::to_string(mesh.axialCells) + ' ' +
              std::to_string(mesh.radialCells) + " 1) simpleGrading (1 " + number(mesh.wallGrading) + " 1) );\n" +
              "edges (\n" + edges.str() + ");\n" +
              "boundary (\n"
              " inlet { type patch; faces ((0 3 4 0)); }\n"
              " outlet { type patch; faces ((1 2 5 1)); }\n"
              " wall { type wall; faces ((3 2 5 4)); }\n"
              " front { type wedge; faces ((0 1 5 4)); }\n"
              " back { type wedge; faces ((0 3 2 1)); }\n"
              " axis { type empty; faces ((0 1 1 0)); }\n);\nmergePatchPairs ();\n");
    const std::string wallShear = "wallShearStress { type wallShearStress; libs (\"libfieldFunctionObjects.so\"); "
                                  "patches (wall); writeControl writeTime; }\n";
    const std::string output = "writeFormat ascii; writePrecision 12; writeCompression off;\n"
                               "timeFormat general; timePrecision 10; runTimeModifiable false;\n";
    if (mesh.transient)
    {
        // The wall shear stress and its magnitude at every step, so that fieldAverage (after them) averages both: the
        // time-averaged WSS is the mean of the magnitude. A pulsatile inflow also writes the fields every 1/40 of its
        // cycle, whose writes in the systole the systolic figures are read from, and runs one cycle past the SPH's
        // end (the averages stop there): the two cycles' systoles show how periodic the flow has become.
        const std::string mean = " { mean on; prime2Mean off; base time; }";
        const double period = pipe.inflowWaveform.period();
        write(directory / "system/controlDict",
              header("dictionary", "controlDict") + "application pimpleFoam; startFrom startTime; startTime 0; " +
                  "stopAt endTime; endTime " + number(pipe.endTimeS + period) + "; deltaT 1e-7; adjustTimeStep yes; " +
                  "maxCo 0.5; maxDeltaT 1;\nwriteControl adjustableRunTime; writeInterval " +
                  number(period > 0.0 ? period / kWritesPerCycle : pipe.endTimeS) + ";\n" + output + "functions {\n" +
                  wallShear +
                  "shearMagnitude { type mag; libs (\"libfieldFunctionObjects.so\"); field wallShearStress; "
                  "writeControl writeTime; }\n"
                  "average { type fieldAverage; libs (\"libfieldFunctionObjects.so\"); writeControl writeTime; "
                  "timeStart " + number(pipe.averageFromS) + "; timeEnd " + number(pipe.endTimeS) + "; fields ( U" +
                  mean + " p" + mean +
                  " wallShearStress" + mean + " \"mag(wallShearStress)\"" + mean + " ); }\n}\n");
    }
    else
        write(directory / "system/controlDict",
              header("dictionary", "controlDict") +
                  "application simpleFoam; startFrom startTime; startTime 0; stopAt endTime; endTime 20000; deltaT 1;\n"
                  "writeControl timeStep; writeInterval 20000;\n" + output + "functions {\n" + wallShear + "}\n");
    write(directory / "system/fvSchemes",
          header("dictionary", "fvSchemes") +
              (mesh.transient ? "ddtSchemes { default backward; }\n" : "ddtSchemes { default steadyState; }\n") +
              "gradSchemes { default Gauss linear; }\ndivSchemes { default none; div(phi,U) " +
              (mesh.transient ? "Gauss linear" : "bounded Gauss linear") +
              "; div((nuEff*dev2(T(grad(U))))) Gauss linear; }\n"
              "laplacianSchemes { default Gauss linear corrected; }\ninterpolationSchemes { default linear; }\n"
              "snGradSchemes { default corrected; }\n");
    // Transient: every pressure correction to 1e-10 (the largest final residual is reported), and two non-orthogonal
    // correctors: the cells by the wall lean up to 38 degrees where the narrowing is steepest (x = 2.0 and 2.8 mm),
    // and without them the cell velocities there broke up into a stationary wiggle (the cells' mean axial velocity
    // at 2.0 mm 36 % above the flow rate's, radial velocities of 0.3 m/s by the wall).
    if (mesh.transient)
        write(directory / "system/fvSolution",
              header("dictionary", "fvSolution") +
                  "solvers { \"(p|pFinal)\" { solver GAMG; smoother GaussSeidel; tolerance 1e-10; relTol 0; }\n"
                  " \"(U|UFinal)\" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-12; relTol 0; } }\n"
                  "PIMPLE { nOuterCorrectors 1; nCorrectors 2; nNonOrthogonalCorrectors 2; }\n");
    else
        write(directory / "system/fvSolution",
              header("dictionary", "fvSolution") +
                  "solvers { p { solver GAMG; smoother GaussSeidel; tolerance 1e-14; relTol 0.05; }\n"
                  " U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-14; relTol 0.1; } }\n" +
                  std::string(mesh.classicSimple
                       ? "SIMPLE { nNonOrthogonalCorrectors 0; consistent no; residualControl { p 1e-11; } }\n"
                         "relaxationFactors { equations { U 0.7; } fields { p 0.3; } }\n"
                       : "SIMPLE { nNonOrthogonalCorrectors 0; consistent yes; residualControl { p 1e-11; } }\n"
                         "relaxationFactors { equations { U 0.9; } fields { p 1; } }\n"));
    write(directory / "constant/transportProperties",
          header("dictionary", "transportProperties") + "transportModel Newtonian; nu " +
              number(pipe.viscosityPaS / pipe.densityKgM3) + ";\n");
    write(directory / "constant/turbulenceProperties", header("dictionary", "turbulenceProperties") + "simulationType laminar;\n");
    write(directory / "0/p", header("volScalarField", "p") +
                                 "dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 0;\n"
                                 "boundaryField { inlet { type zeroGradient; } outlet { type fixedValue; value uniform 0; }\n"
                                 " wall { type zeroGradient; } front { type wedge; } back { type wedge; } axis { type empty; } }\n");
}

/// 0/U: the parabola u = 2 U (1 - r^2 / R0^2) at the inlet's face centres (r from the axis); transient, times the
/// SPH's inflow factor (StenosisPipe::inflowFactor: the ramp (1 - cos(pi t / T)) / 2 over T and the pulsatile
/// waveform) at 41 times over the ramp and at each of the waveform's knots to the end, in constant/boundaryData,
/// which OpenFOAM interpolates linearly in time (0.08 % of the flow at most on the ramp; the waveform is linear
/// between its knots) and holds after the last.
void writeInflow(const sim::sph::StenosisPipe& pipe, const OpenFoamMesh& mesh, const fs::path& directory)
{
    const std::vector<double> centres = readList(directory / "0/C", 3, "inlet");
    const double radius = 1e-3 * pipe.radiusMm;
    const auto profile = [&](double scale) {
        std::ostringstream faces;
        for (std::size_t f = 0; f + 2 < centres.size(); f += 3)
        {
            const double r = std::hypot(centres[f + 1], centres[f + 2]);
            faces << " (" << number(scale * 2.0 * pipe.meanSpeedMS * (1.0 - r * r / (radius * radius))) << " 0 0)";
        }
        return std::to_string(centres.size() / 3) + " (" + faces.str() + " )\n";
    };
    std::string inlet = "fixedValue; value nonuniform List<vector> " + profile(1.0);
    if (mesh.transient)
    {
        const fs::path data = directory / "constant/boundaryData/inlet";
        std::ostringstream points;
        for (std::size_t f = 0; f + 2 < centres.size(); f += 3)
            points << " (" << number(centres[f]) << ' ' << number(centres[f + 1]) << ' ' << number(centres[f + 2])
                   << ')';
        write(data / "points", std::to_string(centres.size() / 3) + " (" + points.str() + " )\n");
        constexpr int kRampSteps = 40;
        std::vector<double> times = {2.0 * pipe.endTimeS};
        for (int k = 0; k <= kRampSteps; ++k)
            times.push_back(pipe.rampS * k / kRampSteps);
        const double period = pipe.inflowWaveform.period();
        for (double cycle = 0.0; period > 0.0 && cycle <= pipe.endTimeS; cycle += period)
            for (const auto& knot : pipe.inflowWaveform.points)
                times.push_back(cycle + knot.first);
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end(), [](double a, double b) { return b - a < 1e-12; }),
                    times.end());
        for (double time : times)
            write(data / number(time) / "U", profile(pipe.inflowFactor(time)));
        inlet = "timeVaryingMappedFixedValue; mapMethod nearest; offset (0 0 0); setAverage off";
    }
    write(directory / "0/U", header("volVectorField", "U") +
                                 "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (0 0 0);\nboundaryField {\n"
                                 " inlet { type " + inlet + "; }\n"
                                 " outlet { type zeroGradient; } wall { type noSlip; }\n"
                                 " front { type wedge; } back { type wedge; } axis { type empty; }\n}\n");
}

/// The lumen's area averaged over the slab (m^2; the mean of pi R(x)^2, 64-point midpoint rule).
double slabArea(const sim::sph::StenosisPipe& pipe, double xMm, double thicknessMm)
{
    double sum = 0.0;
    for (int k = 0; k < 64; ++k)
        sum += std::pow(1e-3 * pipe.radiusAtMm(xMm + thicknessMm * ((k + 0.5) / 64.0 - 0.5)), 2);
    return std::numbers::pi * sum / 64.0;
}

/// The cells whose centres lie in the slab |x - x_s| <= thickness / 2, read as the SPH reads its particles
/// (CrossSections.h): volume-weighted mean velocity and pressure, the peak the mean of the fastest 5 % of the volume;
/// the area is the lumen's over the slab (the leaning cells by the wall do not tile the slab exactly), the flow rate
/// area x mean velocity.
sim::sph::SectionFlow sectionOfCells(const sim::sph::StenosisPipe& pipe, double xMm, const std::vector<double>& centres,
                                     const std::vector<double>& velocity, const std::vector<double>& pressure,
                                     const std::vector<double>& volume)
{
    const double xM = 1e-3 * xMm, thicknessM = 1e-3 * pipe.sectionThicknessMm();
    std::vector<std::size_t> in;
    for (std::size_t i = 0; i < volume.size(); ++i)
        if (std::abs(centres[3 * i] - xM) <= 0.5 * thicknessM * (1.0 + 1e-9))
            in.push_back(i);
    sim::sph::SectionFlow flow;
    if (in.empty())
        return flow;
    double v = 0.0, flux = 0.0, p = 0.0;
    for (std::size_t i : in)
        v += volume[i], flux += volume[i] * velocity[3 * i], p += volume[i] * pressure[i];
    std::sort(in.begin(), in.end(), [&velocity](std::size_t a, std::size_t b) { return velocity[3 * a] > velocity[3 * b]; });
    double topVolume = 0.0, top = 0.0;
    for (std::size_t k = 0; k < in.size() && topVolume < 0.05 * v; ++k)
        topVolume += volume[in[k]], top += volume[in[k]] * velocity[3 * in[k]];
    flow.areaM2 = slabArea(pipe, xMm, pipe.sectionThicknessMm());
    flow.meanVelocityMS = flux / v;
    flow.flowRateM3S = flow.areaM2 * flow.meanVelocityMS;
    flow.peakVelocityMS = top / topVolume;
    flow.meanPressurePa = pipe.densityKgM3 * p / v;
    flow.particles = int(in.size());
    return flow;
}

/// The time directories written in [fromS, toS] (s), in time order.
std::vector<std::pair<double, fs::path>> timesWithin(const fs::path& directory, double fromS, double toS)
{
    std::vector<std::pair<double, fs::path>> times;
    const double slack = 1e-9 * std::max(1.0, toS);
    for (const auto& entry : fs::directory_iterator(directory))
    {
        const std::string name = entry.path().filename().string();
        char* end = nullptr;
        const double value = std::strtod(name.c_str(), &end);
        if (entry.is_directory() && end && *end == '\0' && value >= fromS - slack && value <= toS + slack)
            times.emplace_back(value, entry.path());
    }
    std::sort(times.begin(), times.end());
    return times;
}

/// The sections averaged over the systole of the cycle that starts at `cycleS`, by the trapezoid rule over the writes
/// in it (five a systole); empty when fewer than two were written.
std::vector<sim::sph::SectionFlow> systolicSections(const sim::sph::StenosisPipe& pipe, const fs::path& directory,
                                                    double cycleS, const std::vector<double>& centres,
                                                    const std::vector<double>& volume)
{
    const auto times = timesWithin(directory, cycleS + pipe.systole.fromS, cycleS + pipe.systole.toS);
    if (times.size() < 2)
        return {};
    const std::vector<double> arcs = pipe.sectionArcsMm();
    std::vector<sim::sph::SectionFlow> sums(arcs.size());
    for (std::size_t t = 0; t < times.size(); ++t)
    {
        const double weight = 0.5 * (times[std::min(t + 1, times.size() - 1)].first - times[t > 0 ? t - 1 : 0].first);
        const std::vector<double> velocity = readList(times[t].second / "U", 3);
        const std::vector<double> pressure = readList(times[t].second / "p", 1);
        for (std::size_t k = 0; k < arcs.size(); ++k)
            sim::sph::addWeighted(sums[k], sectionOfCells(pipe, arcs[k], centres, velocity, pressure, volume), weight);
    }
    return sim::sph::averaged(std::move(sums), arcs.size(), times.back().first - times.front().first);
}

} // namespace

OpenFoamStenosisFlow runOpenFoamStenosis(const sim::sph::StenosisPipe& pipe, const OpenFoamMesh& mesh,
                                         const fs::path& directory)
{
    OpenFoamStenosisFlow flow;
    const std::string key = caseKey(pipe, mesh);
    const std::string solver = mesh.transient ? "pimpleFoam" : "simpleFoam";
    const bool solved = fs::exists(directory / kMarker) && fs::exists(directory / kSolvedKey) &&
                        read(directory / kSolvedKey) == key;
    if (solved) // the same case solved before: read again (the sections' slabs follow the spacing, the case does not)
    {
        flow.reused = true;
        flow.seconds = std::stod(read(directory / kSolvedSeconds));
    }
    else
    {
        if (fs::exists(directory))
        {
            if (!fs::exists(directory / kMarker))
                throw Error(directory.string() + " exists and is not a case of this bench: not touched");
            fs::remove_all(directory);
        }
        fs::create_directories(directory);
        write(directory / kMarker, "written by VascuSim's bench_sph_openfoam; the whole folder is replaced by its next "
                                   "run of another case (" + std::string(kSolvedKey) + " names the one it holds)\n");
        if (!std::getenv("WM_PROJECT_DIR") && fs::exists("/usr/share/openfoam/etc/controlDict"))
            setenv("WM_PROJECT_DIR", "/usr/share/openfoam", 0); // Debian's layout; the binaries need it to find etc/

        const auto start = std::chrono::steady_clock::now();
        writeCase(pipe, mesh, directory);
        run(directory, "blockMesh", "log.blockMesh");
        run(directory, "postProcess -func writeCellCentres -time 0", "log.writeCellCentres");
        writeInflow(pipe, mesh, directory);
        run(directory, solver, "log." + solver);
        run(directory, "postProcess -func writeCellVolumes -latestTime", "log.writeCellVolumes");
        flow.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        write(directory / kSolvedSeconds, std::to_string(flow.seconds));
        write(directory / kSolvedKey, key);
    }

    const std::string log = read(directory / ("log." + solver));
    if (mesh.transient) // a time step's pressure corrections each solve to 1e-10: the largest final residual
    {
        const std::regex pressureSolve("Solving for p, Initial residual = [-0-9.e+]+, Final residual = ([-0-9.e+]+)");
        for (auto it = std::sregex_iterator(log.begin(), log.end(), pressureSolve); it != std::sregex_iterator(); ++it)
            flow.pressureResidual = std::max(flow.pressureResidual, std::stod((*it)[1]));
        const std::regex timeStep("\nTime = ");
        flow.iterations =
            int(std::distance(std::sregex_iterator(log.begin(), log.end(), timeStep), std::sregex_iterator()));
        flow.converged = log.find("\nEnd") != std::string::npos && flow.pressureResidual <= 1e-10;
    }
    else // one pressure solve per SIMPLE iteration (no non-orthogonal correctors)
    {
        const std::regex pressureSolve("Solving for p, Initial residual = ([-0-9.e+]+)");
        for (auto it = std::sregex_iterator(log.begin(), log.end(), pressureSolve); it != std::sregex_iterator(); ++it)
            flow.pressureResidual = std::stod((*it)[1]), ++flow.iterations;
        flow.converged = log.find("SIMPLE solution converged") != std::string::npos;
    }

    // The averages at the SPH's end (a pulsatile run goes on one cycle past it); the cell volumes at the last time.
    const auto ends = timesWithin(directory, pipe.endTimeS, pipe.endTimeS);
    const fs::path time = mesh.transient && !ends.empty() ? ends.front().second : latestTime(directory);
    const std::string mean = mesh.transient ? "Mean" : ""; // the window's averages
    const std::vector<double> centres = readList(directory / "0/C", 3), velocity = readList(time / ("U" + mean), 3),
                              pressure = readList(time / ("p" + mean), 1),
                              volume = readList(latestTime(directory) / "V", 1);
    flow.cells = int(volume.size());
    if (centres.size() != 3 * volume.size() || velocity.size() != centres.size() || pressure.size() != volume.size())
        throw Error("the fields in " + time.string() + " do not match the mesh's " + std::to_string(flow.cells) + " cells");
    const double fullTurn = 360.0 / mesh.wedgeDegrees;
    const std::vector<double> arcs = pipe.sectionArcsMm();
    for (double x : arcs)
        flow.sections.push_back(sectionOfCells(pipe, x, centres, velocity, pressure, volume));
    flow.figures = sim::sph::stenosisFigures(arcs, flow.sections, pipe.compareMm);
    if (mesh.transient && !pipe.systole.empty()) // the averaged cycle's systole, and the next cycle's
    {
        flow.systolicSections = systolicSections(pipe, directory, pipe.averageFromS, centres, volume);
        const auto next = systolicSections(pipe, directory, pipe.endTimeS, centres, volume);
        if (flow.systolicSections.empty() || next.empty())
            throw Error("OpenFOAM wrote no fields in the systoles of " + directory.string());
        flow.systolicFigures = sim::sph::stenosisFigures(arcs, flow.systolicSections, pipe.compareMm);
        flow.nextSystolicFigures = sim::sph::stenosisFigures(arcs, next, pipe.compareMm);
    }
    const std::vector<double> wallCentres = readList(directory / "0/C", 3, "wall");
    // Transient: the time average of the magnitude (TAWSS); steady: the magnitude of the stress.
    const std::vector<double> shear = mesh.transient ? readList(time / "mag(wallShearStress)Mean", 1, "wall")
                                                     : readList(time / "wallShearStress", 3, "wall");
    const int shearWidth = mesh.transient ? 1 : 3;
    double throatSum = 0.0;
    int throatFaces = 0;
    for (std::size_t f = 0; shearWidth * f + shearWidth - 1 < shear.size() && 3 * f + 2 < wallCentres.size(); ++f)
    {
        const double xMm = 1e3 * wallCentres[3 * f];
        const double tau = pipe.densityKgM3 * (shearWidth == 1 ? std::abs(shear[f])
                                               : Eigen::Vector3d(shear[3 * f], shear[3 * f + 1], shear[3 * f + 2]).norm());
        flow.wallArcMm.push_back(xMm), flow.wallShearPa.push_back(tau);
        if (std::abs(xMm - pipe.throatAtMm) <= 0.5 * pipe.sectionThicknessMm())
            throatSum += tau, ++throatFaces;
    }
    flow.throatWallShearPa = throatFaces > 0 ? throatSum / throatFaces : 0.0;
    const std::vector<double> inletFlux = readList(time / "phi", 1, "inlet");
    flow.inletFlowRateM3S = -fullTurn * std::accumulate(inletFlux.begin(), inletFlux.end(), 0.0);
    return flow;
}

} // namespace vsim::bench
