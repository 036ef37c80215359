#include "RunFiles.h"

#include "BundleFiles.h"
#include "VtkXmlFiles.h"
#include "vsim/core/Error.h"
#include "vsim/core/StoredText.h"
#include "vsim/interop/VtkMesh.h"
#include "vsim/interop/VtkSimulationData.h"

#include <nlohmann/json.hpp>
#include <vtkImageData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <set>

namespace vsim::study {
namespace fs = std::filesystem;
namespace {

using nlohmann::json;

constexpr int kRunFormatVersion = 1;
const std::regex kFrameName("frame_[0-9]{6}\\.(vtu|vtp|vti)");

/// A tet mesh as an unstructured grid, a network or particles as polydata, a grid as image data.
std::string extensionOf(const SimulationData& data)
{
    return std::holds_alternative<TetMesh>(data) ? ".vtu" : std::holds_alternative<GridFields>(data) ? ".vti" : ".vtp";
}

void writeFrame(const SimulationData& data, const fs::path& file)
{
    if (const auto* mesh = std::get_if<TetMesh>(&data))
        detail::writeVtkXml<vtkXMLUnstructuredGridWriter>(interop::toVtk(*mesh).Get(), file, true);
    else if (const auto* network = std::get_if<VesselNetwork>(&data))
        detail::writeVtkXml<vtkXMLPolyDataWriter>(interop::toVtk(*network).Get(), file, true);
    else if (const auto* particles = std::get_if<ParticleSet>(&data))
        detail::writeVtkXml<vtkXMLPolyDataWriter>(interop::toVtk(*particles).Get(), file, true);
    else
        detail::writeVtkXml<vtkXMLImageDataWriter>(interop::toVtk(std::get<GridFields>(data)).Get(), file, true);
    syncFile(file);
}

SimulationData readFrame(const fs::path& file)
{
    const std::string extension = file.extension().string();
    if (extension == ".vtu")
        return interop::tetMeshFromVtk(detail::readVtkXml<vtkXMLUnstructuredGridReader>(file).Get());
    if (extension == ".vtp") // a network has lines, particles have none
    {
        const vtkSmartPointer<vtkPolyData> polyData = detail::readVtkXml<vtkXMLPolyDataReader>(file);
        if (polyData->GetNumberOfLines() > 0)
            return interop::networkFromVtk(polyData.Get());
        return interop::particlesFromVtk(polyData.Get());
    }
    if (extension == ".vti")
        return interop::gridFieldsFromVtk(detail::readVtkXml<vtkXMLImageDataReader>(file).Get());
    throw Error("a run frame of an unknown format", {{"file", file.string()}});
}

/// Numbers as JSON, NaN and infinities as null (JSON has none).
json numbers(const std::map<std::string, double>& values)
{
    json out = json::object();
    for (const auto& [key, value] : values)
        out[key] = std::isfinite(value) ? json(value) : json(nullptr);
    return out;
}

std::map<std::string, double> numbersFrom(const json& values)
{
    std::map<std::string, double> out;
    for (const auto& [key, value] : values.items())
        out[key] = value.is_null() ? std::nan("") : value.get<double>();
    return out;
}

json readRunJson(const fs::path& runJson)
{
    try
    {
        json document = json::parse(readTextFile(runJson));
        if (document.at("format") != "vascusim-run" || document.at("version").get<int>() > kRunFormatVersion)
            throw Error("not a run this VascuSim reads", {{"file", runJson.string()}});
        return document;
    }
    catch (const json::exception& exception)
    {
        throw Error("cannot parse a run's run.json", {{"file", runJson.string()}, {"reason", exception.what()}});
    }
}

RunFrame frameEntry(const json& entry)
{
    RunFrame frame;
    frame.number = entry.at("number").get<int>();
    frame.step = entry.at("step").get<long>();
    frame.position = entry.at("position").get<double>();
    return frame;
}

} // namespace

void writeRunFolder(const SolverRun& run, const fs::path& runJson)
{
    if (run.frames.size() != run.keptFrameNumbers.size())
        throw Error("a run is written with its frames in memory");
    const fs::path folder = runJson.parent_path();
    fs::create_directories(folder / "frames");
    json frames = json::array();
    std::set<std::string> written;
    std::string collection = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n";
    for (const RunFrame& frame : run.frames)
    {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%06d", frame.number);
        const std::string file = "frames/" + std::string(name) + extensionOf(frame.data);
        writeFrame(frame.data, folder / file);
        written.insert(fs::path(file).filename().string());
        frames.push_back({{"number", frame.number}, {"step", frame.step}, {"position", frame.position}, {"file", file},
                          {"bytes", fs::file_size(folder / file)}, {"crc32", fileChecksum(folder / file)}});
        char timestep[64];
        std::snprintf(timestep, sizeof timestep, "%.17g", frame.position);
        collection += "    <DataSet timestep=\"" + std::string(timestep) + "\" part=\"0\" file=\"" + file + "\"/>\n";
    }
    collection += "  </Collection>\n</VTKFile>\n";
    for (const auto& entry : fs::directory_iterator(folder / "frames"))
    {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && std::regex_match(name, kFrameName) && !written.count(name))
            fs::remove(entry.path());
    }
    writeFileAtomically(folder / "series.pvd", collection);
    const json document = {
        {"format", "vascusim-run"},
        {"version", kRunFormatVersion},
        {"solver", run.provenance.solver},
        {"axis", {{"quantity", run.axis.quantity}, {"unit", run.axis.unit}, {"target", run.axis.target}}},
        {"provenance",
         {{"parameters", run.provenance.parameters},
          {"inputs", run.provenance.inputs},
          {"started_utc", run.provenance.startedUtc},
          {"wall_seconds", run.provenance.wallSeconds}}},
        {"steps", run.steps},
        {"frames_taken", run.framesTaken},
        {"frames", frames},
        {"status", {{"metrics", numbers(run.status.metrics())}, {"attributes", run.status.attributes()}}},
        {"metrics", numbers(run.metrics)}};
    writeFileAtomically(runJson, document.dump(1));
}

