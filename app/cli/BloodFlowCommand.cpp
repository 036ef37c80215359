#include "BloodFlowCommand.h"

#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/app/BloodFlowPipeline.h"
#include "vsim/app/InjectionPipeline.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/core/Units.h"
#include "vsim/study/RunSeries.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <sstream>
#include <tuple>

namespace vsim::cli {
namespace {

/// A number and its unit ("5ml/s", "0.3 m/s", "90mmHg"); throws vsim::Error naming --`option`.
std::pair<double, std::string> numberAndUnit(const std::string& text, const std::string& option)
{
    std::size_t used = 0;
    double value = 0.0;
    try
    {
        value = std::stod(text, &used);
    }
    catch (const std::exception&)
    {
        throw Error("--" + option + " expects a number with its unit, got '" + text + "'");
    }
    std::string unit = text.substr(used);
    unit.erase(std::remove(unit.begin(), unit.end(), ' '), unit.end());
    return {value, unit};
}

/// Pa from "90mmHg", "12kPa" or "1000Pa" (a bare number: mmHg).
double pressurePa(double value, const std::string& unit, const std::string& option)
{
    if (unit.empty() || unit == "mmHg")
        return units::mmHgToPa(value);
    if (unit == "Pa")
        return value;
    if (unit == "kPa")
        return 1e3 * value;
    throw UsageError("--" + option + ": unknown unit '" + unit + "' (mmHg, kPa or Pa)");
}

/// --inlet: a flow rate (ml/s, ml/min, l/min), a mean velocity (m/s, cm/s) or a pressure (mmHg, kPa, Pa), optionally
/// "@NODE" for the vessel end.
app::BloodFlowInlet parseInlet(const std::string& text)
{
    app::BloodFlowInlet inlet;
    std::string quantity = text;
    if (const std::size_t at = text.find('@'); at != std::string::npos)
    {
        quantity = text.substr(0, at);
        inlet.endNode = int(parseNumbers(text.substr(at + 1), ',', 1, "inlet")[0]);
    }
    const auto [value, unit] = numberAndUnit(quantity, "inlet");
    using Kind = app::BloodFlowInlet::Kind;
    if (unit == "ml/s")
        inlet.kind = Kind::FlowRate, inlet.value = 1e-6 * value;
    else if (unit == "ml/min")
        inlet.kind = Kind::FlowRate, inlet.value = units::mlPerMinToM3PerS(value);
    else if (unit == "l/min")
        inlet.kind = Kind::FlowRate, inlet.value = units::mlPerMinToM3PerS(1e3 * value);
    else if (unit == "m/s")
        inlet.kind = Kind::MeanVelocity, inlet.value = value;
    else if (unit == "cm/s")
        inlet.kind = Kind::MeanVelocity, inlet.value = 1e-2 * value;
    else if (unit == "mmHg" || unit == "kPa" || unit == "Pa")
        inlet.kind = Kind::Pressure, inlet.value = pressurePa(value, unit, "inlet");
    else
        throw UsageError("--inlet: unknown unit '" + unit +
                         "' (a flow rate in ml/s, ml/min or l/min, a mean velocity in m/s or cm/s, or a pressure in "
                         "mmHg, kPa or Pa)");
    return inlet;
}

/// A waveform file: lines "time_s,factor" (or separated by blanks), '#' comments; times increasing from 0.
sim::sph::Waveform readWaveform(const std::string& file)
{
    std::ifstream in(file);
    if (!in)
        throw Error("cannot read the waveform file '" + file + "'");
    sim::sph::Waveform waveform;
    std::string line;
    int number = 0;
    while (std::getline(in, line))
    {
        ++number;
        if (line.empty() || line[0] == '#')
            continue;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        double time = 0.0, factor = 0.0;
        if (!(fields >> time >> factor))
        {
            if (number == 1) // a header
                continue;
            throw Error("the waveform file '" + file + "', line " + std::to_string(number) + ": expected 'time_s,factor'");
        }
        if (!waveform.points.empty() && !(time > waveform.points.back().first))
            throw Error("the waveform file '" + file + "', line " + std::to_string(number) + ": times must increase");
        waveform.points.push_back({time, factor});
    }
    if (waveform.points.size() < 2 || waveform.points.front().first != 0.0)
        throw Error("the waveform file '" + file + "' needs at least two points, the first at time 0");
    return waveform;
}

/// What both SPH commands do before anything runs: --backend checked, --out checked (a refused folder costs no
/// time; it is claimed when the run is written), the study opened for writing and its centerlines chosen (--centerlines or the newest).
study::Study prepareSphRun(const Arguments& arguments, std::string& backend, std::string& centerlinesId)
{
    backend = arguments.option("backend", "auto");
    if (backend != "auto" && backend != "cpu" && backend != "cuda")
        throw UsageError("--backend: auto, cpu or cuda, not '" + backend + "'");
    if (arguments.hasOption("out"))
        checkOutputFolder(arguments.option("out"), "run");
    study::Study study = openStudyForWriting(arguments);
    centerlinesId = chooseCenterlines(study, arguments.option("centerlines"));
    return study;
}

/// --param key=value into `parameters`, each key into `given`; then the options that set a solver parameter
/// (option, key, unit).
void applySolverOptions(const Arguments& arguments, ParameterSet& parameters, std::vector<std::string>& given,
                        const std::vector<std::tuple<std::string, std::string, std::string>>& options)
{
    applyParameters(arguments, parameters);
    for (const auto& [name, value] : arguments.options)
        if (name == "param")
            given.push_back(value.substr(0, value.find('=')));
    for (const auto& [option, key, unit] : options)
        if (arguments.hasOption(option))
        {
            parameters.set(key, quantityOption(arguments, option, unit, 0.0));
            given.push_back(key);
        }
}

/// --frames: 1 to 10000.
int framesOption(const Arguments& arguments, double fallback)
{
    const double frames = quantityOption(arguments, "frames", "", fallback);
    if (!(frames >= 1.0 && frames <= 10000.0))
        throw UsageError("--frames: 1 to 10000");
    return int(frames);
}

} // namespace

int simulateSph(const Arguments& arguments, const Progress& progress)
{
    app::BloodFlowSetup setup;
    study::Study study = prepareSphRun(arguments, setup.backend, setup.centerlinesId);
    setup.inlet = parseInlet(arguments.option("inlet", "0.2m/s"));
    if (arguments.hasOption("waveform"))
        setup.inlet.waveform = readWaveform(arguments.option("waveform"));
    const std::string profile = arguments.option("profile", "parabolic");
    if (profile != "parabolic" && profile != "plug")
        throw UsageError("--profile: parabolic or plug, not '" + profile + "'");
    setup.inlet.parabolic = profile == "parabolic";
    if (arguments.hasOption("outlet"))
    {
        const auto [value, unit] = numberAndUnit(arguments.option("outlet"), "outlet");
        setup.outletPressurePa = pressurePa(value, unit, "outlet");
    }
    setup.compareMm = quantityOption(arguments, "compare", "mm", 6.0);
    if (arguments.hasOption("ramp"))
        setup.rampS = quantityOption(arguments, "ramp", "s", 0.0);
    applySolverOptions(arguments, setup.parameters, setup.given,
                       {{"spacing", "spacing_mm", "mm"},
                        {"until", "end_time_s", "s"},
                        {"void-fraction", "void_fraction", ""}});
    setup.frames = framesOption(arguments, 20.0);
    const app::BloodFlowRun flow = app::runBloodFlow(study, setup, {}, progress.subRange(0.0, 0.95));
    const std::string document = app::bloodFlowDocument(flow, setup);
    const std::vector<std::string> inputs{setup.centerlinesId};
    const app::BloodFlowArtifacts added = app::addBloodFlowRun(study, flow, setup, inputs);
    const std::string& runId = added.run;
    study.save();
    if (arguments.hasOption("out"))
    {
        claimOutputFolder(arguments.option("out"), "run");
        study::writeRunSeries(arguments.option("out"), flow.run, document);
    }
    progress.report(1.0, "saved");
    std::cout << document.substr(0, document.size() - 2) << ",\n  \"run_artifact\": \"" << runId << "\",\n"
              << "  \"wall_loads_artifact\": \"" << added.wallLoads << "\"\n}\n";
    return runExitCode(flow.run.status, runId);
}

int simulateInjection(const Arguments& arguments, const Progress& progress)
{
    app::InjectionSetup setup;
    study::Study study = prepareSphRun(arguments, setup.backend, setup.centerlinesId);
    if (arguments.hasOption("needle-end"))
        setup.needleEndNode = int(parseNumbers(arguments.option("needle-end"), ',', 1, "needle-end")[0]);
    setup.needleBoreMm = quantityOption(arguments, "needle-bore", "mm", setup.needleBoreMm);
    setup.particlesPerSecond = quantityOption(arguments, "rate", "/s", setup.particlesPerSecond);
    setup.collectionDepthMm = quantityOption(arguments, "box-depth", "mm", setup.collectionDepthMm);
    setup.collectionMarginMm = quantityOption(arguments, "box-margin", "mm", setup.collectionMarginMm);
    applySolverOptions(arguments, setup.parameters, setup.given,
                       {{"spacing", "spacing_mm", "mm"},
                        {"until", "end_time_s", "s"},
                        {"void-fraction", "void_fraction", ""}});
    if (arguments.hasOption("gauge"))
    {
        const auto [value, unit] = numberAndUnit(arguments.option("gauge"), "gauge");
        setup.parameters.set("reference_pressure_pa", pressurePa(value, unit, "gauge"));
        setup.given.push_back("reference_pressure_pa");
    }
    setup.frames = framesOption(arguments, 10.0);
    const app::InjectionRun injection = app::runInjection(study, setup, {}, progress.subRange(0.0, 0.95));
    const std::string document = app::injectionDocument(injection, setup);
    const std::string runId = app::addInjectionRun(study, injection, setup);
    study.save();
    if (arguments.hasOption("out"))
    {
        claimOutputFolder(arguments.option("out"), "run");
        study::writeRunSeries(arguments.option("out"), injection.run, document);
    }
    progress.report(1.0, "saved");
    std::cout << document.substr(0, document.size() - 2) << ",\n  \"run_artifact\": \"" << runId << "\"\n}\n";
    return runExitCode(injection.run.status, runId);
}

} // namespace vsim::cli
