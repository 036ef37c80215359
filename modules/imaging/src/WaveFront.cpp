#include "WaveFront.h"

#include "vsim/core/Median.h"

#include "GuidedHelpers.h"
#include "LocalHalfLevel.h"
#include "ShellOffsets.h"
#include "WaveComponents.h"
#include "WorkBox.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <queue>
#include <unordered_map>

namespace vsim::imaging::detail {
namespace {

using Eigen::Vector3d;

/// kLimited: beyond a branch limit of the front that reached it; free for the other fronts (a hepatic point's front
/// meeting the aortic front in the celiac leaves no hole where the aortic one stopped).
constexpr std::uint8_t kUntouched = 0, kFinal = 1, kBlocked = 2, kLimited = 3;
/// Cross-sections under this (a 10 mm vessel) get the local half-level boundary (LocalHalfLevel.h).
constexpr double kSmallVesselAreaMm2 = 80.0;
constexpr float kUnknown = std::numeric_limits<float>::quiet_NaN();
/// The shell whose median is a thin-level voxel's background (mm from it): beyond a tip under 1 mm and its blur.
constexpr double kShellInnerMm = 1.5, kShellOuterMm = 2.5;

constexpr std::size_t kJunctionWaves = 6; ///< waves after a jump before it is judged a junction or a leak
/// A branch is crossed below the trunk's core level while its cross-section is under this (a 5 mm vessel): the blur
/// and the contrast falling along the tree dim a thin branch's centre. A wider piece that grew out of the trunk
/// through a contact (the cancellous bone of a vertebral body, 150..250 HU, under the core level) is not crossed.
constexpr double kDimBranchAreaMm2 = 20.0;

using Component = WaveComponent;

struct Node
{
    float dist;
    std::uint32_t voxel;
    bool operator>(const Node& other) const { return dist > other.dist; }
};

class Propagation
{
public:
    Propagation(const CtVolume& ct, const std::vector<FrontSeed>& seeds, const WaveSettings& settings)
        : m_ct(ct), m_seeds(seeds), m_settings(settings), m_box(workBox(ct, seeds)),
          m_smooth(m_box.count(), kUnknown), m_brightest(m_box.count(), 0.0f), m_state(m_box.count(), kUntouched), m_owner(m_box.count(), 0),
          m_dist(m_box.count(), std::numeric_limits<float>::infinity()), m_parent(m_box.count(), -1),
          m_component(m_box.count(), -1), m_thin(m_box.count(), 0)
    {
        const Vector3d s = ct.geometry().spacing;
        for (int dk = -1; dk <= 1; ++dk)
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di)
                    if (di || dj || dk)
                        m_steps.push_back({{di, dj, dk}, float(Vector3d(di * s.x(), dj * s.y(), dk * s.z()).norm())});
        m_voxelVolume = s.prod();
        m_aliasWaves = std::max<std::size_t>(1, std::size_t(std::ceil(s.maxCoeff() / settings.waveWidthMm - 1e-9)));
    }

    WaveResult run(const Progress& progress)
    {
        for (std::size_t n = 0; n < m_seeds.size(); ++n)
        {
            const Vector3d index = m_ct.geometry().patientToIndex(m_seeds[n].pointMm);
            const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
            const std::uint32_t b = m_box.index(i, j, k);
            m_seedVoxels.push_back(b);
            if (!m_seeds[n].grows)
                continue;
            m_dist[b] = 0.0f;
            m_owner[b] = std::uint8_t(n + 1);
            m_queue.push({0.0f, b});
        }
        std::vector<std::uint32_t> wave;
        std::size_t currentWave = 0, popped = 0;
        while (!m_queue.empty())
        {
            const Node node = m_queue.top();
            m_queue.pop();
            const std::uint32_t v = node.voxel;
            if ((m_state[v] != kUntouched && m_state[v] != kLimited) || node.dist > m_dist[v] || m_owner[v] == 0)
                continue;
            const std::size_t waveIndex = std::size_t(node.dist / m_settings.waveWidthMm);
            if (waveIndex > currentWave)
            {
                finishWave(wave, currentWave);
                wave.clear();
                currentWave = waveIndex;
            }
            const FrontSeed& seed = m_seeds[m_owner[v] - 1];
            if (m_parent[v] >= 0 && m_state[std::uint32_t(m_parent[v])] == kBlocked)
            {
                m_state[v] = kBlocked;
                continue;
            }
            if (seed.include && beyondBranchLimit(v, node.dist, seed))
            {
                m_state[v] = kLimited;
                m_dist[v] = std::numeric_limits<float>::infinity();
                m_owner[v] = 0;
                ++m_limited;
                continue;
            }
            m_state[v] = kFinal;
            if (seed.include)
                wave.push_back(v);
            // The core level holds in the trunk and wide branches: a thin branch's centre is dimmer (blur, the
            // contrast falling along it).
            float brightest = 0.0f;
            if (!seed.include || smoothed(v, brightest) >= seed.coreHu || inThinBranch(v))
                expand(v, node.dist, seed);
            if (++popped % 65536 == 0)
                progress.report(std::min(0.95, double(currentWave) * m_settings.waveWidthMm /
                                                   std::max(1.0, std::min(1000.0, longestReach()))),
                                "growing the vessel fronts");
        }
        finishWave(wave, currentWave);
        judgeSuspects(currentWave, true);
        return result(currentWave + 1);
    }

private:
    double longestReach() const
    {
        double reach = 0.0;
        for (const FrontSeed& seed : m_seeds)
            reach = std::max(reach, seed.maxLengthMm);
        return reach;
    }

