#include "ValidateCommand.h"

#include "CommandLine.h"

#include "vsim/app/BackendNames.h"
#include "vsim/app/DamBreakValidationRun.h"
#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/sim/fem/FemValidation.h"
#include "vsim/sim/heat/HeatValidation.h"
#include "vsim/sim/network/NetworkValidation.h"
#include "vsim/sim/smoke/SmokeValidation.h"
#include "vsim/sim/sph/SphValidation.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <functional>
#include <iostream>

namespace vsim::cli {

namespace {

/// One solver's validation cases and how to run one of them.
struct CaseFamily
{
    std::string name; ///< as given on the command line: "fem", "network", "heat", "sph", "smoke"
    std::vector<std::string> cases;
    std::function<ValidationResult(const std::string&, const Progress&)> run;
};

/// The options only the dam break takes (`--backend`, `--particles`, `--until`).
const char* const kDamBreakOptions[] = {"backend", "particles", "until"};

/// The sph family: the CPU's cases, then the dam break on the backend the options ask for.
CaseFamily sphFamily(const Arguments& arguments)
{
    std::vector<std::string> cases = sim::sph::sphValidationCases();
    cases.push_back("sph-dambreak");
    const std::string backend = arguments.option("backend", "auto");
    if (!app::isBackendName(backend))
        throw UsageError("--backend: unknown backend '" + backend + "' (auto, cpu, cuda)");
    sim::sph::DamBreakCheckOptions options;
    options.particles = quantityOption(arguments, "particles", "", options.particles);
    options.untilS = quantityOption(arguments, "until", "s", options.untilS);
    return {"sph", cases, [backend, options](const std::string& c, const Progress& p) {
                return c == "sph-dambreak" ? app::validateDamBreak(backend, options, p)
                                           : sim::sph::runSphValidation(c, p);
            }};
}

std::vector<CaseFamily> caseFamilies(const Arguments& arguments)
{
    return {{"fem", sim::fem::femValidationCases(), [](const std::string& c, const Progress& p) { return sim::fem::runFemValidation(c, p); }},
            {"network", sim::network::networkValidationCases(),
             [](const std::string& c, const Progress& p) { return sim::network::runNetworkValidation(c, p); }},
            {"heat", sim::heat::heatValidationCases(),
             [](const std::string& c, const Progress& p) { return sim::heat::runHeatValidation(c, p); }},
            sphFamily(arguments),
            {"smoke", sim::smoke::smokeValidationCases(),
             [](const std::string& c, const Progress& p) { return sim::smoke::runSmokeValidation(c, p); }}};
}

} // namespace

int validateSolvers(const Arguments& arguments, const Progress& progress)
{
    const std::string requested = arguments.positional.front();
    std::vector<std::pair<std::string, const CaseFamily*>> runs; // case, its family
    const std::vector<CaseFamily> families = caseFamilies(arguments);
    std::string familyNames, cases;
    for (const CaseFamily& family : families)
    {
        for (const std::string& name : family.cases)
        {
            if (requested == "all" || requested == family.name || requested == name)
                runs.emplace_back(name, &family);
            cases += ", " + name;
        }
        familyNames += ", " + family.name;
    }
    if (runs.empty())
        throw Error("unknown validation case '" + requested + "' (known: all" + familyNames + cases + ")");
    const bool damBreakAsked = std::any_of(runs.begin(), runs.end(), [](const auto& run) { return run.first == "sph-dambreak"; });
    for (const char* option : kDamBreakOptions)
        if (arguments.hasOption(option) && !damBreakAsked)
            throw UsageError(Pattern{"--%1 applies to sph-dambreak only", {option}});
    // A run of every case leaves the dam break out where it would take hours (no GPU), saying so.
    if (damBreakAsked && requested != "sph-dambreak")
        if (const std::string why = app::whyDamBreakLeftOut(arguments.option("backend", "auto")); !why.empty())
        {
            std::erase_if(runs, [](const auto& run) { return run.first == "sph-dambreak"; });
            std::cout << nlohmann::json{{"case", "sph-dambreak"}, {"left_out", why}}.dump(2) << "\n";
        }
    std::vector<std::string> failures;
    for (std::size_t i = 0; i < runs.size(); ++i)
    {
        const Progress part = progress.subRange(double(i) / runs.size(), double(i + 1) / runs.size());
        const ValidationResult result = runs[i].second->run(runs[i].first, part);
        nlohmann::json figures = nlohmann::json::array();
        for (const ValidationFigure& figure : result.figures)
        {
            figures.push_back({{"name", figure.name},
                               {"measured", figure.measured},
                               {"expected", figure.expected},
                               {"tolerance", figure.tolerance},
                               {"unit", figure.unit},
                               {"passed", figure.passed()}});
            if (!figure.passed())
                failures.push_back(result.name + ": " + figure.name);
        }
        std::cout << nlohmann::json{{"case", result.name},
                                    {"description", result.description},
                                    {"seconds", result.seconds},
                                    {"passed", result.passed()},
                                    {"figures", figures}}
                         .dump(2)
                  << "\n";
    }
    if (!failures.empty())
    {
        std::string list;
        for (const std::string& failure : failures)
            list += (list.empty() ? "" : "; ") + failure;
        throw Error("out of tolerance: " + list);
    }
    return 0;
}

} // namespace vsim::cli
