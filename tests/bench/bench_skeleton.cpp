// Skeletonization speed against scikit-image, on the same mask in the same run.
//
//   bench_skeleton <skimage_skeleton.py> <work folder> [repetitions=3]
//
// Renders the default 512 x 512 x 400 aaa phantom (20 HU noise), segments it with default parameters, crops the
// label to its bounding box (+1 voxel) and writes it raw; then times VascuSim's thinning + VDSM (and the whole
// skeleton graph) and runs skeletonize_3d (Debian python3-skimage) on the same file. Prints one JSON object with
// the medians and both skeletons' crowded-voxel counts; exit 1 unless ours is at least 3x faster and unit-width.

#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/Skeletonization.h"
#include "vsim/imaging/VesselSegmentation.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace vsim;

namespace {

double seconds(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

/// The label cropped to the bounding box of its 1-voxels plus one voxel.
LabelVolume cropped(const LabelVolume& label)
{
    const auto& d = label.geometry().dims;
    std::array<int, 3> low{d[0], d[1], d[2]}, high{0, 0, 0};
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
                if (label.at(i, j, k))
                    low = {std::min(low[0], i), std::min(low[1], j), std::min(low[2], k)},
                    high = {std::max(high[0], i), std::max(high[1], j), std::max(high[2], k)};
    VolumeGeometry geometry = label.geometry();
    std::array<int, 3> start{};
    for (int a = 0; a < 3; ++a)
    {
        start[a] = std::max(0, low[a] - 1);
        geometry.dims[a] = std::min(d[a] - 1, high[a] + 1) - start[a] + 1;
    }
    geometry.origin = label.geometry().indexToPatient(Eigen::Vector3d(start[0], start[1], start[2]));
    LabelVolume out(geometry);
    for (int k = 0; k < geometry.dims[2]; ++k)
        for (int j = 0; j < geometry.dims[1]; ++j)
            for (int i = 0; i < geometry.dims[0]; ++i)
                out.at(i, j, k) = label.at(start[0] + i, start[1] + j, start[2] + k);
    return out;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 3)
    {
        std::cerr << "usage: bench_skeleton <skimage_skeleton.py> <work folder> [repetitions]\n";
        return 2;
    }
    const std::string script = argv[1];
    const std::filesystem::path work = argv[2];
    const int repetitions = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;
    std::filesystem::create_directories(work);

    const dicom::PhantomOptions options;
    const dicom::PhantomModel model = dicom::buildPhantomModel(dicom::PhantomKind::Aaa, options);
    const CtVolume ct = dicom::renderPhantomCt(model, dicom::stackOf(dicom::phantomGeometry(options)), options);
    auto start = std::chrono::steady_clock::now();
    const LabelVolume label = imaging::segmentVessels(ct, ParameterSet(imaging::segmentationParameters())).label;
    const double segmentSeconds = seconds(start);
    const LabelVolume mask = cropped(label);

    std::vector<double> thinTimes, graphTimes;
    std::size_t ourCrowded = 0, ourVoxels = 0;
    for (int r = 0; r < repetitions; ++r)
    {
        start = std::chrono::steady_clock::now();
        LabelVolume skeleton = imaging::thinToCurves(mask, 1);
        imaging::removeCrowdedPoints(skeleton, &mask);
        thinTimes.push_back(seconds(start));
        ourCrowded = imaging::countCrowdedVoxels(skeleton);
        ourVoxels = std::size_t(std::count(skeleton.data(), skeleton.data() + skeleton.size(), 1));
        start = std::chrono::steady_clock::now();
        imaging::extractSkeleton(mask, 1, ParameterSet(imaging::skeletonParameters()));
        graphTimes.push_back(seconds(start));
    }

    const std::filesystem::path raw = work / "aaa-mask.raw";
    std::ofstream(raw, std::ios::binary).write(reinterpret_cast<const char*>(mask.data()), std::streamsize(mask.size()));
    const auto& d = mask.geometry().dims;
    const std::string command = "/usr/bin/python3 " + script + " " + raw.string() + " " + std::to_string(d[0]) + " " +
                                std::to_string(d[1]) + " " + std::to_string(d[2]) + " " + std::to_string(repetitions);
    std::string reference;
    if (FILE* pipe = popen(command.c_str(), "r"))
    {
        char buffer[512];
        while (std::fgets(buffer, sizeof buffer, pipe))
            reference += buffer;
        if (pclose(pipe) != 0)
            reference.clear();
    }
    if (reference.empty())
    {
        std::cerr << "the scikit-image reference failed (is python3-skimage installed?)\n";
        return 1;
    }
    const auto field = [&](const std::string& key) {
        const auto at = reference.find("\"" + key + "\": ");
        return at == std::string::npos ? -1.0 : std::stod(reference.substr(at + key.size() + 4));
    };
    const double ours = median(thinTimes), theirs = field("skimage_median_s");
    std::printf("{\"case\": \"skeleton_aaa_512x512x400\", \"mask\": [%d, %d, %d], \"repetitions\": %d, "
                "\"segment_s\": %.2f, \"vascusim_thin_vdsm_median_s\": %.3f, \"vascusim_graph_median_s\": %.3f, "
                "\"skimage_median_s\": %.3f, \"speedup\": %.1f, \"vascusim_skeleton_voxels\": %zu, "
                "\"vascusim_crowded_voxels\": %zu, \"skimage_skeleton_voxels\": %.0f, \"skimage_crowded_voxels\": %.0f}\n",
                d[0], d[1], d[2], repetitions, segmentSeconds, ours, median(graphTimes), theirs, theirs / ours, ourVoxels,
                ourCrowded, field("skimage_skeleton_voxels"), field("skimage_crowded_voxels"));
    return theirs >= 3.0 * ours && ourCrowded == 0 ? 0 : 1;
}