    /// Smoothed HU of a box voxel and the brightest raw HU around it (both computed once).
    float smoothed(std::uint32_t b, float& brightest)
    {
        if (std::isnan(m_smooth[b]))
        {
            const auto [i, j, k] = m_box.voxel(b);
            const VolumeGeometry& g = m_ct.geometry();
            float highest = -1e9f;
            for (int dk = -1; dk <= 1; ++dk)
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di)
                        highest = std::max(highest, float(m_ct.at(std::clamp(i + di, 0, g.dims[0] - 1),
                                                                  std::clamp(j + dj, 0, g.dims[1] - 1),
                                                                  std::clamp(k + dk, 0, g.dims[2] - 1))));
            m_smooth[b] = float(smoothedHu(m_ct, i, j, k));
            m_brightest[b] = highest;
        }
        brightest = m_brightest[b];
        return m_smooth[b];
    }

    /// Whether a voxel lies beyond a stop plane (on its normal's side), where include fronts never go.
    bool beyondStop(int i, int j, int k) const
    {
        const Vector3d p = m_ct.geometry().indexToPatient(Vector3d(i, j, k));
        for (const auto& [point, normal] : m_settings.stops)
            if ((p - point).dot(normal) > 0.0)
                return true;
        return false;
    }

    /// Whether voxel v grew from a thin cross-section of its include front (under thinAreaMm2, once the front has
    /// filled its point's lumen: a front starts as a small ball everywhere).
    bool grewFromThin(std::uint32_t v, const FrontSeed& seed) const
    {
        const int c = ancestorComponent(v);
        if (c < 0)
            return false;
        const Component& component = m_components[std::size_t(c)];
        return component.areaMm2 < m_settings.thinAreaMm2 && component.wave >= inflationWaves(seed);
    }

    /// The median raw HU of a shell 1.5 to 2.5 mm around a box voxel (computed once): beside a tip under 1 mm it
    /// is the tissue the tip runs in; inside a vein or an organ as bright as the thin level it is that structure.
    float localBackground(std::uint32_t b)
    {
        if (!m_background)
            m_background.emplace(m_ct, m_box.count(), kShellInnerMm, kShellOuterMm);
        const auto [i, j, k] = m_box.voxel(b);
        return m_background->at(b, i, j, k);
    }

    /// Waves until a front has filled the lumen at its point (its cross-sections before are not the vessel's).
    std::size_t inflationWaves(const FrontSeed& seed) const
    {
        return std::size_t(seed.inscribedRadiusMm / m_settings.waveWidthMm) + 3;
    }

    /// Whether the front of `seed` takes voxel b, reached at path length `dist` from voxel `from`.
    bool accepted(std::uint32_t b, std::uint32_t from, float dist, const FrontSeed& seed)
    {
        float brightest = 0.0f;
        const float hu = smoothed(b, brightest);
        const bool thin = hu < seed.lowerHu;
        if ((thin && !(seed.include && hu >= seed.thinHu && grewFromThin(from, seed) &&
                       hu - localBackground(b) >= seed.thinHu - seed.tissueHu)) ||
            hu > seed.upperHu || (seed.include && brightest > seed.boneHu))
            return false;
        m_thin[b] = thin;
        if (!seed.include)
            return dist <= seed.maxLengthMm;
        if (dist > seed.maxLengthMm)
        {
            ++m_limited;
            return false;
        }
        const auto [i, j, k] = m_box.voxel(b);
        return !beyondStop(i, j, k);
    }

