// The automatic abdominal aorta point (GuidedSegmentation.h findAbdominalAortaPoint): slice by slice the round,
// bright cross-section of 14..56 mm in front of the vertebral body, the middle of the longest chain of them that
// line up over the sampled slices. A vertebral body's core blurred with its cortex can look the same (round,
// 150..600 HU, bone behind it: the arches): of two candidates one in front of the other, only the front one is kept.

#include "vsim/imaging/GuidedSegmentation.h"

#include "SlicePieces.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::imaging {
namespace {

using Eigen::Vector3d;

constexpr double kContrastHu = 150.0, kBoneCortexHu = 600.0; ///< enhanced blood window (smoothed HU)
constexpr double kMinAreaMm2 = 150.0, kMaxAreaMm2 = 2500.0;   ///< 14..56 mm equivalent diameter
constexpr double kRoundness = 0.85;                           ///< share of the equivalent disc inside the piece
constexpr double kSpineHu = 200.0, kSpineShare = 0.3;         ///< bone behind: that share of a 30 x 30 mm window
constexpr double kTrackStepMm = 15.0;                         ///< largest shift between sampled slices
constexpr double kBoneBehindReachMm = 12.0;                   ///< bone behind looked for this far up and down
constexpr double kCortexBorderShare = 0.3;                    ///< bone: its core bordered by cortex

struct Candidate
{
    int k = 0;
    Vector3d centreMm = Vector3d::Zero();
    double meanHu = 0.0;
};

/// The in-plane 3 x 3 binomial mean of slice k.
std::vector<float> smoothedSlice(const CtVolume& ct, int k)
{
    const VolumeGeometry& g = ct.geometry();
    const int nx = g.dims[0], ny = g.dims[1];
    std::vector<float> out(std::size_t(nx) * std::size_t(ny));
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
        {
            double sum = 0.0;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di)
                    sum += double((2 - std::abs(di)) * (2 - std::abs(dj))) *
                           ct.at(std::clamp(i + di, 0, nx - 1), std::clamp(j + dj, 0, ny - 1), k);
            out[std::size_t(i) + std::size_t(nx) * std::size_t(j)] = float(sum / 16.0);
        }
    return out;
}

