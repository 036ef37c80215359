#include "DemoCommand.h"

#include "NetworkCommands.h"
#include "ReportCommand.h"
#include "WallCommands.h"
#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/dicom/PhantomModel.h"
#include "vsim/dicom/PhantomWriter.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iostream>
#include <sstream>

namespace vsim::cli {
namespace {

namespace fs = std::filesystem;

/// Runs one command as `vascusim-cli <words>` would, its JSON output kept out of the demo's own.
std::string step(const std::vector<std::string>& words, const Progress& progress)
{
    std::ostringstream captured;
    std::streambuf* previous = std::cout.rdbuf(captured.rdbuf());
    try
    {
        runCommandLine(words, progress);
    }
    catch (...)
    {
        std::cout.rdbuf(previous);
        throw;
    }
    std::cout.rdbuf(previous);
    return captured.str();
}

std::string triple(const Eigen::Vector3d& p)
{
    std::ostringstream text;
    text << p.x() << "," << p.y() << "," << p.z();
    return text.str();
}

/// The hepatic phantom's catheter tip (the root of the tree) and tumour sphere, as simulate network takes them.
std::pair<std::string, std::string> hepaticTipAndTumour()
{
    const dicom::PhantomModel model = dicom::buildPhantomModel(dicom::PhantomKind::HepaticTree, {});
    Eigen::Vector3d root = model.nodes.front().position;
    for (const dicom::VesselSegment& segment : model.segments)
        if (segment.parent < 0)
            root = model.nodes[std::size_t(segment.from)].position;
    const auto& m = model.measures;
    const Eigen::Vector3d centre(m.at("tumour_centre_x_mm"), m.at("tumour_centre_y_mm"), m.at("tumour_centre_z_mm"));
    std::ostringstream tumour;
    tumour << triple(centre) << "," << m.at("tumour_radius_mm");
    return {triple(root), tumour.str()};
}

} // namespace

int runDemo(const Arguments& arguments, const Progress& progress)
{
    const std::string out = arguments.option("out");
    dicom::PhantomOptions options;
    if (arguments.hasOption("size"))
        options.size = parseTriple<int>(arguments.option("size"), 'x', "size");
    claimOutputFolder(out, "demo");
    const std::vector<std::string> cases = {"aaa", "hepatic-tree", "stenosis"};
    for (const std::string& kind : cases)
        if (fs::exists(fs::path(out) / kind))
            throw Error("the demo folder already holds a " + kind + " demo; choose a new or empty --out",
                        {{"folder", (fs::path(out) / kind).string()}});
    nlohmann::json summary = nlohmann::json::array();
    for (std::size_t c = 0; c < cases.size(); ++c)
    {
        const std::string& kind = cases[c];
        const Progress part = progress.subRange(double(c) / cases.size(), double(c + 1) / cases.size());
        auto stage = [&](double from, double to) { return part.subRange(from, to); };
        const fs::path folder = fs::path(out) / kind;
        const std::string study = (folder / (kind + ".vsim")).string(), phantom = (folder / "phantom").string();
        const dicom::PhantomKind phantomKind = dicom::phantomKindFromName(kind);
        const dicom::PhantomFiles phantomFiles = dicom::writePhantom(
            phantomKind, options, dicom::phantomSeriesDescription(phantomKind), phantom, stage(0.0, 0.1));
        step({"import", phantomFiles.dicomFolder.string(), "--study", study}, stage(0.1, 0.2));
        step({"segment", "--study", study}, stage(0.2, 0.35));
        step({"skeleton", "--study", study}, stage(0.35, 0.45));
        step({"centerline", "--study", study}, stage(0.45, 0.55));
        if (kind == "aaa")
        {
            step({"mesh", "wall", "--study", study}, stage(0.55, 0.6));
            // The demo patient is a man without a family history of AAA: stated, as the strength model needs both.
            step({"simulate", "fem", "--study", study, "--protocol", "physiological", "--backend", "auto", "--param",
                  "female=0", "--param", "family_history=0", "--out", (folder / "wall-run").string()},
                 stage(0.6, 0.85));
        }
        if (kind == "hepatic-tree")
        {
            const auto [tip, tumour] = hepaticTipAndTumour();
            step({"simulate", "network", "--study", study, "--tip", tip, "--tumour", tumour, "--out",
                                   (folder / "network-run").string()},
                 stage(0.55, 0.85));
        }
        const std::string report = (folder / "report.pdf").string();
        const std::string written =
            step({"report", "--study", study, "--out", report, "--dicom-pdf", (folder / "report.dcm").string(),
                               "--metrics-json", (folder / "metrics.json").string(), "--metrics-csv",
                               (folder / "metrics.csv").string()},
                 stage(0.85, 1.0));
        removeWrittenFiles(phantomFiles.series.files, phantomFiles.dicomFolder); // the CT is in the study now; truth stays
        nlohmann::json entry = nlohmann::json::parse(written);
        entry["case"] = kind;
        entry["study"] = study;
        summary.push_back(entry);
    }
    progress.report(1.0, "demo written");
    std::cout << summary.dump(2) << "\n";
    return 0;
}

} // namespace vsim::cli
