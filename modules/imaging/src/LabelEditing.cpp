#include "vsim/imaging/LabelEditing.h"

#include "vsim/core/Error.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace vsim::imaging {

void LabelEdit::merge(const LabelEdit& later)
{
    if (later.empty())
        return;
    if (!empty() && later.after != after)
        throw Error("cannot merge a paint and an erase stroke");
    after = later.after;
    const std::unordered_set<std::size_t> known(voxels.begin(), voxels.end());
    for (std::size_t i = 0; i < later.voxels.size(); ++i)
        if (!known.count(later.voxels[i]))
        {
            voxels.push_back(later.voxels[i]);
            before.push_back(later.before[i]);
        }
}

namespace {

/// Writes `value` into the voxels of the box of `radiusMm` around `centreMm` that `inside(offset mm)` accepts.
template <typename Inside>
LabelEdit paintWhere(LabelVolume& label, const Eigen::Vector3d& centreMm, double radiusMm, std::uint8_t value,
                     const Inside& inside)
{
    const VolumeGeometry& geometry = label.geometry();
    const Eigen::Vector3d centre = geometry.patientToIndex(centreMm);
    LabelEdit edit;
    edit.after = value;
    Eigen::Vector3i low, high;
    for (int a = 0; a < 3; ++a)
    {
        const double reach = radiusMm / geometry.spacing[a] + 1.0;
        low[a] = std::max(0, int(std::floor(centre[a] - reach)));
        high[a] = std::min(geometry.dims[a] - 1, int(std::ceil(centre[a] + reach)));
    }
    for (int k = low[2]; k <= high[2]; ++k)
        for (int j = low[1]; j <= high[1]; ++j)
            for (int i = low[0]; i <= high[0]; ++i)
            {
                if (!inside(geometry.indexToPatient(Eigen::Vector3d(i, j, k)) - centreMm))
                    continue;
                std::uint8_t& voxel = label.at(i, j, k);
                if (voxel == value)
                    continue;
                edit.voxels.push_back(geometry.linearIndex(i, j, k));
                edit.before.push_back(voxel);
                voxel = value;
            }
    return edit;
}

void checkBrush(const LabelVolume& label, double radiusMm)
{
    if (label.isEmpty())
        throw Error("there is no label to edit");
    if (!(radiusMm > 0.0))
        throw Error("the brush needs a positive radius");
}

} // namespace

LabelEdit paintDisc(LabelVolume& label, const Eigen::Vector3d& centreMm, const Eigen::Vector3d& planeNormal,
                    double radiusMm, std::uint8_t value)
{
    checkBrush(label, radiusMm);
    if (planeNormal.norm() < 1e-9)
        throw Error("the brush needs a plane");
    const VolumeGeometry& geometry = label.geometry();
    const Eigen::Vector3d normal = planeNormal.normalized();
    // Half a voxel along the normal, measured with the spacing the normal sees (one slice of the MPR view).
    const Eigen::Vector3d normalInIndex = geometry.direction.transpose() * normal;
    const double halfThickness = 0.5 * normalInIndex.cwiseAbs().dot(geometry.spacing) / normalInIndex.cwiseAbs().sum();
    return paintWhere(label, centreMm, radiusMm, value, [&](const Eigen::Vector3d& offset) {
        const double along = offset.dot(normal);
        return std::abs(along) <= halfThickness + 1e-9 && (offset - along * normal).norm() <= radiusMm;
    });
}

LabelEdit paintBall(LabelVolume& label, const Eigen::Vector3d& centreMm, double radiusMm, std::uint8_t value)
{
    checkBrush(label, radiusMm);
    return paintWhere(label, centreMm, radiusMm, value,
                      [&](const Eigen::Vector3d& offset) { return offset.norm() <= radiusMm; });
}

void reapply(LabelVolume& label, const LabelEdit& edit)
{
    for (std::size_t voxel : edit.voxels)
        label.data()[voxel] = edit.after;
}

LabelEdit removeIsland(LabelVolume& label, const Eigen::Vector3d& pointMm, double searchMm)
{
    if (label.isEmpty())
        throw Error("there is no label to edit");
    const VolumeGeometry& g = label.geometry();
    const Eigen::Vector3d index = g.patientToIndex(pointMm);
    // The start: the labelled voxel nearest to the point within the search radius (at least half a voxel's
    // diagonal: a point inside a voxel is that far from its centre at most).
    searchMm = std::max(searchMm, 0.5 * g.spacing.norm());
    const Eigen::Vector3d reach = (Eigen::Vector3d::Constant(searchMm).array() / g.spacing.array()).ceil();
    std::size_t start = g.voxelCount();
    double nearest = searchMm;
    for (int k = int(std::floor(index.z() - reach.z())); k <= int(std::ceil(index.z() + reach.z())); ++k)
        for (int j = int(std::floor(index.y() - reach.y())); j <= int(std::ceil(index.y() + reach.y())); ++j)
            for (int i = int(std::floor(index.x() - reach.x())); i <= int(std::ceil(index.x() + reach.x())); ++i)
            {
                if (!g.contains(i, j, k) || !label.at(i, j, k))
                    continue;
                const double d = (g.indexToPatient(Eigen::Vector3d(i, j, k)) - pointMm).norm();
                if (d <= nearest)
                    nearest = d, start = g.linearIndex(i, j, k);
            }
    LabelEdit edit;
    edit.after = 0;
    if (start == g.voxelCount())
        return edit;
    const std::size_t nx = std::size_t(g.dims[0]), ny = std::size_t(g.dims[1]);
    std::vector<std::size_t> stack{start};
    edit.voxels.push_back(start);
    edit.before.push_back(label.data()[start]);
    label.data()[start] = 0;
    while (!stack.empty())
    {
        const std::size_t v = stack.back();
        stack.pop_back();
        const int i = int(v % nx), j = int(v / nx % ny), k = int(v / (nx * ny));
        for (int n = 0; n < 27; ++n)
        {
            const int ii = i + n % 3 - 1, jj = j + n / 3 % 3 - 1, kk = k + n / 9 - 1;
            if (!g.contains(ii, jj, kk) || !label.at(ii, jj, kk))
                continue;
            const std::size_t w = g.linearIndex(ii, jj, kk);
            edit.voxels.push_back(w);
            edit.before.push_back(label.data()[w]);
            label.data()[w] = 0;
            stack.push_back(w);
        }
    }
    return edit;
}

void revert(LabelVolume& label, const LabelEdit& edit)
{
    for (std::size_t i = 0; i < edit.voxels.size(); ++i)
        label.data()[edit.voxels[i]] = edit.before[i];
}

} // namespace vsim::imaging