/// The round bright pieces of slice k with bone behind them (patient +y is posterior).
std::vector<Candidate> sliceCandidates(const CtVolume& ct, int k)
{
    const VolumeGeometry& g = ct.geometry();
    const int nx = g.dims[0], ny = g.dims[1];
    const double pixelArea = g.spacing.x() * g.spacing.y();
    const std::vector<float> hu = smoothedSlice(ct, k);
    const auto inWindow = [&](int i, int j) {
        const float v = hu[std::size_t(i) + std::size_t(nx) * std::size_t(j)];
        return v >= kContrastHu && v <= kBoneCortexHu;
    };
    std::vector<Candidate> candidates;
    for (const std::vector<std::uint32_t>& piece : detail::slicePieces(nx, ny, inWindow))
    {
        const double area = double(piece.size()) * pixelArea;
        if (area < kMinAreaMm2 || area > kMaxAreaMm2)
            continue;
        double ci = 0.0, cj = 0.0, sumHu = 0.0;
        for (std::size_t p : piece)
            ci += double(p % std::size_t(nx)), cj += double(p / std::size_t(nx)), sumHu += hu[p];
        ci /= double(piece.size()), cj /= double(piece.size());
        // Roundness: the share of the disc of the same area around the centroid that the piece fills.
        const double radius = std::sqrt(area / std::numbers::pi);
        std::size_t inDisc = 0, disc = 0;
        const int ri = int(std::ceil(radius / g.spacing.x())), rj = int(std::ceil(radius / g.spacing.y()));
        for (int j = int(cj) - rj; j <= int(cj) + rj; ++j)
            for (int i = int(ci) - ri; i <= int(ci) + ri; ++i)
            {
                if (i < 0 || j < 0 || i >= nx || j >= ny ||
                    std::hypot((i - ci) * g.spacing.x(), (j - cj) * g.spacing.y()) > radius)
                    continue;
                ++disc;
                const float v = hu[std::size_t(i) + std::size_t(nx) * std::size_t(j)];
                inDisc += v >= kContrastHu && v <= kBoneCortexHu;
            }
        if (disc == 0 || double(inDisc) / double(disc) < kRoundness)
            continue;
        // Not bone: a vertebral body's cancellous core is bordered by cortex; an aorta by its wall and fat.
        std::size_t border = 0, cortex = 0;
        for (std::size_t p : piece)
        {
            const int i = int(p % std::size_t(nx)), j = int(p / std::size_t(nx));
            for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}})
            {
                const int ii = i + di, jj = j + dj;
                if (ii < 0 || jj < 0 || ii >= nx || jj >= ny)
                    continue;
                const float v = hu[std::size_t(ii) + std::size_t(nx) * std::size_t(jj)];
                if (v >= kContrastHu && v <= kBoneCortexHu)
                    continue;
                ++border;
                cortex += v > kBoneCortexHu;
            }
        }
        if (border == 0 || double(cortex) / double(border) > kCortexBorderShare)
            continue;
        // Bone behind: a 30 x 30 mm window from just behind the piece, centred 10 mm towards the midline's side, in
        // this slice or one within 12 mm (at an intervertebral disc the vertebral bodies are above and below).
        const Vector3d centre = g.indexToPatient(Vector3d(ci, cj, k));
        double boneShare = 0.0;
        const int reachK = int(std::lround(kBoneBehindReachMm / g.spacing.z()));
        for (int kk = std::max(0, k - reachK); kk <= std::min(g.dims[2] - 1, k + reachK); ++kk)
        {
            std::size_t bone = 0, behind = 0;
            for (double dy = radius + 2.0; dy <= radius + 32.0; dy += g.spacing.y())
                for (double dx = -25.0; dx <= 5.0; dx += g.spacing.x())
                {
                    const Vector3d index = g.patientToIndex(centre + Vector3d(dx, dy, 0.0));
                    const int i = int(std::lround(index.x())), j = int(std::lround(index.y()));
                    if (i < 0 || j < 0 || i >= nx || j >= ny)
                        continue;
                    ++behind;
                    bone += kk == k ? hu[std::size_t(i) + std::size_t(nx) * std::size_t(j)] > kSpineHu
                                    : ct.at(i, j, kk) > kSpineHu;
                }
            if (behind > 0)
                boneShare = std::max(boneShare, double(bone) / double(behind));
        }
        if (boneShare < kSpineShare)
            continue;
        candidates.push_back({k, centre, sumHu / double(piece.size())});
    }
    // The aorta lies in front of the vertebral body: a candidate with another one in front of it (10..70 mm
    // anterior, within 40 mm to either side) is the vertebral body's blurred core, not blood.
    std::vector<Candidate> inFront;
    for (const Candidate& c : candidates)
        if (std::none_of(candidates.begin(), candidates.end(), [&](const Candidate& other) {
                const Vector3d d = other.centreMm - c.centreMm;
                return d.y() <= -10.0 && d.y() >= -70.0 && std::abs(d.x()) <= 40.0;
            }))
            inFront.push_back(c);
    return inFront;
}

} // namespace

Eigen::Vector3d findAbdominalAortaPoint(const CtVolume& ct)
{
    const VolumeGeometry& g = ct.geometry();
    const int step = std::max(1, int(std::lround(4.0 / g.spacing.z())));
    // Chains of candidates over the sampled slices: a candidate continues the chain of one in the sampled slice
    // before within kTrackStepMm. The aorta is the longest chain (vertebral bodies break at every disc, the aorta
    // does not: its bone behind is looked for 12 mm up and down); of equal ones the brighter.
    struct Chain
    {
        std::vector<Candidate> members;
        double sumHu = 0.0;
    };
    std::vector<Chain> chains;
    for (int k = 0; k < g.dims[2]; k += step)
        for (const Candidate& candidate : sliceCandidates(ct, k))
        {
            Chain* continued = nullptr;
            double nearest = kTrackStepMm;
            for (Chain& chain : chains)
            {
                const Candidate& last = chain.members.back();
                const double distance = (candidate.centreMm - last.centreMm).head<2>().norm();
                if (k - last.k == step && distance <= nearest)
                    nearest = distance, continued = &chain;
            }
            if (!continued)
                continued = &chains.emplace_back();
            continued->members.push_back(candidate);
            continued->sumHu += candidate.meanHu;
        }
    const auto extent = [](const Chain& c) { return c.members.back().k - c.members.front().k; };
    const Chain* longest = nullptr;
    for (const Chain& chain : chains)
        if (!longest || extent(chain) > extent(*longest) ||
            (extent(chain) == extent(*longest) &&
             chain.sumHu / double(chain.members.size()) > longest->sumHu / double(longest->members.size())))
            longest = &chain;
    const std::size_t bestLength = longest ? longest->members.size() : 0;
    if (bestLength < 3)
        throw Error("no abdominal aorta found (a round contrast-filled cross-section in front of the spine in three "
                    "neighbouring slices): give a point inside it with --seed x,y,z");
    return longest->members[bestLength / 2].centreMm;
}

} // namespace vsim::imaging
