#include "vsim/study/RunSeries.h"

#include "BundleFiles.h"
#include "RunFiles.h"

namespace vsim::study {

void writeRunSeries(const std::filesystem::path& folder, const SolverRun& run, const std::string& metricsJson)
{
    std::filesystem::create_directories(folder);
    writeRunFolder(run, folder / "run.json");
    writeFileAtomically(folder / "metrics.json", metricsJson + "\n");
}

} // namespace vsim::study
