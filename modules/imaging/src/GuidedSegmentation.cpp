#include "vsim/imaging/GuidedSegmentation.h"

#include "GuidedHelpers.h"
#include "VesselPaths.h"
#include "WaveFront.h"

#include "vsim/core/Error.h"
#include "vsim/core/Hounsfield.h"
#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace vsim::imaging {
namespace {

using Eigen::Vector3d;
using detail::mmText;

/// Enhanced parenchyma stays below this; brighter voxels around a point are other contrast-filled blood or bone.
constexpr double kSoftTissueCeilingHu = 200.0;
/// Voxels touching a voxel this far above a front's window are bone or calcium, not blood.
constexpr double kBoneMarginHu = 150.0;
constexpr double kCoreRadiusMm = 5.0;   // include points in lumens at least this wide get a core level (hysteresis)
constexpr double kCoreFraction = 0.6;  // the core level: this far from the lower level to the blood
/// Target hepatic: the hepatic arteries are under 8 mm across (the common hepatic artery of adults 4-6 mm, e.g.
/// Song et al., Radiology 2010 on celiac variants): a point centred into a wider lumen was pulled into a vein.
constexpr double kHepaticArteryRadiusMm = 4.0;
/// The thin-vessel level stays this many standard deviations of the smoothed tissue above the tissue: a front
/// following a dim tip never crosses parenchyma on its noise.
constexpr double kThinNoiseMultiple = 4.0;

/// The noise of the dominant tissue among `values`: their robust standard deviation (1.4826 x the median absolute
/// deviation from the median), three times over the values within 2.5 of it from the median (a shell holding liver,
/// fat and a vein mixes levels; its dominant tissue's own spread is the noise).
double dominantSpread(std::vector<double> values)
{
    const auto medianOf = [](std::vector<double> v) {
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
        return v[v.size() / 2];
    };
    double spread = 0.0;
    for (int pass = 0; pass < 3 && values.size() >= 8; ++pass)
    {
        const double level = medianOf(values);
        std::vector<double> deviations;
        for (double v : values)
            deviations.push_back(std::abs(v - level));
        spread = 1.4826 * medianOf(deviations);
        std::vector<double> kept;
        for (double v : values)
            if (std::abs(v - level) <= 2.5 * spread)
                kept.push_back(v);
        values = std::move(kept);
    }
    return spread;
}

/// Moves an include point to the middle of its lumen: hill-climbing on the chamfer distance (mm) to the nearest
/// voxel below the window, within 15 mm; sets the inscribed radius there. A click near the wall of a small artery
/// beside a large vein stays in the artery (the climb stops at the first ridge).
void centreInLumen(const CtVolume& ct, detail::FrontSeed& seed)
{
    const VolumeGeometry& g = ct.geometry();
    const Vector3d s = g.spacing, index = g.patientToIndex(seed.pointMm);
    std::array<int, 3> low{}, extent{};
    for (int a = 0; a < 3; ++a)
    {
        low[a] = std::max(0, int(std::lround(index[a] - 15.0 / s[a])));
        extent[a] = std::min(g.dims[a] - 1, int(std::lround(index[a] + 15.0 / s[a]))) - low[a] + 1;
    }
    const auto at = [&](int i, int j, int k) {
        return static_cast<std::size_t>(i) + static_cast<std::size_t>(extent[0]) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(extent[1]) * static_cast<std::size_t>(k));
    };
    std::vector<float> distance(static_cast<std::size_t>(extent[0]) * static_cast<std::size_t>(extent[1]) *
                                static_cast<std::size_t>(extent[2]));
    for (int k = 0; k < extent[2]; ++k)
        for (int j = 0; j < extent[1]; ++j)
            for (int i = 0; i < extent[0]; ++i)
                distance[at(i, j, k)] = detail::smoothedHu(ct, i + low[0], j + low[1], k + low[2]) >= seed.lowerHu ? 1e6f : 0.0f;
    // Two-pass chamfer distance with the 26-neighbourhood's true step lengths.
    for (int pass = 0; pass < 2; ++pass)
        for (int n = 0; n < extent[0] * extent[1] * extent[2]; ++n)
        {
            const int m = pass == 0 ? n : extent[0] * extent[1] * extent[2] - 1 - n;
            const int i = m % extent[0], j = (m / extent[0]) % extent[1], k = m / (extent[0] * extent[1]);
            float& d = distance[std::size_t(m)];
            if (d == 0.0f)
                continue;
            for (int dk = -1; dk <= 1; ++dk)
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di)
                    {
                        const int ii = i + di, jj = j + dj, kk = k + dk;
                        const bool before = pass == 0 ? (dk < 0 || (dk == 0 && (dj < 0 || (dj == 0 && di < 0))))
                                                      : (dk > 0 || (dk == 0 && (dj > 0 || (dj == 0 && di > 0))));
                        if (!before || ii < 0 || jj < 0 || kk < 0 || ii >= extent[0] || jj >= extent[1] || kk >= extent[2])
                            continue;
                        d = std::min(d, distance[at(ii, jj, kk)] + float(Vector3d(di * s.x(), dj * s.y(), dk * s.z()).norm()));
                    }
        }
    int ci = std::clamp(int(std::lround(index.x())) - low[0], 0, extent[0] - 1);
    int cj = std::clamp(int(std::lround(index.y())) - low[1], 0, extent[1] - 1);
    int ck = std::clamp(int(std::lround(index.z())) - low[2], 0, extent[2] - 1);
    for (bool moved = true; moved;)
    {
        moved = false;
        int bi = ci, bj = cj, bk = ck;
        for (int dk = -1; dk <= 1; ++dk)
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di)
                {
                    const int ii = ci + di, jj = cj + dj, kk = ck + dk;
                    if (ii >= 0 && jj >= 0 && kk >= 0 && ii < extent[0] && jj < extent[1] && kk < extent[2] &&
                        distance[at(ii, jj, kk)] > distance[at(bi, bj, bk)])
                        bi = ii, bj = jj, bk = kk;
                }
        if (bi != ci || bj != cj || bk != ck)
            ci = bi, cj = bj, ck = bk, moved = true;
    }
    seed.pointMm = g.indexToPatient(Vector3d(ci + low[0], cj + low[1], ck + low[2]));
    seed.inscribedRadiusMm = std::min(15.0, double(distance[at(ci, cj, ck)]));
}

