#include "vsim/study/RunSeries.h"

#include "ArtifactFiles.h"
#include "vsim/core/Error.h"

#include <cstdio>
#include <fstream>

namespace vsim::study {
namespace {

/// Removes the frames of an earlier, longer run in the same run folder (frame_NNNN.vtu from `first` on): only files
/// of the names this writer gives, so that series.pvd and frames/ agree.
void removeOlderFrames(const std::filesystem::path& frames, std::size_t first)
{
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(frames, error))
    {
        const std::string name = entry.path().filename().string();
        unsigned index = 0;
        char tail[8] = {};
        if (entry.is_regular_file() && name.size() == 14 && std::sscanf(name.c_str(), "frame_%4u.%3s", &index, tail) == 2 &&
            std::string(tail) == "vtu" && index >= first)
            std::filesystem::remove(entry.path(), error);
    }
}

} // namespace

void writeRunSeries(const std::filesystem::path& folder, const std::vector<TetMesh>& frames,
                    const std::vector<double>& times, const std::string& metricsJson)
{
    if (frames.size() != times.size())
        throw Error("a run series needs one time per frame");
    std::filesystem::create_directories(folder / "frames");
    removeOlderFrames(folder / "frames", frames.size());
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
