#pragma once

// Small phantom series for the DICOM tests: rendered in memory (the truth) and written with DCMTK, so each test
// can damage the series the way hospital data is damaged and compare the import with the truth.

#include "TestOutput.h"
#include "vsim/dicom/CtSeriesWriter.h"
#include "vsim/dicom/PhantomModel.h"
#include "vsim/dicom/PhantomRender.h"

#include <QDir>

#include <filesystem>

namespace vsim::test {

/// A phantom series on disk with the volume it was rendered from.
struct PhantomSeries
{
    dicom::PhantomModel model;
    dicom::PhantomOptions options;
    VolumeGeometry geometry; ///< the axial grid of the phantom
    CtVolume truth;          ///< HU of every written slice, stack order
    dicom::WrittenSeries written;
};

/// Options of the small test phantoms: 96 x 96 x 48 voxels of 3.5 x 3.5 x 8 mm (the whole aaa model fits).
inline dicom::PhantomOptions smallPhantomOptions(double noiseHu = 20.0)
{
    dicom::PhantomOptions options;
    options.size = {96, 96, 48};
    options.spacing = {3.5, 3.5, 8.0};
    options.noiseHu = noiseHu;
    options.seed = 7;
    return options;
}

/// A fresh, empty folder under the suite's test output.
inline std::filesystem::path freshFolder(const QString& suite, const QString& name)
{
    const std::filesystem::path folder = std::filesystem::path(outputFolder(suite).toStdString()) / name.toStdString();
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    return folder;
}

/// Renders `kind` on `stack` (the phantom's axial grid when empty) and writes it to `folder`.
inline PhantomSeries writePhantomSeries(dicom::PhantomKind kind, const dicom::PhantomOptions& options,
                                        const std::filesystem::path& folder,
                                        dicom::CtSeriesDescription description = {},
                                        dicom::SliceStack stack = {})
{
    PhantomSeries series;
    series.options = options;
    series.model = dicom::buildPhantomModel(kind, options);
    series.geometry = dicom::phantomGeometry(options);
    if (stack.positions.empty())
        stack = dicom::stackOf(series.geometry);
    series.truth = dicom::renderPhantomCt(series.model, stack, options);
    series.written = dicom::writeCtSeries(series.truth, stack, description, folder);
    return series;
}

/// Number of voxels that differ between two volumes of the same size (all when the sizes differ).
inline std::size_t differingVoxels(const CtVolume& a, const CtVolume& b)
{
    if (a.size() != b.size())
        return std::max(a.size(), b.size());
    std::size_t count = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        count += a.data()[i] != b.data()[i];
    return count;
}

} // namespace vsim::test
