#include "vsim/interop/NrrdFile.h"

#include "vsim/interop/ItkImage.h"

#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkNrrdImageIO.h>

namespace vsim::interop {

template <typename T>
void writeNrrd(const ImageVolume<T>& volume, const std::filesystem::path& file, bool compress)
{
    auto writer = itk::ImageFileWriter<ItkImage3<T>>::New();
    writer->SetImageIO(itk::NrrdImageIO::New());
    writer->SetInput(toItk(volume));
    writer->SetFileName(file.string());
    writer->SetUseCompression(compress);
    try
    {
        writer->Update();
    }
    catch (const itk::ExceptionObject& exception)
    {
        throw Error("cannot write NRRD image", {{"file", file.string()}, {"reason", exception.GetDescription()}});
    }
}

template <typename T>
ImageVolume<T> readNrrd(const std::filesystem::path& file)
{
    auto reader = itk::ImageFileReader<ItkImage3<T>>::New();
    reader->SetImageIO(itk::NrrdImageIO::New());
    reader->SetFileName(file.string());
    try
    {
        reader->Update();
    }
    catch (const itk::ExceptionObject& exception)
    {
        throw Error("cannot read NRRD image", {{"file", file.string()}, {"reason", exception.GetDescription()}});
    }
    return fromItk<T>(reader->GetOutput());
}

VolumeGeometry readNrrdGeometry(const std::filesystem::path& file)
{
    auto io = itk::NrrdImageIO::New();
    io->SetFileName(file.string());
    try
    {
        io->ReadImageInformation();
    }
    catch (const itk::ExceptionObject& exception)
    {
        throw Error("cannot read NRRD header", {{"file", file.string()}, {"reason", exception.GetDescription()}});
    }
    if (io->GetNumberOfDimensions() != 3)
        throw Error("image file is not 3D", {{"file", file.string()}});
    VolumeGeometry geometry;
    for (unsigned axis = 0; axis < 3; ++axis)
    {
        geometry.dims[axis] = static_cast<int>(io->GetDimensions(axis));
        geometry.spacing[axis] = io->GetSpacing(axis);
        geometry.origin[axis] = io->GetOrigin(axis);
        const std::vector<double> column = io->GetDirection(axis);
        for (unsigned row = 0; row < 3; ++row)
            geometry.direction(row, axis) = column[row];
    }
    return geometry;
}

template void writeNrrd(const ImageVolume<std::int16_t>&, const std::filesystem::path&, bool);
template void writeNrrd(const ImageVolume<std::uint8_t>&, const std::filesystem::path&, bool);
template void writeNrrd(const ImageVolume<float>&, const std::filesystem::path&, bool);
template ImageVolume<std::int16_t> readNrrd(const std::filesystem::path&);
template ImageVolume<std::uint8_t> readNrrd(const std::filesystem::path&);
template ImageVolume<float> readNrrd(const std::filesystem::path&);

} // namespace vsim::interop
