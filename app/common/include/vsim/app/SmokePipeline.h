#pragma once

// Surgical smoke in a study (issue 21): a scenario's scene placed on the study's anatomy where it has one (the EVH
// tunnel around the longest segment of the newest centerlines; the liver-ablation dome over the newest liver label,
// else the box phantom), run on the run driver (sim/smoke/SmokeSolver.h), and kept as a Run artifact with the
// endoscope's obscuration curve and times. The scenes are illustrative (SmokeScenes.h says what is synthetic).

#include "vsim/core/Parameters.h"
#include "vsim/core/Progress.h"
#include "vsim/core/SolverRun.h"
#include "vsim/sim/smoke/SmokeSolver.h"
#include "vsim/study/Study.h"

#include <string>
#include <utility>
#include <vector>

namespace vsim::app {

struct SmokeSetup
{
    std::string scenario = "ball-drop"; ///< sim::smoke::smokeScenarios()
    ParameterSet parameters{sim::smoke::smokeParameters("ball-drop")};
    int frames = 20; ///< frames over the run
    std::string backend = "auto"; ///< auto (the GPU when present), cpu, cuda
};

struct SmokeRun
{
    SolverRun run;
    std::string scenario, description;
    std::vector<std::string> inputs; ///< the study's artifacts the scene was placed on
    std::vector<std::pair<double, double>> obscuration; ///< (s, obscured fraction)
    ParameterSet parameters{sim::smoke::smokeParameters("ball-drop")};
    std::string grid; ///< "64 x 64 x 64 cells of 15.6 mm"
    std::string backend = "cpu"; ///< where it ran: cpu or cuda
    std::string device;          ///< the GPU, when on cuda
    std::vector<std::string> warnings;
};

/// The setup with `scenario`'s parameter defaults. Throws vsim::Error for an unknown scenario.
SmokeSetup smokeSetup(const std::string& scenario);

/// Builds the scene on the study and runs it. Throws vsim::Error when the scenario needs what the study lacks
/// (evh: centerlines), for an unknown backend, and for cuda without a device.
SmokeRun runSmoke(const study::Study& study, const SmokeSetup& setup, const Progress& progress = {});

/// The run's document (the CLI's output, the run folder's metrics.json).
std::string smokeDocument(const SmokeRun& run);

/// Adds the run to the study ("simulate smoke"): its frames, metrics, the obscuration curve as the attribute
/// "obscuration_curve" (JSON [[s, fraction], ...]); returns its id.
std::string addSmokeRun(study::Study& study, const SmokeRun& run);

} // namespace vsim::app
