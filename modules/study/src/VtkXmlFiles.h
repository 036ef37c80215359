#pragma once

// Reading and writing one VTK XML dataset file, shared by the artifact files and the runs' frames.

#include "vsim/core/Error.h"

#include <vtkSmartPointer.h>

#include <filesystem>
#include <type_traits>

namespace vsim::study::detail {

/// Writes `data` with a VTK XML writer (binary; appended and zlib-compressed with `compress`). Throws vsim::Error.
template <typename Writer, typename DataSet>
void writeVtkXml(DataSet* data, const std::filesystem::path& file, bool compress = false)
{
    auto writer = vtkSmartPointer<Writer>::New();
    writer->SetInputData(data);
    writer->SetFileName(file.c_str());
    if (compress)
    {
        writer->SetDataModeToAppended();
        writer->SetCompressorTypeToZLib();
    }
    else
        writer->SetDataModeToBinary();
    if (writer->Write() != 1)
        throw Error("cannot write VTK XML file", {{"file", file.string()}});
}

/// Reads a file with a VTK XML reader; throws vsim::Error when it is missing or cannot be read.
template <typename Reader>
auto readVtkXml(const std::filesystem::path& file)
{
    if (!std::filesystem::exists(file))
        throw Error("file does not exist", {{"file", file.string()}});
    auto reader = vtkSmartPointer<Reader>::New();
    reader->SetFileName(file.c_str());
    reader->Update();
    if (reader->GetErrorCode() != 0 || !reader->GetOutput())
        throw Error("cannot read VTK XML file", {{"file", file.string()}});
    return vtkSmartPointer<std::remove_pointer_t<decltype(reader->GetOutput())>>(reader->GetOutput());
}

} // namespace vsim::study::detail
