#include "ValidateCommand.h"

#include "vsim/core/Error.h"
#include "vsim/sim/fem/FemValidation.h"
#include "vsim/sim/network/NetworkValidation.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace vsim::cli {

int validateSolvers(const Arguments& arguments, const Progress& progress)
{
    const std::string requested = arguments.positional.front();
    const std::vector<std::string> fem = sim::fem::femValidationCases(),
                                   network = sim::network::networkValidationCases();
    std::vector<std::string> names{requested};
    if (requested == "fem" || requested == "network" || requested == "all")
    {
        names.clear();
        if (requested != "network")
            names.insert(names.end(), fem.begin(), fem.end());
        if (requested != "fem")
            names.insert(names.end(), network.begin(), network.end());
    }
    std::vector<std::string> failures;
    for (std::size_t i = 0; i < names.size(); ++i)
    {
        const Progress part = progress.subRange(double(i) / names.size(), double(i + 1) / names.size());
        const ValidationResult result = names[i].rfind("network-", 0) == 0
                                            ? sim::network::runNetworkValidation(names[i], part)
                                            : sim::fem::runFemValidation(names[i], part);
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