SolverRun readRunFolder(const fs::path& runJson, bool withFrames)
{
    const json document = readRunJson(runJson);
    SolverRun run;
    try
    {
        run.provenance.solver = document.at("solver").get<std::string>();
        const json& axis = document.at("axis");
        run.axis = {axis.at("quantity").get<std::string>(), axis.at("unit").get<std::string>(),
                    axis.at("target").get<double>()};
        const json& provenance = document.at("provenance");
        run.provenance.parameters = provenance.at("parameters").get<std::map<std::string, std::string>>();
        run.provenance.inputs = provenance.at("inputs").get<std::map<std::string, std::string>>();
        run.provenance.startedUtc = provenance.at("started_utc").get<std::string>();
        run.provenance.wallSeconds = provenance.at("wall_seconds").get<double>();
        run.steps = document.at("steps").get<long>();
        run.framesTaken = document.at("frames_taken").get<int>();
        run.status = RunStatus::fromRecords(numbersFrom(document.at("status").at("metrics")),
                                            document.at("status").at("attributes").get<std::map<std::string, std::string>>());
        run.metrics = numbersFrom(document.at("metrics"));
        for (const json& entry : document.at("frames"))
        {
            RunFrame frame = frameEntry(entry);
            run.keptFrameNumbers.push_back(frame.number);
            if (withFrames)
            {
                frame.data = readFrame(runJson.parent_path() / entry.at("file").get<std::string>());
                run.frames.push_back(std::move(frame));
            }
        }
    }
    catch (const json::exception& exception)
    {
        throw Error("a run's run.json lacks an entry", {{"file", runJson.string()}, {"reason", exception.what()}});
    }
    return run;
}

RunFrame readRunFrame(const fs::path& runJson, std::size_t index)
{
    const json document = readRunJson(runJson);
    const json& frames = document.at("frames");
    if (index >= frames.size())
        throw Error(Pattern{"the run has no frame %1 (it kept %2)",
                            {std::to_string(index), std::to_string(frames.size())}});
    RunFrame frame = frameEntry(frames.at(index));
    frame.data = readFrame(runJson.parent_path() / frames.at(index).at("file").get<std::string>());
    return frame;
}

std::string checkRunFrames(const fs::path& runJson)
{
    try
    {
        const json document = readRunJson(runJson);
        for (const json& entry : document.at("frames"))
        {
            const std::string file = entry.at("file").get<std::string>();
            const fs::path path = runJson.parent_path() / file;
            std::error_code error;
            if (!fs::exists(path, error))
                return storedText(Pattern{"a frame of the run is missing: %1", {file}});
            if (fs::file_size(path, error) != entry.at("bytes").get<std::uintmax_t>() ||
                fileChecksum(path) != entry.at("crc32").get<std::uint32_t>())
                return storedText(Pattern{"a frame of the run differs from its record (damaged): %1", {file}});
        }
        return {};
    }
    catch (const std::exception& exception)
    {
        return std::string("the run's record cannot be read: ") + exception.what();
    }
}

std::vector<fs::path> runFolderFiles(const fs::path& folder)
{
    std::vector<fs::path> files;
    std::error_code error;
    for (const char* name : {"run.json", "series.pvd"})
        if (fs::is_regular_file(folder / name, error))
            files.push_back(folder / name);
    for (const auto& entry : fs::directory_iterator(folder / "frames", error))
        if (entry.is_regular_file() && std::regex_match(entry.path().filename().string(), kFrameName))
            files.push_back(entry.path());
    return files;
}

} // namespace vsim::study
