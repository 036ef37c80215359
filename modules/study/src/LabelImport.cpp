#include "vsim/study/LabelImport.h"

#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"

#include <array>
#include <cmath>
#include <sstream>

namespace vsim::study {
namespace {

constexpr double kToleranceMm = 1e-3; // grids written by different programs agree to about a micrometre
constexpr double kVoxelTolerance = 1e-3; // an offset "a whole number of voxels" within this share of a voxel

std::string describe(const VolumeGeometry& g)
{
    std::ostringstream text;
    text << g.dims[0] << " x " << g.dims[1] << " x " << g.dims[2] << " voxels of " << g.spacing.x() << " x "
         << g.spacing.y() << " x " << g.spacing.z() << " mm, origin (" << g.origin.x() << ", " << g.origin.y() << ", "
         << g.origin.z() << ") mm";
    return text.str();
}

} // namespace

LabelVolume maskOnImageGrid(const CtVolume& mask, const VolumeGeometry& image, std::optional<std::uint8_t> value,
                            std::vector<std::string>& warnings)
{
    const VolumeGeometry& source = mask.geometry();
    auto refuse = [&](const std::string& why) {
        return Error(Pattern{"the mask's grid does not match the image's (%1): mask %2; image %3",
                             {why, describe(source), describe(image)}});
    };
    // Each mask axis must run along an image axis (either way: a stack stored in the other order) with its voxel
    // size: a signed permutation of the image's lattice.
    std::array<int, 3> axisOf{}, signOf{};
    for (int a = 0; a < 3; ++a)
    {
        axisOf[a] = -1;
        for (int b = 0; b < 3; ++b)
        {
            const double along = source.direction.col(a).dot(image.direction.col(b));
            if (std::abs(std::abs(along) - 1.0) <= 1e-4)
            {
                axisOf[a] = b, signOf[a] = along > 0.0 ? 1 : -1;
                if (std::abs(source.spacing[a] - image.spacing[b]) > kToleranceMm)
                    throw refuse("another voxel size");
            }
        }
        if (axisOf[a] < 0)
            throw refuse("other axes");
    }
    // Where the mask's voxel (0,0,0) lies in the image's index space: it must be a whole voxel.
    const Eigen::Vector3d offset = image.patientToIndex(source.origin);
    const Eigen::Vector3d whole = offset.array().round();
    if ((offset - whole).cwiseAbs().maxCoeff() > kVoxelTolerance)
        throw refuse("origins not a whole number of voxels apart");
    const int di = int(whole.x()), dj = int(whole.y()), dk = int(whole.z());
    const bool sameLattice = axisOf == std::array<int, 3>{0, 1, 2} && signOf == std::array<int, 3>{1, 1, 1};

    // A binary mask from elsewhere (0 / 255, 0 / 1000) is one structure: stored as label 1, the value the vessel
    // steps (skeleton, measure, mesh) read as the lumen; a mask with several values keeps them.
    std::optional<std::int16_t> onlyValue;
    bool binary = true;
    for (std::size_t v = 0; v < mask.size() && binary; ++v)
        if (const std::int16_t own = mask.data()[v]; own != 0)
        {
            binary = !onlyValue || *onlyValue == own;
            onlyValue = own;
        }
    if (!value && binary && onlyValue && *onlyValue > 1) // a negative value is no mask's: refused below
    {
        warnings.push_back(storedText(Pattern{"the mask holds one value (%1): stored as label 1, the lumen's (give "
                                              "--label-value N for another)",
                                              {std::to_string(*onlyValue)}}));
        value = 1;
    }
    LabelVolume label(image);
    std::size_t labelled = 0, outside = 0;
    const std::array<int, 3>& d = source.dims;
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
            {
                const std::int16_t own = mask.data()[source.linearIndex(i, j, k)];
                if (own == 0)
                    continue;
                if (!value && (own < 1 || own > 255))
                    throw Error(Pattern{"the mask holds the value %1, outside the labels 1..255: give the label value "
                                        "to use (--label-value N)",
                                        {std::to_string(own)}});
                ++labelled;
                std::array<int, 3> at{di, dj, dk};
                const std::array<int, 3> index{i, j, k};
                for (int a = 0; a < 3; ++a)
                    at[std::size_t(axisOf[a])] += signOf[a] * index[std::size_t(a)];
                if (!image.contains(at[0], at[1], at[2]))
                {
                    ++outside;
                    continue;
                }
                label.data()[image.linearIndex(at[0], at[1], at[2])] = value ? *value : std::uint8_t(own);
            }
    if (labelled == 0)
        throw Error("the mask has no labelled voxel");
    if (outside > 0)
        throw refuse(std::to_string(outside) + " of its " + std::to_string(labelled) +
                     " labelled voxels lie outside the image");
    if (!sameLattice)
        warnings.push_back(storedText("the mask's voxels were stored in another axis order or direction: reordered "
                                      "onto the image's grid, voxel for voxel"));
    if (di != 0 || dj != 0 || dk != 0 || d != image.dims)
        warnings.push_back(storedText(Pattern{"the mask was on another grid of the same scan (offset %1, %2, %3 voxels): "
                                              "cut to the image's grid, every labelled voxel kept",
                                              {std::to_string(di), std::to_string(dj), std::to_string(dk)}}));
    return label;
}

} // namespace vsim::study
