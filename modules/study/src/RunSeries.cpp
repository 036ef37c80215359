#include "vsim/study/RunSeries.h"

#include "ArtifactFiles.h"
#include "vsim/core/Error.h"

#include <cstdio>
#include <fstream>

namespace vsim::study {

void writeRunSeries(const std::filesystem::path& folder, const std::vector<TetMesh>& frames,
                    const std::vector<double>& times, const std::string& metricsJson)
{
    if (frames.size() != times.size())
        throw Error("a run series needs one time per frame");
    std::filesystem::create_directories(folder / "frames");
    std::ofstream series(folder / "series.pvd", std::ios::trunc);
    series << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
    for (std::size_t i = 0; i < frames.size(); ++i)
    {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%04zu.vtu", i);
        writeArtifactFile(frames[i], folder / "frames" / name);
        series << "    <DataSet timestep=\"" << times[i] << "\" file=\"frames/" << name << "\"/>\n";
    }
    series << "  </Collection>\n</VTKFile>\n";
    std::ofstream metrics(folder / "metrics.json", std::ios::trunc);
    metrics << metricsJson << "\n";
    if (!series.flush() || !metrics.flush())
        throw Error("cannot write the run series", {{"folder", folder.string()}});
}

} // namespace vsim::study