/// The intensity window of a point: blood = the brightest smoothed HU within 1.5 mm, tissue = the upper quartile of
/// the HU of a 6 mm shell 3 mm beyond the lumen's rough radius below blood - 60 HU (and above -200 HU: no fat or air), the window from half-way
/// between them to blood + margin; include points are then moved to the middle of their lumen.
detail::FrontSeed seedWindow(const CtVolume& ct, const Vector3d& point, bool include, double thinFraction)
{
    const VolumeGeometry& g = ct.geometry();
    const Vector3d index = g.patientToIndex(point);
    const int ci = int(std::lround(index.x())), cj = int(std::lround(index.y())), ck = int(std::lround(index.z()));
    if (!g.contains(ci, cj, ck))
        throw Error(Pattern{"the point %1 lies outside the image; pick it on the images", {mmText(point)}});
    const Vector3d s = g.spacing;
    double blood = -1e9;
    const auto forBall = [&](double radius, const auto& visit) {
        const int ri = int(std::ceil(radius / s.x())), rj = int(std::ceil(radius / s.y())), rk = int(std::ceil(radius / s.z()));
        for (int k = std::max(0, ck - rk); k <= std::min(g.dims[2] - 1, ck + rk); ++k)
            for (int j = std::max(0, cj - rj); j <= std::min(g.dims[1] - 1, cj + rj); ++j)
                for (int i = std::max(0, ci - ri); i <= std::min(g.dims[0] - 1, ci + ri); ++i)
                    visit(i, j, k, Vector3d((i - ci) * s.x(), (j - cj) * s.y(), (k - ck) * s.z()).norm());
    };
    forBall(1.5, [&](int i, int j, int k, double d) {
        if (d <= 1.5)
            blood = std::max(blood, detail::smoothedHu(ct, i, j, k));
    });
    // The lumen's rough radius: the median distance, over the 26 directions, to where the HU falls 100 below blood.
    std::vector<double> reach;
    for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
            {
                if (!di && !dj && !dk)
                    continue;
                const Vector3d direction = Vector3d(di, dj, dk).normalized();
                double r = 0.5;
                for (; r < 40.0; r += 0.5)
                {
                    const Vector3d q = g.patientToIndex(point + r * direction);
                    const int qi = int(std::lround(q.x())), qj = int(std::lround(q.y())), qk = int(std::lround(q.z()));
                    if (!g.contains(qi, qj, qk) || ct.at(qi, qj, qk) < blood - 100.0)
                        break;
                }
                reach.push_back(r);
            }
    std::nth_element(reach.begin(), reach.begin() + std::ptrdiff_t(reach.size() / 2), reach.end());
    const double shellInner = reach[reach.size() / 2] + 1.5, shellOuter = shellInner + 4.0;
    std::vector<std::array<int, 3>> shell;
    forBall(shellOuter, [&](int i, int j, int k, double d) {
        if (d >= shellInner && d <= shellOuter && (i + j + k) % 2 == 0)
            shell.push_back({i, j, k});
    });
    std::vector<double> tissue, tissueSmoothed;
    for (const auto& [i, j, k] : shell) // soft tissue: no fat, air or lung, and no other contrast-filled blood (< 200 HU)
        if (const double hu = ct.at(i, j, k); hu > -200.0 && hu < std::min(blood - 60.0, kSoftTissueCeilingHu))
            tissue.push_back(hu), tissueSmoothed.push_back(detail::smoothedHu(ct, i, j, k));
    // An exclude point inside a chamber may have no soft tissue in its shell: its window then reaches 300 HU down.
    if (tissue.size() < 20 && include)
        throw Error(Pattern{"no tissue darker than the point %1 around it (%2 HU): is it inside a vessel, and is the "
                            "image contrast-enhanced CT?",
                            {mmText(point), std::to_string(int(blood))}});
    double tissueHu = blood - 300.0;
    if (tissue.size() >= 20)
    {
        // The brighter tissue around (the upper quartile): the parenchyma a hepatic artery runs in, not the fat.
        std::nth_element(tissue.begin(), tissue.begin() + std::ptrdiff_t(3 * tissue.size() / 4), tissue.end());
        tissueHu = tissue[3 * tissue.size() / 4];
    }
    if (include && blood - tissueHu < 60.0)
        throw Error(Pattern{"the point %1 is not in a contrast-filled vessel (%2 HU against %3 HU around it); pick a "
                            "point inside the lumen",
                            {mmText(point), std::to_string(int(blood)), std::to_string(int(tissueHu))}});
    detail::FrontSeed seed;
    seed.pointMm = point;
    seed.include = include;
    seed.lowerHu = tissueHu + 0.5 * (blood - tissueHu);
    seed.tissueHu = tissueHu;
    seed.upperHu = blood + std::max(150.0, 0.5 * (blood - tissueHu));
    seed.boneHu = seed.upperHu + kBoneMarginHu;
    if (!include)
        return seed;
    centreInLumen(ct, seed);
    // The blood level again, now in the middle of the lumen: the median smoothed HU within half the lumen's
    // radius (the brightest voxel near a click is biased upwards by the noise).
    std::vector<double> core;
    const Vector3d centre = g.patientToIndex(seed.pointMm);
    const double coreRadius = std::max(0.5 * seed.inscribedRadiusMm, 0.5 * s.minCoeff());
    for (int k = int(std::floor(centre.z() - coreRadius / s.z())); k <= int(std::ceil(centre.z() + coreRadius / s.z())); ++k)
        for (int j = int(std::floor(centre.y() - coreRadius / s.y())); j <= int(std::ceil(centre.y() + coreRadius / s.y())); ++j)
            for (int i = int(std::floor(centre.x() - coreRadius / s.x())); i <= int(std::ceil(centre.x() + coreRadius / s.x())); ++i)
                if (g.contains(i, j, k) &&
                    Vector3d((i - centre.x()) * s.x(), (j - centre.y()) * s.y(), (k - centre.z()) * s.z()).norm() <= coreRadius)
                    core.push_back(detail::smoothedHu(ct, i, j, k));
    if (!core.empty())
    {
        std::nth_element(core.begin(), core.begin() + std::ptrdiff_t(core.size() / 2), core.end());
        const double lumen = core[core.size() / 2];
        seed.lowerHu = tissueHu + 0.5 * (lumen - tissueHu);
        // Thin vessels may be followed down to thinFraction of the contrast, never into the tissue's noise.
        seed.thinHu = std::max(tissueHu + thinFraction * (lumen - tissueHu),
                               tissueHu + kThinNoiseMultiple * dominantSpread(tissueSmoothed));
        // An aorta-sized lumen (inscribed radius >= 5 mm) is crossed only through voxels 60 % of the way from the
        // lower level to its blood: its rim touches the vertebral body, whose cancellous bone (150..250 HU) lies
        // inside a window that reaches down half-way to fat. Small vessels keep the plain window (their centres
        // are dimmed by the scanner's blur).
        if (seed.inscribedRadiusMm >= kCoreRadiusMm)
            seed.coreHu = seed.lowerHu + kCoreFraction * (lumen - seed.lowerHu);
    }
    return seed;
}

