#include "vsim/study/VolumeFileImport.h"

#include "vsim/core/Error.h"
#include "vsim/core/Hounsfield.h"
#include "vsim/core/Localized.h"
#include "vsim/core/Parameters.h"
#include "vsim/core/StoredText.h"
#include "vsim/interop/ItkImage.h"
#include "vsim/study/Study.h"

#include <itkImageFileReader.h>
#include <itkMetaImageIO.h>
#include <itkNiftiImageIO.h>
#include <itkNrrdImageIO.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace vsim::study {
namespace {

struct FormatChoice
{
    itk::ImageIOBase::Pointer io;
    std::string name;
};

FormatChoice chooseFormat(const std::filesystem::path& file)
{
    const std::pair<itk::ImageIOBase::Pointer, std::string> candidates[] = {
        {itk::NiftiImageIO::New().GetPointer(), "NIfTI"},
        {itk::NrrdImageIO::New().GetPointer(), "NRRD"},
        {itk::MetaImageIO::New().GetPointer(), "MetaImage"}};
    for (const auto& [io, name] : candidates)
        if (io->CanReadFile(file.c_str()))
            return {io, name};
    throw Error("not a NIfTI, NRRD or MetaImage volume (or the file cannot be read)", {{"file", file.filename().string()}});
}

template <typename T>
typename interop::ItkImage3<T>::Pointer readAs(const std::filesystem::path& file, itk::ImageIOBase* io)
{
    auto reader = itk::ImageFileReader<interop::ItkImage3<T>>::New();
    reader->SetImageIO(io);
    reader->SetFileName(file.string());
    try
    {
        reader->Update();
    }
    catch (const itk::ExceptionObject& exception)
    {
        throw Error("cannot read the volume", {{"file", file.filename().string()}, {"reason", exception.GetDescription()}});
    }
    return reader->GetOutput();
}

/// Rounds to int16, counting what had to change.
CtVolume toHounsfield(interop::ItkImage3<float>* image, std::vector<std::string>& warnings, const Progress& progress)
{
    const RealVolume real = interop::fromItk<float>(image);
    CtVolume hounsfield(real.geometry());
    std::size_t rounded = 0;
    std::size_t clamped = 0;
    constexpr double kLowest = std::numeric_limits<std::int16_t>::min();
    constexpr double kHighest = std::numeric_limits<std::int16_t>::max();
    const std::size_t count = real.size();
    for (std::size_t v = 0; v < count; ++v)
    {
        double value = real.data()[v];
        if (!std::isfinite(value))
            value = 0.0, ++clamped;
        const double nearest = std::round(value);
        rounded += std::abs(nearest - value) > 1e-3;
        const double kept = std::clamp(nearest, kLowest, kHighest);
        clamped += kept != nearest;
        hounsfield.data()[v] = static_cast<std::int16_t>(kept);
        if ((v & 0xFFFFF) == 0)
            progress.report(0.6 + 0.4 * static_cast<double>(v) / static_cast<double>(count), localized("vsim::Progress", "converting to HU"));
    }
    if (rounded)
        warnings.push_back(storedText(
            Pattern{"%1 voxels were not whole numbers and were rounded to integer HU", {std::to_string(rounded)}}));
    if (clamped)
        warnings.push_back(storedText(Pattern{"%1 voxels were outside the int16 range or not finite and were clamped",
                                              {std::to_string(clamped)}}));
    return hounsfield;
}

/// ITK's MetaImage reader only prints a message when the embedded voxel data is cut short; refuse such a file.
void checkMetaImageComplete(const std::filesystem::path& file, itk::ImageIOBase* io)
{
    auto* meta = dynamic_cast<itk::MetaImageIO*>(io);
    if (!meta || meta->GetMetaImagePointer()->CompressedData() ||
        std::string(meta->GetMetaImagePointer()->ElementDataFileName()) != "LOCAL")
        return;
    const auto needed = static_cast<std::uintmax_t>(io->GetImageSizeInBytes());
    const auto size = std::filesystem::file_size(file);
    if (size < needed)
        throw Error("the volume file is truncated: it holds fewer bytes than its header announces",
                    {{"file", file.filename().string()}, {"bytes", std::to_string(size)},
                     {"voxel bytes expected", std::to_string(needed)}});
}

} // namespace

ImportedVolume readVolumeFile(const std::filesystem::path& file, const Progress& progress)
{
    if (!std::filesystem::is_regular_file(file))
        throw Error("volume file does not exist", {{"file", file.filename().string()}});
    FormatChoice format = chooseFormat(file);
    progress.report(0.0, withArguments(localized("vsim::Progress", "reading %1"), {format.name}));
    try
    {
        format.io->SetFileName(file.string());
        format.io->ReadImageInformation();
    }
    catch (const itk::ExceptionObject& exception)
    {
        throw Error("cannot read the volume header", {{"file", file.filename().string()}, {"reason", exception.GetDescription()}});
    }
    checkMetaImageComplete(file, format.io);
    if (format.io->GetNumberOfDimensions() != 3)
        throw Error("the volume is not 3D", {{"dimensions", std::to_string(format.io->GetNumberOfDimensions())}});
    if (format.io->GetNumberOfComponents() != 1)
        throw Error("the volume has more than one component per voxel (colour or vector data)",
                    {{"components", std::to_string(format.io->GetNumberOfComponents())}});

    ImportedVolume result;
    result.format = format.name;
    if (format.io->GetComponentType() == itk::IOComponentEnum::SHORT)
    {
        result.image = interop::fromItk<std::int16_t>(readAs<std::int16_t>(file, format.io).GetPointer());
    }
    else
    {
        auto real = readAs<float>(file, format.io);
        progress.report(0.6, localized("vsim::Progress", "converting to HU"));
        result.image = toHounsfield(real.GetPointer(), result.warnings, progress);
    }
    progress.report(1.0, localized("vsim::Progress", "read"));
    return result;
}

std::string importVolumeFile(Study& study, const std::filesystem::path& file,
                             const std::optional<HounsfieldRescale>& rescale, const Progress& progress)
{
    return addImportedVolume(study, readVolumeFile(file, progress), file, rescale);
}

std::string addImportedVolume(Study& study, ImportedVolume imported, const std::filesystem::path& file,
                              const std::optional<HounsfieldRescale>& rescale)
{
    acceptAsHounsfield(imported.image, rescale, imported.warnings);
    Provenance provenance;
    provenance.command = "import volume";
    provenance.inputs = {file.filename().string()};
    provenance.parameters = {{"format", imported.format}};
    if (rescale)
        provenance.parameters["rescale"] = numberText(rescale->slope) + "," + numberText(rescale->intercept);
    return study.addImage(imported.image, file.stem().string(), std::move(provenance), std::move(imported.warnings));
}

} // namespace vsim::study