    void expand(std::uint32_t v, float dist, const FrontSeed& seed)
    {
        const auto [i, j, k] = m_box.voxel(v);
        for (const auto& [offset, length] : m_steps)
        {
            const int ii = i + offset[0], jj = j + offset[1], kk = k + offset[2];
            if (ii < m_box.low[0] || jj < m_box.low[1] || kk < m_box.low[2] || ii >= m_box.low[0] + m_box.size[0] ||
                jj >= m_box.low[1] + m_box.size[1] || kk >= m_box.low[2] + m_box.size[2])
                continue;
            const std::uint32_t q = m_box.index(ii, jj, kk);
            const float next = dist + length;
            const bool limited = m_state[q] == kLimited;
            if ((m_state[q] != kUntouched && !limited) || (limited && seed.branchLengthMm < 1e8) || next >= m_dist[q] ||
                !accepted(q, v, next, seed))
                continue;
            m_dist[q] = next;
            m_owner[q] = m_owner[v];
            m_parent[q] = std::int32_t(v);
            m_queue.push({next, q});
        }
    }

    /// The component of the nearest ancestor voxel that has one (-1 when none within a few steps).
    int ancestorComponent(std::uint32_t v) const
    {
        std::int32_t p = m_parent[v];
        for (int step = 0; step < 4 && p >= 0; ++step, p = m_parent[std::uint32_t(p)])
            if (m_component[std::uint32_t(p)] >= 0)
                return m_component[std::uint32_t(p)];
        return -1;
    }

    /// Whether voxel v grew inside a branch under kDimBranchAreaMm2 (its nearest linked ancestor's component).
    bool inThinBranch(std::uint32_t v) const
    {
        const int c = ancestorComponent(v);
        return c >= 0 && m_components[std::size_t(c)].branch && m_components[std::size_t(c)].areaMm2 < kDimBranchAreaMm2;
    }

    bool beyondBranchLimit(std::uint32_t v, float dist, const FrontSeed& seed) const
    {
        if (seed.branchLengthMm >= 1e8)
            return false;
        const int c = ancestorComponent(v);
        return c >= 0 && m_components[std::size_t(c)].branch &&
               dist - m_components[std::size_t(c)].branchStartMm > seed.branchLengthMm;
    }

    /// Splits a wave into 26-connected components, links them to their parents, tests them for leaks.
    void finishWave(const std::vector<std::uint32_t>& wave, std::size_t waveIndex)
    {
        if (wave.empty())
            return;
        std::unordered_map<std::uint32_t, int> slot;
        slot.reserve(wave.size() * 2);
        for (std::size_t n = 0; n < wave.size(); ++n)
            slot[wave[n]] = int(n);
        std::vector<int> root(wave.size());
        for (std::size_t n = 0; n < wave.size(); ++n)
            root[n] = int(n);
        const auto find = [&](int x) {
            while (root[std::size_t(x)] != x)
                x = root[std::size_t(x)] = root[std::size_t(root[std::size_t(x)])];
            return x;
        };
        for (std::size_t n = 0; n < wave.size(); ++n)
        {
            const auto [i, j, k] = m_box.voxel(wave[n]);
            for (const auto& [offset, length] : m_steps)
            {
                const int ii = i + offset[0], jj = j + offset[1], kk = k + offset[2];
                if (ii < m_box.low[0] || jj < m_box.low[1] || kk < m_box.low[2] || ii >= m_box.low[0] + m_box.size[0] ||
                    jj >= m_box.low[1] + m_box.size[1] || kk >= m_box.low[2] + m_box.size[2])
                    continue;
                const auto it = slot.find(m_box.index(ii, jj, kk));
                if (it != slot.end() && m_owner[wave[n]] == m_owner[wave[std::size_t(it->second)]])
                    root[std::size_t(find(int(n)))] = find(it->second);
            }
        }
        std::unordered_map<int, int> componentOfRoot;
        for (std::size_t n = 0; n < wave.size(); ++n)
        {
            const int r = find(int(n));
            auto [it, added] = componentOfRoot.try_emplace(r, int(m_components.size()));
            if (added)
            {
                Component c;
                c.seed = m_owner[wave[n]] - 1;
                c.wave = waveIndex;
                m_components.push_back(c);
            }
            m_components[std::size_t(it->second)].voxels.push_back(wave[n]);
        }
        for (const auto& [r, id] : componentOfRoot)
            linkComponent(id);
        for (const auto& [r, id] : componentOfRoot)
            judgeComponent(id);
        judgeSuspects(waveIndex, false);
    }

