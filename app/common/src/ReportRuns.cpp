#include "ReportSections.h"

#include "ReportSupport.h"
#include "vsim/app/RunRecord.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Validation.h"
#include "vsim/sim/fem/FemProtocols.h"
#include "vsim/sim/fem/FemValidation.h"
#include "vsim/sim/network/NetworkRun.h"
#include "vsim/sim/network/NetworkValidation.h"
#include "vsim/sim/smoke/SmokeSolver.h"
#include "vsim/sim/smoke/SmokeValidation.h"
#include "vsim/sim/sph/SphSolver.h"
#include "vsim/sim/sph/SphValidation.h"

#include <set>

namespace vsim::app::detail {
namespace {

struct SolverInfo
{
    std::string description;
    std::vector<ParameterSpec> parameters; ///< those the run used
    std::vector<ParameterSpec> declared;   ///< every parameter of the solver
    std::vector<std::string> validationCases;
    std::function<ValidationResult(const std::string&, const Progress&)> validate;
    ValidationConfiguration validation; ///< the settings its validation cases run with
};

SolverInfo solverOf(const study::Artifact& run)
{
    if (run.provenance.command == "simulate fem")
        return {textOr(run.provenance.parameters, "wall_model", "0") == "1"
                    ? localized("Report",
                                "Wall mechanics: quadratic (10-node) tetrahedral FEM, the Raghavan & Vorp 2000 "
                                "hyperelastic AAA wall (nearly incompressible), the blood pressure as a follower "
                                "load on the lumen, ends held; the static equilibrium by Newton's method (GMRES "
                                "preconditioned by a sparse Cholesky or LU factorisation) to the force tolerance. The imaged geometry is taken as unloaded (CT shows "
                                "the vessel at its pressure); the intraluminal thrombus, where the wall mesh has "
                                "it, as its own layer (Wang et al. 2001).")
                    : localized("Report", "Wall mechanics: tetrahedral FEM (co-rotational linear elasticity or St. "
                                          "Venant-Kirchhoff), lumped mass, Rayleigh damping, backward Euler with "
                                          "block-Jacobi preconditioned CG (thesis ch. 4); the physiological protocol's "
                                          "figures from the static equilibrium after the load path."),
                sim::fem::femProtocolParameters(textOr(run.provenance.parameters, "protocol", "physiological")),
                sim::fem::femParameters(),
                sim::fem::femValidationCases(),
                [](const std::string& name, const Progress& p) { return sim::fem::runFemValidation(name, p); },
                sim::fem::femValidationConfiguration()};
    if (run.provenance.command == "simulate sph")
        // The report re-runs the quick cases (seconds); the flow cases (a minute or more each) run in the test suite
        // and with vascusim-cli validate sph-hydrostatic, sph-poiseuille, sph-womersley, sph-mass, sph-stenosis.
        return {localized("Report",
                          "Blood flow: weakly compressible SPH (thesis ch. 5; Liu quartic kernel, Tait equation "
                          "of state, delta-SPH density diffusion, Morris viscosity with no-slip walls whose "
                          "pressure is extrapolated from the blood, leapfrog with an adaptive step) on particles "
                          "seeded in the lumen label; a flow-rate inlet at the largest vessel's end and pressure "
                          "outlets with particle buffers; double precision on the CPU."),
                sim::sph::sphParameters(),
                sim::sph::sphParameters(),
                {"sph-kernel", "sph-fpm"},
                [](const std::string& name, const Progress& p) { return sim::sph::runSphValidation(name, p); },
                {"cpu", 0, 0.0,
                 localized("Report", "the CPU backend in double precision, explicit steps (no linear solves)")}};
    if (run.provenance.command == "simulate smoke")
    {
        const std::vector<ParameterSpec> parameters =
            sim::smoke::smokeParameters(textOr(run.provenance.parameters, "scenario", "ball-drop"));
        return {localized("Report", "Surgical smoke: stable fluids on a MAC grid (thesis ch. 7; semi-Lagrangian velocity "
                                    "advection, conservative limited transport of the smoke, Boussinesq buoyancy, "
                                    "vorticity confinement and vortex particles), the pressure projection by "
                                    "multigrid-preconditioned conjugate gradients; single precision on the CPU."),
                parameters, parameters, sim::smoke::smokeValidationCases(),
                [](const std::string& name, const Progress& p) { return sim::smoke::runSmokeValidation(name, p); },
                sim::smoke::smokeValidationConfiguration()};
    }
    return {localized("Report", "Drug delivery: two-phase homogeneous fluid in a network of conical Hagen-Poiseuille "
                                "pipes, Kirchhoff solve, plug filling (thesis ch. 6)."),
            sim::network::networkParameters(),
            sim::network::networkParameters(),
            sim::network::networkValidationCases(),
            [](const std::string& name, const Progress& p) { return sim::network::runNetworkValidation(name, p); },
            sim::network::networkValidationConfiguration()};
}

/// How the validation's settings differ from the reported run's (backend, iteration cap, tolerance): a sentence
/// for the report, which says so also when nothing differs.
std::string validationAgainstRun(const ValidationConfiguration& validation, const study::Artifact& run)
{
    const auto& recorded = run.provenance.parameters;
    const std::string backend = textOr(recorded, "backend", "cpu");
    std::vector<std::string> differences;
    if (backend != validation.backend)
        differences.push_back(withArguments(localized("Report", "the run used the %1 backend, the cases the %2"),
                                            {backend, validation.backend}));
    const RunStatus status = runStatusOf(run);
    if (status.solves > 0 && status.iterationCap == 0 && validation.iterationCap > 0)
        differences.push_back(withArguments(
            localized("Report", "the run's linear solves were direct (factorised), the cases' iterative (at most %1 "
                                "iterations)"),
            {std::to_string(validation.iterationCap)}));
    if (status.iterationCap > 0 && status.iterationCap < validation.iterationCap)
        differences.push_back(
            withArguments(localized("Report", "the run's solves stopped at %1 iterations, the cases' at %2"),
                          {std::to_string(status.iterationCap), std::to_string(validation.iterationCap)}));
    if (status.tolerance > validation.loosestTolerance && validation.loosestTolerance > 0.0)
        differences.push_back(withArguments(
            localized("Report", "the run solved to a relative residual of %1, the cases to %2 or tighter"),
            {report::formatMetric(status.tolerance), report::formatMetric(validation.loosestTolerance)}));
    const std::string ran = withArguments(localized("Report", "The cases ran %1."), {validation.text});
    if (differences.empty())
        return ran + " " + localized("Report", "That is the configuration of the reported run.");
    std::string listed;
    for (std::size_t i = 0; i < differences.size(); ++i)
        listed += (i ? "; " : "") + differences[i];
    return ran + " " +
           withArguments(localized("Report",
                                   "What differs from the reported run: %1. The cases show the method, not this "
                                   "run's solver settings."),
                         {listed});
}

} // namespace

report::Section runsSection(const std::vector<const study::Artifact*>& runs, const ReportOptions& options,
                            const Progress& progress)
{
    report::Section section{"runs", localized("Report", "Runs: parameters, solver, validation"), {}};
    std::set<std::string> validated; // commands whose solver's cases are in the section
    for (std::size_t i = 0; i < runs.size(); ++i)
    {
        const study::Artifact& run = *runs[i];
        const SolverInfo solver = solverOf(run);
        report::Table summary;
        summary.caption = storedTextForPeople(run.name) + " (" + run.id + ")";
        summary.columns = {localized("Report", "Item"), localized("Report", "Value")};
        const auto& parameters = run.provenance.parameters;
        const std::string protocol = textOr(parameters, "protocol");
        const std::string device = textOr(parameters, "device");
        const RunStatus status = runStatusOf(run);
        summary.rows = {
            {localized("Report", "Solver"), solver.description},
            {localized("Report", "Command"),
             run.provenance.command + (protocol.empty() ? "" : " --protocol " + protocol)},
            {localized("Report", "Backend"),
             textOr(parameters, "backend", "cpu") + (device.empty() ? "" : " (" + device + ")")},
            // The run driver's runs record run_steps and run_wall_seconds; the wall's static solve its own keys.
            {localized("Report", "Steps"),
             textOr(run.attributes, "steps", textOr(run.attributes, "run_steps", localized("Report", "1 (steady solve)")))},
            {localized("Report", "Wall-clock time"),
             [&]
             {
                 auto seconds = runMetric(run, "wall_clock_s", "", "s");
                 if (!seconds)
                     seconds = runMetric(run, "run_wall_seconds", "", "s");
                 return seconds ? seconds->text + " s" : localized("Report", "not recorded");
             }()},
            {localized("Report", "Convergence"), status.convergenceText(true)},
            {localized("Report", "Inputs"),
             [&]
             {
                 std::string list;
                 for (const std::string& input : run.provenance.inputs)
                     list += (list.empty() ? "" : ", ") + input;
                 return list;
             }()},
            {localized("Report", "Made"), withArguments(localized("Report", "%1 by VascuSim %2"),
                                                        {run.provenance.time, run.provenance.softwareVersion})}};
        // The warnings are stored in English: the run status's own is rebuilt, the solvers' are read as stored texts,
        // both in the reader's language.
        const std::string statusWarning = status.warningText(false);
        for (const std::string& warning : run.warnings)
            summary.rows.push_back({localized("Report", "Warning"), !warning.empty() && warning == statusWarning
                                                                        ? status.warningText(true)
                                                                        : storedTextForPeople(warning)});
        section.blocks.push_back(summary);
        section.blocks.push_back(parameterTable(run, solver.parameters, solver.declared,
                                                withArguments(localized("Report", "Parameters of %1"), {run.id})));

        if (!options.validate)
            continue;
        if (!validated.count(run.provenance.command)) // each solver's cases once
        {
            report::Table cases;
            cases.caption = localized("Report", "Validation of this solver in this build (vascusim-cli validate)");
            cases.columns = {localized("Report", "Case"), localized("Report", "What is compared"),
                             localized("Report", "Result")};
            for (std::size_t c = 0; c < solver.validationCases.size(); ++c)
            {
                const Progress part =
                    progress.subRange((i + double(c) / solver.validationCases.size()) / runs.size(),
                                      (i + double(c + 1) / solver.validationCases.size()) / runs.size());
                const ValidationResult result = solver.validate(solver.validationCases[c], part);
                cases.rows.push_back({result.name, storedTextForPeople(result.description),
                                      result.passed() ? localized("Report", "passed") : localized("Report", "FAILED")});
            }
            validated.insert(run.provenance.command);
            section.blocks.push_back(cases);
        }
        section.blocks.push_back(report::Paragraph{validationAgainstRun(solver.validation, run)});
    }
    return section;
}

} // namespace vsim::app::detail
