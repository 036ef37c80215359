#include "NetworkCommands.h"

#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/app/NetworkPipeline.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/core/Units.h"
#include "vsim/study/NetworkFile.h"

#include <algorithm>
#include <iostream>

namespace vsim::cli {
namespace {

/// "2ml/min", "2 ml/min", "0.05ml/s" or a plain number (ml/min) -> ml/min; a mass rate ("1.9g/min", "30mg/s")
/// through the mixture's density (kg/m^3 = g/l).
double parseRateMlPerMin(const std::string& text, double densityKgPerM3)
{
    std::size_t used = 0;
    double value = 0.0;
    try
    {
        value = std::stod(text, &used);
    }
    catch (const std::exception&)
    {
        throw Error("--rate expects a volume rate such as 2ml/min, got '" + text + "'");
    }
    std::string unit = text.substr(used);
    unit.erase(std::remove(unit.begin(), unit.end(), ' '), unit.end());
    if (unit.empty() || unit == "ml/min")
        return value;
    if (unit == "ml/s")
        return 60.0 * value;
    const double gramsPerMl = densityKgPerM3 * 1e-3;
    if (unit == "g/min")
        return value / gramsPerMl;
    if (unit == "mg/s")
        return 60.0 * 1e-3 * value / gramsPerMl;
    throw UsageError("--rate: unknown unit '" + unit + "' (ml/min, ml/s, g/min or mg/s)");
}

Eigen::Vector3d point(const std::vector<double>& v) { return {v[0], v[1], v[2]}; }

} // namespace

int simulateNetwork(const Arguments& arguments, const Progress& progress)
{
    if (arguments.hasOption("out")) // before the run: a refused folder costs no time
        checkOutputFolder(arguments.option("out"), "run");
    study::Study study = openStudyForWriting(arguments);
    sim::network::NetworkRunSetup setup;
    applyParameters(arguments, setup.parameters);
    if (arguments.hasOption("void-fraction"))
        setup.parameters.set("void_fraction", parseNumbers(arguments.option("void-fraction"), ',', 1, "void-fraction")[0]);
    if (arguments.hasOption("rate") && arguments.hasOption("tip-pressure"))
        throw Error("give the injection as a rate (--rate) or a tip pressure (--tip-pressure), not both");
    if (arguments.hasOption("rate"))
        setup.parameters.set("injection_rate_ml_min",
                             parseRateMlPerMin(arguments.option("rate"), sim::network::networkMixture(setup.parameters).density()));
    if (arguments.hasOption("tip-pressure"))
        setup.tipPressurePa = units::mmHgToPa(quantityOption(arguments, "tip-pressure", "mmHg", 0.0));

    std::map<std::string, std::string> source;
    std::vector<std::string> inputs, warnings;
    if (arguments.hasOption("network"))
    {
        setup.network = study::readNetworkFile(arguments.option("network"));
        // A hand-written network states its outlets, unless it asks for Murray-law defaults.
        setup.defaultOutlets = arguments.option("default-outlets") == "murray";
        if (arguments.hasOption("default-outlets") && !setup.defaultOutlets)
            throw Error("--default-outlets takes 'murray'");
        source["network_file"] = std::filesystem::path(arguments.option("network")).filename().string();
        inputs.push_back(source["network_file"]);
    }
    else
    {
        const std::string centerlinesId = chooseCenterlines(study, arguments.option("centerlines"));
        setup.network = app::buildStudyNetwork(study, centerlinesId, warnings, progress.subRange(0.0, 0.3));
        inputs.push_back(centerlinesId);
        const std::string labelId = app::labelOfCenterlines(study, centerlinesId);
        if (!labelId.empty())
            inputs.push_back(labelId);
    }
    if (arguments.hasOption("inlet"))
        source["inlet"] = arguments.option("inlet");
    const std::string tip = arguments.option("tip");
    if (tip.find(',') != std::string::npos)
        setup.tipPointMm = point(parseNumbers(tip, ',', 3, "tip"));
    else if (tip != "root") // the root: the network's inlet (runNetwork's default)
        setup.tipNode = int(parseNumbers(tip, ',', 1, "tip")[0]);
    source["tip"] = tip;
    if (arguments.hasOption("tumour"))
    {
        const std::vector<double> sphere = parseNumbers(arguments.option("tumour"), ',', 4, "tumour");
        setup.tumour = sim::network::TumourSphere{point(sphere), sphere[3]}.region();
        source["tumour_mm"] = arguments.option("tumour");
    }
    if (arguments.hasOption("tumour-label"))
    {
        if (setup.tumour)
            throw Error("give the tumour as a sphere (--tumour) or a label (--tumour-label), not both");
        const int value = arguments.hasOption("tumour-value") ? int(parseNumbers(arguments.option("tumour-value"), ',', 1, "tumour-value")[0]) : 0;
        setup.tumour = app::volumeRegion(study, arguments.option("tumour-label"), value);
        source["tumour_label"] = arguments.option("tumour-label") + (value ? ":" + std::to_string(value) : std::string());
        inputs.push_back(arguments.option("tumour-label"));
    }
    // The liver (and the tumour as a label) for territories, coverage and feeders.
    auto valueOption = [&](const char* name) {
        return arguments.hasOption(name) ? int(parseNumbers(arguments.option(name), ',', 1, name)[0]) : 0;
    };
    if (arguments.hasOption("liver-label"))
    {
        const int liverValue = valueOption("liver-value");
        setup.liver = app::sharedLabel(study, arguments.option("liver-label"), liverValue, "liver");
        source["liver_label"] = arguments.option("liver-label") + (liverValue ? ":" + std::to_string(liverValue) : std::string());
        inputs.push_back(arguments.option("liver-label"));
        if (arguments.hasOption("tumour-label"))
            setup.tumourLabel = app::sharedLabel(study, arguments.option("tumour-label"), valueOption("tumour-value"), "tumour");
    }
    else if (arguments.hasOption("liver-value"))
        throw Error("--liver-value needs --liver-label");
    for (const auto& [name, value] : arguments.options)
        if (name == "control")
            setup.controlPointsMm.push_back(point(parseNumbers(value, ',', 3, "control")));
        else if (name == "add-feeder" || name == "remove-feeder")
        {
            std::string& listed = source[name == "add-feeder" ? "feeders_added" : "feeders_removed"];
            listed += (listed.empty() ? "" : ",") + value;
        }
    app::applyRecordedChoices(setup, source);

    sim::network::NetworkRunResult run = sim::network::runNetwork(setup, progress.subRange(0.3, 0.95));
    run.warnings.insert(run.warnings.begin(), warnings.begin(), warnings.end());
    const std::string document = app::networkRunDocument(run, setup.parameters, source);
    const app::NetworkRunIds ids = app::addNetworkRun(study, run, setup.parameters, inputs, source);
    study.save();
    if (arguments.hasOption("out"))
    {
        claimOutputFolder(arguments.option("out"), "run");
        app::writeNetworkRun(arguments.option("out"), run, document);
    }
    progress.report(1.0, "saved");
    std::cout << document.substr(0, document.size() - 1) << ",\n  \"artifact\": \"" << ids.network
              << "\",\n  \"run_artifact\": \"" << ids.run << "\"\n}\n";
    return 0;
}

} // namespace vsim::cli
