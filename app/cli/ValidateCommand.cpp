#include "ValidateCommand.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/FemValidation.h"
#include "vsim/sim/heat/HeatValidation.h"
#include "vsim/sim/network/NetworkValidation.h"
#include "vsim/sim/smoke/SmokeValidation.h"
#include "vsim/sim/sph/SphValidation.h"

#include <nlohmann/json.hpp>

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

std::vector<CaseFamily> caseFamilies()
{
    return {{"fem", sim::fem::femValidationCases(), [](const std::string& c, const Progress& p) { return sim::fem::runFemValidation(c, p); }},
            {"network", sim::network::networkValidationCases(),
             [](const std::string& c, const Progress& p) { return sim::network::runNetworkValidation(c, p); }},
            {"heat", sim::heat::heatValidationCases(),
             [](const std::string& c, const Progress& p) { return sim::heat::runHeatValidation(c, p); }},
            {"sph", sim::sph::sphValidationCases(),
             [](const std::string& c, const Progress& p) { return sim::sph::runSphValidation(c, p); }},
            {"smoke", sim::smoke::smokeValidationCases(),
             [](const std::string& c, const Progress& p) { return sim::smoke::runSmokeValidation(c, p); }}};
}

} // namespace

int validateSolvers(const Arguments& arguments, const Progress& progress)
{
    const std::string requested = arguments.positional.front();
    std::vector<std::pair<std::string, const CaseFamily*>> runs; // case, its family
    const std::vector<CaseFamily> families = caseFamilies();
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
