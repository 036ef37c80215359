#include "SmokeCommand.h"

#include "CliSupport.h"
#include "vsim/app/SmokePipeline.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/study/RunSeries.h"

#include <iostream>

namespace vsim::cli {

int simulateSmoke(const Arguments& arguments, const Progress& progress)
{
    const std::string scenario = arguments.option("scenario", "ball-drop");
    app::SmokeSetup setup = app::smokeSetup(scenario);
    setup.backend = arguments.option("backend", "auto");
    if (setup.backend != "cpu" && setup.backend != "auto" && setup.backend != "cuda")
        throw UsageError("--backend: auto, cpu or cuda, not '" + setup.backend + "'");
    if (arguments.hasOption("out"))
        checkOutputFolder(arguments.option("out"), "run");
    applyParameters(arguments, setup.parameters);
    if (arguments.hasOption("grid"))
        setup.parameters.set("grid_cells", parseNumbers(arguments.option("grid"), ',', 1, "grid")[0]);
    if (arguments.hasOption("particles"))
        setup.parameters.set("particles", parseNumbers(arguments.option("particles"), ',', 1, "particles")[0]);
    if (arguments.hasOption("frames"))
    {
        const double frames = parseNumbers(arguments.option("frames"), ',', 1, "frames")[0];
        if (!(frames >= 1.0 && frames <= 10000.0))
            throw UsageError("--frames: 1 to 10000");
        setup.frames = int(frames);
    }
    study::Study study = openStudyForWriting(arguments);
    const app::SmokeRun run = app::runSmoke(study, setup, progress.subRange(0.0, 0.95));
    const std::string document = app::smokeDocument(run);
    const std::string runId = app::addSmokeRun(study, run);
    study.save();
    if (arguments.hasOption("out"))
    {
        claimOutputFolder(arguments.option("out"), "run");
        study::writeRunSeries(arguments.option("out"), run.run, document);
    }
    progress.report(1.0, "saved");
    std::cout << document.substr(0, document.size() - 2) << ",\n  \"run_artifact\": \"" << runId << "\"\n}\n";
    return runExitCode(run.run.status, runId);
}

} // namespace vsim::cli
