// Full-size guided segmentation: the patient-like AAA phantom at 512 x 512 x 400 (0.7 x 0.7 x 1 mm), target aorta from
// one point in the sac, then again after moving the point 5 mm (a re-run), `repeats` times each; prints JSON with
// the medians, the phantom's rendering time and the Dice of the aorta and iliac lumen against the truth labels;
// then once from no point (the automatic abdominal aorta point): its Dice and the label's share in bone.
// Usage: bench_guided_segmentation [repeats] [seed]

#include "vsim/dicom/AnatomyPhantom.h"
#include "vsim/imaging/GuidedSegmentation.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

using namespace vsim;

namespace {

double seconds(const std::chrono::steady_clock::time_point& start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    dicom::PhantomOptions options;
    options.style = dicom::PhantomStyle::Patient;
    options.seed = argc > 2 ? std::uint64_t(std::atoll(argv[2])) : 1;
    auto start = std::chrono::steady_clock::now();
    const dicom::AnatomyPhantom phantom = dicom::buildAnatomyPhantom(dicom::PhantomKind::Aaa, options);
    const CtVolume ct = dicom::renderAnatomyCt(phantom, dicom::phantomGeometry(options), options.seed);
    const double renderSeconds = seconds(start);
    const LabelVolume truth = dicom::renderAnatomyLabels(phantom, dicom::phantomGeometry(options));

    const dicom::VesselSegment& aorta = phantom.arteries.segments.front();
    const double peakZ = phantom.measures.at("max_outer_diameter_z_mm");
    const Eigen::Vector3d point = *std::min_element(aorta.points.begin(), aorta.points.end(), [&](auto& a, auto& b) {
        return std::abs(a.z() - peakZ) < std::abs(b.z() - peakZ);
    });
    const ParameterSet parameters(imaging::guidedSegmentationParameters());
    imaging::SegmentationRequest request;
    request.target = imaging::SegmentationTarget::Aorta;
    std::vector<double> first, rerun;
    imaging::SegmentationResult result;
    for (int r = 0; r < repeats; ++r)
    {
        request.includeMm = {point};
        start = std::chrono::steady_clock::now();
        result = imaging::segmentFromPoints(ct, parameters, request);
        first.push_back(seconds(start));
        request.includeMm = {point + Eigen::Vector3d(0, 0, -5)};
        start = std::chrono::steady_clock::now();
        imaging::segmentFromPoints(ct, parameters, request);
        rerun.push_back(seconds(start));
    }
    // Dice over the whole truth lumen (branches beyond 20 mm count against it), and the label's share in bone.
    const auto score = [&](const LabelVolume& label, double& bone) {
        std::size_t both = 0, inLabel = 0, inTruth = 0, inBone = 0;
        for (std::size_t v = 0; v < truth.geometry().voxelCount(); ++v)
        {
            const bool l = label.data()[v] == 1, t = truth.data()[v] == dicom::label::kVesselLumen;
            both += l && t, inLabel += l, inTruth += t, inBone += l && truth.data()[v] == dicom::label::kBone;
        }
        bone = double(inBone) / double(std::max<std::size_t>(inLabel, 1));
        return 2.0 * double(both) / double(inLabel + inTruth);
    };
    double bone = 0.0, autoBone = 0.0;
    const double dice = score(result.label, bone);
    // From no point: the automatic abdominal aorta point (the default of `segment --target aorta`).
    request.includeMm.clear();
    start = std::chrono::steady_clock::now();
    const imaging::SegmentationResult automatic = imaging::segmentFromPoints(ct, parameters, request);
    const double autoSeconds = seconds(start);
    const double autoDice = score(automatic.label, autoBone);
    std::printf("{\"benchmark\": \"guided_segmentation\", \"phantom\": \"aaa patient-like\", \"dims\": [512, 512, 400], "
                "\"spacing_mm\": [0.7, 0.7, 1.0], \"seed\": %llu, \"render_s\": %.2f, \"repeats\": %d, "
                "\"segment_median_s\": %.2f, \"rerun_median_s\": %.2f, \"volume_ml\": %.2f, \"leaks_cut\": %g, "
                "\"dice_all_arteries\": %.4f, \"bone_share\": %.5f, \"work_voxels\": %g, \"automatic_point_s\": %.2f, "
                "\"automatic_point_dice_all_arteries\": %.4f, \"automatic_point_bone_share\": %.5f}\n",
                (unsigned long long)options.seed, renderSeconds, repeats, median(first), median(rerun),
                result.figures.at("volume_ml"), result.figures.at("leaks_cut"), dice, bone,
                result.figures.at("work_voxels"), autoSeconds, autoDice, autoBone);
    return 0;
}
