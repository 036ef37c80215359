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

LabelEdit paintDisc(LabelVolume& label, const Eigen::Vector3d& centreMm, const Eigen::Vector3d& planeNormal,
                    double radiusMm, std::uint8_t value)
{
    if (label.isEmpty())
        throw Error("there is no label to edit");
    if (!(radiusMm > 0.0) || planeNormal.norm() < 1e-9)
        throw Error("the brush needs a positive radius and a plane");
    const VolumeGeometry& geometry = label.geometry();
    const Eigen::Vector3d normal = planeNormal.normalized();
    // Half a voxel along the normal, measured with the spacing the normal sees (one slice of the MPR view).
    const Eigen::Vector3d normalInIndex = geometry.direction.transpose() * normal;
    const double halfThickness = 0.5 * normalInIndex.cwiseAbs().dot(geometry.spacing) / normalInIndex.cwiseAbs().sum();
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
                const Eigen::Vector3d offset = geometry.indexToPatient(Eigen::Vector3d(i, j, k)) - centreMm;
                const double along = offset.dot(normal);
                if (std::abs(along) > halfThickness + 1e-9 || (offset - along * normal).norm() > radiusMm)
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

void reapply(LabelVolume& label, const LabelEdit& edit)
{
    for (std::size_t voxel : edit.voxels)
        label.data()[voxel] = edit.after;
}

void revert(LabelVolume& label, const LabelEdit& edit)
{
    for (std::size_t i = 0; i < edit.voxels.size(); ++i)
        label.data()[edit.voxels[i]] = edit.before[i];
}

} // namespace vsim::imaging