    /// Parent (the component most of its voxels grew from), area, and the parent's children list.
    void linkComponent(int id)
    {
        Component& c = m_components[std::size_t(id)];
        std::unordered_map<int, int> votes;
        for (std::uint32_t v : c.voxels)
            if (const int p = ancestorComponent(v); p >= 0)
                ++votes[p];
        for (const auto& [p, count] : votes)
            if (c.parent < 0 || count > votes[c.parent])
                c.parent = p;
        for (std::uint32_t v : c.voxels)
            m_component[v] = id;
        c.areaMm2 = double(c.voxels.size()) * m_voxelVolume / m_settings.waveWidthMm;
        if (c.parent >= 0)
            m_components[std::size_t(c.parent)].children.push_back(id);
    }

    /// The cross-section the leak test reads (WaveComponents.h), mm2.
    double leakTestArea(int id) const { return averagedAreaMm2(m_components, id, m_aliasWaves); }

    /// Branch bookkeeping and the leak test, once every component of the wave is linked.
    void judgeComponent(int id)
    {
        Component& c = m_components[std::size_t(id)];
        if (thinBurst(c))
            return;
        if (c.parent >= 0) // a side branch: the parent went on elsewhere (a sibling twice as wide) and this piece is small
        {
            const Component& parent = m_components[std::size_t(c.parent)];
            double largestSibling = 0.0;
            for (int sibling : parent.children)
                if (sibling != id)
                    largestSibling = std::max(largestSibling, m_components[std::size_t(sibling)].areaMm2);
            c.side = largestSibling >= 2.0 * c.areaMm2 && c.areaMm2 < 0.3 * parent.areaMm2;
        }

        // The ancestors' cross-sections (up to 12 waves back), once the front has filled the lumen at its point.
        const FrontSeed& seed = m_seeds[std::size_t(c.seed)];
        const std::size_t inflation = inflationWaves(seed);
        std::vector<double> history; // newest first
        std::vector<bool> sides;
        for (int a = c.parent; a >= 0 && history.size() < 12 && m_components[std::size_t(a)].wave >= inflation;
             a = m_components[std::size_t(a)].parent)
        {
            history.push_back(leakTestArea(a));
            sides.push_back(m_components[std::size_t(a)].side);
        }
        if (c.parent >= 0)
        {
            const Component& parent = m_components[std::size_t(c.parent)];
            c.branch = parent.branch;
            c.branchStartMm = parent.branchStartMm;
            c.trunkAreaMm2 = parent.trunkAreaMm2;
            if (!c.branch && history.size() >= 4)
            {
                c.trunkAreaMm2 = median(history);
                if (c.side && c.areaMm2 < 0.25 * c.trunkAreaMm2) // a tapering trunk is no branch: it did not split
                    c.branch = true, c.branchStartMm = double(c.wave) * m_settings.waveWidthMm;
            }
        }
        if (history.size() < 4)
            return;
        // A leak passes a neck and widens past it: beyond factor x the narrowest recent cross-section, and either
        // the neck was a side branch (a contact with a touching vein or the aorta: the vessel went on beside it) or
        // the front widens past the calibre it had before the neck. A stenosis (the whole front narrows and widens
        // back to its calibre) is not a leak; nor is a vessel followed towards its root (1.6 x at most per merge).
        const std::size_t neck = std::size_t(std::min_element(history.begin(), history.end()) - history.begin());
        const double reference = history[neck];
        const double area = leakTestArea(id);
        if (area <= m_settings.leakAreaFactor * reference || area <= m_settings.leakMinAreaMm2)
            return;
        const bool sideNeck = c.side || std::find(sides.begin(), sides.begin() + std::ptrdiff_t(neck) + 1, true) !=
                                            sides.begin() + std::ptrdiff_t(neck) + 1;
        // The calibre before the neck: the widest cross-section up to 40 waves further back (a stenosis is longer
        // than the 12-wave window).
        double beforeNeck = 0.0;
        {
            int a = c.parent;
            for (std::size_t n = 0; n < neck && a >= 0; ++n)
                a = m_components[std::size_t(a)].parent;
            for (std::size_t n = 0; n < 40 && a >= 0 && m_components[std::size_t(a)].wave >= inflation;
                 ++n, a = m_components[std::size_t(a)].parent)
                if (n > 0)
                    beforeNeck = std::max(beforeNeck, leakTestArea(a));
        }
        if (!sideNeck && area <= 1.5 * beforeNeck)
            return;
        // A leak, unless the next waves show a junction reached from a branch (a front climbing towards the root
        // meets the parent and a sibling at once: the jump splits into pieces each of a branch's calibre).
        int top = id;
        for (int a = c.parent; a >= 0 && m_components[std::size_t(a)].areaMm2 > 1.5 * reference;
             a = m_components[std::size_t(a)].parent)
            top = a;
        m_suspects.push_back({id, top, reference});
    }