double defaultMaxLength(SegmentationTarget target)
{
    switch (target)
    {
    case SegmentationTarget::Aorta: return 1000.0;
    case SegmentationTarget::Hepatic: return 250.0;
    case SegmentationTarget::All: return 150.0;
    }
    return 150.0;
}

} // namespace

std::string segmentationTargetName(SegmentationTarget target)
{
    switch (target)
    {
    case SegmentationTarget::Aorta: return "aorta";
    case SegmentationTarget::Hepatic: return "hepatic";
    case SegmentationTarget::All: return "all";
    }
    return {};
}

SegmentationTarget segmentationTargetFromName(const std::string& name)
{
    for (SegmentationTarget target : {SegmentationTarget::Aorta, SegmentationTarget::Hepatic, SegmentationTarget::All})
        if (segmentationTargetName(target) == name)
            return target;
    throw Error(Pattern{"unknown segmentation target '%1'; known targets: aorta, hepatic, all", {name}});
}

std::vector<ParameterSpec> guidedSegmentationParameters()
{
    const std::string group = "Guided segmentation (waves from points)";
    return {
        {"wave_width_mm", "Wave width", "mm", 1.0, 0.3, 5, group,
         "Path-length width of one wave; its connected pieces are the vessel's cross-sections."},
        {"leak_area_factor", "Leak area factor", "", 3.0, 1.5, 20, group,
         "A cross-section this many times the narrowest of the 12 before it is a leak and is cut back to that neck "
         "(explosion control as in Tschirren 2005)."},
        {"leak_min_area_mm2", "Smallest leak", "mm2", 20, 1, 1000, group,
         "Cross-sections smaller than this are never called leaks."},
        {"thin_area_mm2", "Thin vessel", "mm2", 8.0, 0, 50, group,
         "A front whose cross-section is under this (a vessel under 3.2 mm across) grows on down to the thin level: "
         "the scanner's blur dims a tip under 1 mm below the half level of the blood. 0: off."},
        {"thin_level_fraction", "Thin level", "", 0.2, 0.05, 0.5, group,
         "The thin level: this fraction of the way from the tissue to the blood, and at least 4 robust standard "
         "deviations of the smoothed tissue above it."},
        {"branch_length_mm", "Aortic branch length", "mm", 20, 0, 500, group,
         "Target aorta: path length followed into a branch (a cross-section under a quarter of the trunk's)."},
        {"hepatic_aorta_branch_mm", "Aortic branches (hepatic)", "mm", 5, 0, 100, group,
         "Target hepatic: the aortic point's front (the widest) fills the aorta but enters its branches only this far; "
         "the other points' fronts grow the tree and cannot pass the aorta."},
        {"hepatic_minimal_paths", "Join points by minimal paths", "", 1, 0, 1, group,
         "Target hepatic: a point whose front stopped short of the aorta's (cut at a touching vein or organ) is joined "
         "to it along the minimal path on vesselness, and the path is given its lumen. 0: off.",
         ParameterSpec::Kind::Integer},
    };
}

