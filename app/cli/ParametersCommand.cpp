// `vascusim-cli parameters [TABLE] [--json]`: every parameter a `--param key=value` or a GUI form takes, with
// its unit, range, default and meaning (ParameterCatalogue.h).
#include "CliCommands.h"

#include "vsim/app/ParameterCatalogue.h"
#include "vsim/core/Error.h"

#include <iostream>

namespace vsim::cli {
namespace {

std::string tableNames(const std::vector<app::ParameterTable>& tables)
{
    std::string names;
    for (const app::ParameterTable& table : tables)
        names += (names.empty() ? "" : ", ") + table.name;
    return names;
}

void printTable(const app::ParameterTable& table)
{
    std::cout << table.name << "\n";
    for (const ParameterSpec& spec : table.specs)
    {
        const std::string unit = spec.unit.empty() ? "" : " " + spec.unit;
        std::cout << "  " << spec.key << " = " << numberText(spec.defaultValue) << unit << "  ["
                  << numberText(spec.minimum) << ", " << numberText(spec.maximum) << "]"
                  << (spec.kind == ParameterSpec::Kind::Integer ? " integer" : "") << "\n      " << spec.label
                  << ": " << spec.description << "\n";
    }
}

} // namespace

int printParameters(const Arguments& arguments)
{
    std::vector<app::ParameterTable> tables = app::parameterCatalogue();
    if (!arguments.positional.empty())
    {
        const std::string wanted = arguments.positional[0];
        std::erase_if(tables, [&](const app::ParameterTable& table) { return table.name != wanted; });
        if (tables.empty())
            throw Error("parameters: no table '" + wanted + "' (" + tableNames(app::parameterCatalogue()) +
                        ")");
    }
    if (arguments.hasOption("json"))
    {
        std::cout << app::parameterCatalogueJson(tables) << std::endl;
        return 0;
    }
    for (const app::ParameterTable& table : tables)
        printTable(table);
    return 0;
}

} // namespace vsim::cli
