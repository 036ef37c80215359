#include "ReportSections.h"

#include "ReportSupport.h"
#include "vsim/core/Validation.h"
#include "vsim/sim/fem/FemProtocols.h"
#include "vsim/sim/fem/FemValidation.h"
#include "vsim/sim/network/NetworkRun.h"
#include "vsim/sim/network/NetworkValidation.h"

#include <map>

namespace vsim::app::detail {
namespace {

struct SolverInfo
{
    std::string description;
    std::vector<ParameterSpec> parameters;
    std::vector<std::string> validationCases;
    std::function<ValidationResult(const std::string&, const Progress&)> validate;
};

SolverInfo solverOf(const study::Artifact& run)
{
    if (run.provenance.command == "simulate fem")
        return {"Wall mechanics: tetrahedral FEM (co-rotational linear elasticity or St. Venant-Kirchhoff), lumped "
                "mass, Rayleigh damping, backward Euler with block-Jacobi preconditioned CG (thesis ch. 4).",
                sim::fem::femParameters(), sim::fem::femValidationCases(),
                [](const std::string& name, const Progress& p) { return sim::fem::runFemValidation(name, p); }};
    return {"Drug delivery: two-phase homogeneous fluid in a network of conical Hagen-Poiseuille pipes, Kirchhoff "
            "solve, plug filling (thesis ch. 6).",
            sim::network::networkParameters(), sim::network::networkValidationCases(),
            [](const std::string& name, const Progress& p) { return sim::network::runNetworkValidation(name, p); }};
}

} // namespace

report::Section runsSection(const std::vector<const study::Artifact*>& runs, const ReportOptions& options,
                            const Progress& progress)
{
    report::Section section{"runs", "Runs: parameters, solver, validation", {}};
    std::map<std::string, report::Table> validated; // by command: each solver's cases once
    for (std::size_t i = 0; i < runs.size(); ++i)
    {
        const study::Artifact& run = *runs[i];
        const SolverInfo solver = solverOf(run);
        report::Table summary;
        summary.caption = run.name + " (" + run.id + ")";
        summary.columns = {"Item", "Value"};
        const auto& parameters = run.provenance.parameters;
        const std::string protocol = textOr(parameters, "protocol");
        const std::string device = textOr(parameters, "device");
        summary.rows = {{"Solver", solver.description},
                        {"Command", run.provenance.command + (protocol.empty() ? "" : " --protocol " + protocol)},
                        {"Backend", textOr(parameters, "backend", "cpu") + (device.empty() ? "" : " (" + device + ")")},
                        {"Steps", textOr(run.attributes, "steps", "1 (steady solve)")},
                        {"Wall-clock time", textOr(run.attributes, "wall_clock_s", "not recorded") +
                                                (run.attributes.count("wall_clock_s") ? " s" : "")},
                        {"Inputs", [&] {
                             std::string list;
                             for (const std::string& input : run.provenance.inputs)
                                 list += (list.empty() ? "" : ", ") + input;
                             return list;
                         }()},
                        {"Made", run.provenance.time + " by VascuSim " + run.provenance.softwareVersion}};
        for (const std::string& warning : run.warnings)
            summary.rows.push_back({"Warning", warning});
        section.blocks.push_back(summary);
        section.blocks.push_back(parameterTable(run, solver.parameters, "Parameters of " + run.id));

        if (!options.validate || validated.count(run.provenance.command))
            continue;
        report::Table cases;
        cases.caption = "Validation of this solver in this build (vascusim-cli validate)";
        cases.columns = {"Case", "What is compared", "Result"};
        for (std::size_t c = 0; c < solver.validationCases.size(); ++c)
        {
            const Progress part = progress.subRange((i + double(c) / solver.validationCases.size()) / runs.size(),
                                                    (i + double(c + 1) / solver.validationCases.size()) / runs.size());
            const ValidationResult result = solver.validate(solver.validationCases[c], part);
            cases.rows.push_back({result.name, result.description, result.passed() ? "passed" : "FAILED"});
        }
        validated[run.provenance.command] = cases;
        section.blocks.push_back(cases);
    }
    return section;
}

} // namespace vsim::app::detail
