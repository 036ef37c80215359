// DICOM import speed and memory against dcm2niix, in the same run on the same files.
//
//   bench_dicom_import <vascusim-cli> <dcm2niix> <work folder> [repetitions=5]
//
// Writes the full-size aaa phantom (512 x 512 x 400, 0.7 x 0.7 x 1.0 mm, explicit little endian) once, then
// alternates `vascusim-cli import <series> --study <new study>` (scan, decode, HU, write the study's NRRD with
// fsync) and `dcm2niix -z n` (scan, decode, write an uncompressed NIfTI) as child processes, timing each and
// reading its peak resident memory from wait4(). Prints one JSON object with the medians; exit 1 when VascuSim is
// slower than dcm2niix or exceeds 1.5 x the voxel bytes + 100 MB.

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Run
{
    double seconds = 0;
    double peakMiB = 0;
    int status = -1;
};

Run runChild(const std::vector<std::string>& command)
{
    std::vector<char*> argv;
    for (const std::string& word : command)
        argv.push_back(const_cast<char*>(word.c_str()));
    argv.push_back(nullptr);
    const auto start = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid == 0)
    {
        if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr))
            _exit(126);
        execv(argv[0], argv.data());
        _exit(127);
    }
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    Run run;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    run.peakMiB = double(usage.ru_maxrss) / 1024.0; // ru_maxrss is in KiB on Linux
    run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return run;
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 4)
    {
        std::cerr << "usage: bench_dicom_import <vascusim-cli> <dcm2niix> <work folder> [repetitions]\n";
        return 2;
    }
    const std::string cli = argv[1], dcm2niix = argv[2];
    const fs::path work = argv[3];
    const int repetitions = argc > 4 ? std::max(1, std::atoi(argv[4])) : 5;
    const fs::path phantom = work / "aaa-512";
    if (!fs::exists(phantom / "truth.json"))
    {
        fs::remove_all(phantom);
        const Run written = runChild({cli, "phantom", "aaa", "--out", phantom.string()});
        if (written.status != 0)
        {
            std::cerr << "cannot write the phantom\n";
            return 1;
        }
    }
    const fs::path series = phantom / "dicom";
    std::vector<double> oursSeconds, oursMiB, theirsSeconds, theirsMiB;
    for (int r = 0; r < repetitions + 1; ++r) // the first round warms the page cache and is not counted
    {
        const fs::path study = work / "bench.vsim", nifti = work / "dcm2niix";
        fs::remove_all(study);
        fs::remove_all(nifti);
        fs::create_directories(nifti);
        const Run ours = runChild({cli, "import", series.string(), "--study", study.string()});
        const Run theirs = runChild({dcm2niix, "-z", "n", "-b", "n", "-o", nifti.string(), series.string()});
        if (ours.status != 0 || theirs.status != 0)
        {
            std::cerr << "an import failed: vascusim-cli " << ours.status << ", dcm2niix " << theirs.status << "\n";
            return 1;
        }
        if (r == 0)
            continue;
        oursSeconds.push_back(ours.seconds);
        oursMiB.push_back(ours.peakMiB);
        theirsSeconds.push_back(theirs.seconds);
        theirsMiB.push_back(theirs.peakMiB);
    }
    const double voxelMiB = 512.0 * 512.0 * 400.0 * 2.0 / (1024.0 * 1024.0);
    const double budgetMiB = 1.5 * voxelMiB + 100.0;
    const double oursTime = median(oursSeconds), theirTime = median(theirsSeconds);
    const double oursPeak = *std::max_element(oursMiB.begin(), oursMiB.end());
    std::printf("{\"case\": \"dicom_import_aaa_512x512x400_explicit_le\", \"repetitions\": %d, "
                "\"vascusim_median_s\": %.3f, \"dcm2niix_median_s\": %.3f, \"speed_ratio\": %.2f, "
                "\"vascusim_peak_rss_mib\": %.1f, \"dcm2niix_peak_rss_mib\": %.1f, \"voxel_mib\": %.1f, "
                "\"memory_budget_mib\": %.1f}\n",
                repetitions, oursTime, theirTime, theirTime / oursTime, oursPeak,
                *std::max_element(theirsMiB.begin(), theirsMiB.end()), voxelMiB, budgetMiB);
    return oursTime <= theirTime && oursPeak <= budgetMiB ? 0 : 1;
}