SegmentationResult segmentFromPoints(const CtVolume& ct, const ParameterSet& parameters,
                                     const SegmentationRequest& request, const Progress& progress)
{
    if (const std::string why = whyNotHounsfield(ct); !why.empty())
        throw Error(Pattern{"the intensities are not CT Hounsfield units (%1): import the CT rescaled to HU "
                            "(vascusim-cli import --rescale SLOPE,INTERCEPT), not MR",
                            {why}});
    std::vector<Vector3d> includes = request.includeMm;
    const bool automatic = includes.empty() && request.target == SegmentationTarget::Aorta;
    if (automatic)
        includes.push_back(findAbdominalAortaPoint(ct));
    if (includes.empty())
        throw Error("the guided segmentation needs at least one include point inside the vessel");
    if (includes.size() + request.excludeMm.size() > 250)
        throw Error("at most 250 include and exclude points");
    const double maxLength = request.maxLengthMm.value_or(defaultMaxLength(request.target));
    std::vector<detail::FrontSeed> seeds;
    for (const Vector3d& p : includes)
    {
        seeds.push_back(seedWindow(ct, p, true, parameters.get("thin_level_fraction")));
        seeds.back().maxLengthMm = maxLength;
        if (request.target == SegmentationTarget::Aorta)
            seeds.back().branchLengthMm = parameters.get("branch_length_mm");
    }
    // Target hepatic: the widest point is the aorta's; a point on an artery that the centring pulled into a wider
    // structure (the portal vein it touches) keeps the click and is joined by its minimal path only.
    const bool joinPaths = request.target == SegmentationTarget::Hepatic && seeds.size() > 1 &&
                           parameters.get("hepatic_minimal_paths") > 0;
    std::vector<detail::FrontSeed> pathPoints;
    std::vector<std::string> seedNotes;
    std::size_t trunk = 0;
    if (request.target == SegmentationTarget::Hepatic && seeds.size() > 1)
    {
        trunk = std::size_t(std::max_element(seeds.begin(), seeds.end(), [](const auto& a, const auto& b) {
                                return a.inscribedRadiusMm < b.inscribedRadiusMm;
                            }) - seeds.begin());
        seeds[trunk].branchLengthMm = parameters.get("hepatic_aorta_branch_mm");
        for (std::size_t n = 0; joinPaths && n < seeds.size(); ++n)
        {
            if (n == trunk)
                continue;
            if (seeds[n].inscribedRadiusMm > kHepaticArteryRadiusMm)
            {
                seedNotes.push_back("the point " + mmText(includes[n]) + " lies beside a wider structure (radius " +
                                    std::to_string(int(std::lround(seeds[n].inscribedRadiusMm))) +
                                    " mm after centring): it grows no front and is joined by its minimal path only");
                seeds[n].grows = false;
                seeds[n].pointMm = includes[n];
            }
            pathPoints.push_back(seeds[n]);
        }
    }
    double includeLower = 1e9, includeUpper = -1e9;
    for (const detail::FrontSeed& seed : seeds)
        includeLower = std::min(includeLower, seed.lowerHu), includeUpper = std::max(includeUpper, seed.upperHu);
    for (const Vector3d& p : request.excludeMm)
    {
        // An exclude front competes on equal terms: its window covers the include fronts' too.
        seeds.push_back(seedWindow(ct, p, false, 1.0));
        seeds.back().lowerHu = std::min(seeds.back().lowerHu, includeLower);
        seeds.back().upperHu = std::max(seeds.back().upperHu, includeUpper);
        seeds.back().maxLengthMm = maxLength;
    }
    detail::WaveSettings settings;
    settings.waveWidthMm = parameters.get("wave_width_mm");
    settings.leakAreaFactor = parameters.get("leak_area_factor");
    settings.leakMinAreaMm2 = parameters.get("leak_min_area_mm2");
    settings.thinAreaMm2 = parameters.get("thin_area_mm2");
    for (const StopPlane& stop : request.stops)
        settings.stops.emplace_back(stop.pointMm, stop.normal.normalized());
    detail::WaveResult waves = detail::propagateFronts(ct, seeds, settings, progress.subRange(0.0, 0.8));
    detail::PathResult paths;
    if (joinPaths)
        paths = detail::joinByMinimalPaths(ct, waves.label, seeds[trunk], pathPoints, detail::PathSettings{},
                                           progress.subRange(0.8, 0.95));

    SegmentationResult result;
    result.label = std::move(waves.label);
    result.seedMm = seeds.front().pointMm;
    result.seedFound = automatic;
    std::size_t voxels = std::size_t(std::count(result.label.data(), result.label.data() + ct.geometry().voxelCount(), 1));
    double lower = 1e9, upper = -1e9;
    for (const detail::FrontSeed& seed : seeds)
        if (seed.include)
            lower = std::min(lower, seed.lowerHu), upper = std::max(upper, seed.upperHu);
    result.figures = {{"lower_hu", lower},
                      {"upper_hu", upper},
                      {"threshold_hu", lower},
                      {"voxels", double(voxels)},
                      {"volume_ml", double(voxels) * ct.geometry().spacing.prod() / 1000.0},
                      {"leaks_cut", double(waves.leaksCut)},
                      {"thin_bursts_blocked", double(waves.thinBursts)},
                      {"waves", double(waves.waves)},
                      {"work_voxels", double(waves.workVoxels)},
                      {"points_joined_by_paths", double(paths.joined)},
                      {"path_length_mm", paths.pathMm},
                      {"path_dim_mm", paths.dimPathMm},
                      {"path_voxels_added", double(paths.voxelsAdded)}};
    for (std::size_t n = 0; n < seeds.size(); ++n)
    {
        const std::string key = (seeds[n].include ? "include_" : "exclude_") + std::to_string(n + 1);
        result.figures[key + "_lower_hu"] = seeds[n].lowerHu;
        if (seeds[n].include && seeds[n].thinHu < 1e29)
            result.figures[key + "_thin_hu"] = seeds[n].thinHu;
        result.figures[key + "_upper_hu"] = seeds[n].upperHu;
        result.figures[key + "_radius_mm"] = seeds[n].inscribedRadiusMm;
    }
    result.warnings = seedNotes;
    result.warnings.insert(result.warnings.end(), waves.leakNotes.begin(), waves.leakNotes.end());
    result.warnings.insert(result.warnings.end(), paths.notes.begin(), paths.notes.end());
    if (waves.limitedVoxels > 0)
        result.warnings.push_back(storedText(Pattern{"the fronts reached the path-length limit (%1 mm) or a branch "
                                                     "limit: the vessel continues beyond the label",
                                                     {std::to_string(int(maxLength))}}));
    if (voxels == 0)
        throw Error("the points grew no vessel: pick them inside the contrast-filled lumen");
    progress.report(1.0, localized("vsim::Progress", "segmented"));
    return result;
}

} // namespace vsim::imaging
