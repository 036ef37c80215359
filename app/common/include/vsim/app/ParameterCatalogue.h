#pragma once

#include "vsim/core/Parameters.h"

#include <string>
#include <vector>

namespace vsim::app {

/// One declared parameter table: the step it tunes and its declarations (Parameters.h).
struct ParameterTable
{
    std::string name; ///< the step, as `vascusim-cli parameters NAME` takes it, e.g. "segmentation"
    std::vector<ParameterSpec> specs;
};

/// Every parameter table of VascuSim, in workflow order: what `vascusim-cli parameters` lists, what the GUI's
/// forms show and what the translations must cover (translations/parameter_texts.cpp is written from it).
std::vector<ParameterTable> parameterCatalogue();

/// The catalogue as JSON: [{"table": name, "parameters": [{key, label, unit, default, minimum, maximum,
/// group, description, kind}]}].
std::string parameterCatalogueJson(const std::vector<ParameterTable>& tables);

} // namespace vsim::app