    /// A cross-section that grew from a thin one at the thin level and burst wider than twice the thin area has
    /// run into tissue or a vein beside the tip: its voxels below the front's window are blocked (the tip's own
    /// voxels before it stay; a leak cut would take the vessel back to its neck). True when it burst.
    bool thinBurst(const Component& c)
    {
        if (c.areaMm2 <= 2.0 * m_settings.thinAreaMm2 || c.parent < 0)
            return false;
        const Component& parent = m_components[std::size_t(c.parent)];
        if (parent.areaMm2 >= m_settings.thinAreaMm2 ||
            std::none_of(c.voxels.begin(), c.voxels.end(), [&](std::uint32_t v) { return m_thin[v] != 0; }))
            return false;
        for (std::uint32_t v : c.voxels)
            if (m_thin[v])
                m_state[v] = kBlocked;
        ++m_thinBursts;
        return true;
    }

    /// Judges the suspected leaks kJunctionWaves after they jumped (or at the end, `final`): a junction when the
    /// jump's descendants in that wave are two or more pieces each within the leak factor of the reference; else
    /// the rising part is cut back to where it began to rise.
    void judgeSuspects(std::size_t waveIndex, bool final)
    {
        std::vector<Suspect> waiting;
        for (const Suspect& suspect : m_suspects)
        {
            const Component& c = m_components[std::size_t(suspect.component)];
            if (!final && waveIndex < c.wave + kJunctionWaves)
            {
                waiting.push_back(suspect);
                continue;
            }
            if (m_components[std::size_t(suspect.top)].blocked)
                continue;
            std::vector<int> pieces, stack{suspect.component};
            while (!stack.empty())
            {
                const int n = stack.back();
                stack.pop_back();
                const Component& d = m_components[std::size_t(n)];
                if (d.wave >= c.wave + kJunctionWaves || d.children.empty())
                {
                    if (d.wave > c.wave)
                        pieces.push_back(n);
                    continue;
                }
                stack.insert(stack.end(), d.children.begin(), d.children.end());
            }
            const bool junction = pieces.size() >= 2 && std::all_of(pieces.begin(), pieces.end(), [&](int n) {
                return m_components[std::size_t(n)].areaMm2 <= m_settings.leakAreaFactor * suspect.referenceMm2;
            });
            if (junction)
                continue;
            Vector3d centre = Vector3d::Zero();
            for (std::uint32_t v : m_components[std::size_t(suspect.top)].voxels)
            {
                const auto [i, j, k] = m_box.voxel(v);
                centre += Vector3d(i, j, k);
            }
            centre = m_ct.geometry().indexToPatient(centre / double(m_components[std::size_t(suspect.top)].voxels.size()));
            char note[200];
            std::snprintf(note, sizeof note, "leak cut at (%.1f, %.1f, %.1f) mm: cross-section %.0f mm2 after %.0f mm2",
                          centre.x(), centre.y(), centre.z(), c.areaMm2, suspect.referenceMm2);
            m_leakNotes.push_back(note);
            block(suspect.top);
        }
        m_suspects = std::move(waiting);
    }

    void block(int id)
    {
        std::vector<int> stack{id};
        while (!stack.empty())
        {
            Component& c = m_components[std::size_t(stack.back())];
            stack.pop_back();
            if (c.blocked)
                continue;
            c.blocked = true;
            for (std::uint32_t v : c.voxels)
                m_state[v] = kBlocked;
            stack.insert(stack.end(), c.children.begin(), c.children.end());
        }
    }

    WaveResult result(std::size_t waves)
    {
        WaveResult out;
        out.label = LabelVolume(m_ct.geometry());
        std::fill(out.label.data(), out.label.data() + m_ct.geometry().voxelCount(), std::uint8_t(0));
        for (std::uint32_t b = 0; b < m_box.count(); ++b)
            if (m_state[b] == kFinal && m_owner[b] > 0 && m_seeds[m_owner[b] - 1].include)
            {
                const auto [i, j, k] = m_box.voxel(b);
                out.label.at(i, j, k) = 1;
            }
        // Boundary refinement of small vessels (cross-sections under kSmallVesselAreaMm2): the smoothed HU and one
        // window decided the growth; the boundary moves to the local half level (LocalHalfLevel.h), one voxel at
        // most. Wide vessels keep the window's boundary (the blur's shift there is negligible, and their rims touch
        // bone and other vessels). Voxels another front claimed, cut leaks and the points stay as they are.
        const auto smallVessel = [&](std::uint32_t b) {
            return m_state[b] == kFinal && m_owner[b] > 0 && m_seeds[m_owner[b] - 1].include && m_component[b] >= 0 &&
                   m_components[std::size_t(m_component[b])].areaMm2 <= kSmallVesselAreaMm2 &&
                   b != m_seedVoxels[m_owner[b] - 1];
        };
        const auto mayMove = [&](int i, int j, int k) {
            if (i < m_box.low[0] || j < m_box.low[1] || k < m_box.low[2] || i >= m_box.low[0] + m_box.size[0] ||
                j >= m_box.low[1] + m_box.size[1] || k >= m_box.low[2] + m_box.size[2])
                return false;
            const std::uint32_t b = m_box.index(i, j, k);
            if (out.label.at(i, j, k))
                return smallVessel(b);
            return m_state[b] == kUntouched && !beyondStop(i, j, k); // nothing is added beyond a stop plane
        };
        moveToLocalHalfLevel(m_ct, out.label, m_box.low, m_box.size, mayMove, 1);
        out.waves = waves;
        out.leaksCut = m_leakNotes.size();
        out.leakNotes = m_leakNotes;
        out.workVoxels = m_box.count();
        out.limitedVoxels = m_limited;
        out.thinBursts = m_thinBursts;
        return out;
    }

    const CtVolume& m_ct;
    const std::vector<FrontSeed>& m_seeds;
    const WaveSettings& m_settings;
    WorkBox m_box;
    std::vector<float> m_smooth;
    std::vector<float> m_brightest;
    std::vector<std::uint8_t> m_state, m_owner;
    std::vector<float> m_dist;
    std::vector<std::int32_t> m_parent, m_component;
    std::vector<Component> m_components;
    std::vector<std::pair<std::array<int, 3>, float>> m_steps;
    std::priority_queue<Node, std::vector<Node>, std::greater<Node>> m_queue;
    std::vector<std::string> m_leakNotes;
    struct Suspect
    {
        int component, top;
        double referenceMm2;
    };
    std::vector<Suspect> m_suspects; ///< leaks awaiting the junction test
    std::vector<std::uint32_t> m_seedVoxels;
    std::size_t m_limited = 0;
    std::vector<std::uint8_t> m_thin; ///< 1: taken below its front's window, at the thin level
    std::optional<ShellMedians> m_background; ///< localBackground's cache (made when a thin level is first tried)
    std::size_t m_thinBursts = 0;
    double m_voxelVolume = 1.0;
    std::size_t m_aliasWaves = 1; ///< waves a voxel layer spans (averagedAreaMm2)
};

} // namespace

WaveResult propagateFronts(const CtVolume& ct, const std::vector<FrontSeed>& seeds, const WaveSettings& settings,
                           const Progress& progress)
{
    Propagation propagation(ct, seeds, settings);
    return propagation.run(progress);
}

} // namespace vsim::imaging::detail
