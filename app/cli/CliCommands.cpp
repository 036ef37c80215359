#include "CliCommands.h"

#include "vsim/app/DemoStudy.h"
#include "vsim/app/StudySummary.h"
#include "vsim/app/VersionInfo.h"
#include "vsim/core/Error.h"
#include "vsim/study/Study.h"
#include "vsim/study/VolumeFileImport.h"

#include <filesystem>
#include <iostream>

namespace vsim::cli {
namespace fs = std::filesystem;

std::string Arguments::option(const std::string& name, const std::string& fallback) const
{
    for (const auto& [key, value] : options)
        if (key == name)
            return value;
    return fallback;
}

bool Arguments::hasOption(const std::string& name) const
{
    for (const auto& option : options)
        if (option.first == name)
            return true;
    return false;
}

Arguments parseArguments(const std::vector<std::string>& words)
{
    Arguments arguments;
    for (std::size_t w = 0; w < words.size(); ++w)
    {
        if (words[w].rfind("--", 0) == 0)
        {
            const std::string name = words[w].substr(2);
            const bool hasValue = w + 1 < words.size() && words[w + 1].rfind("--", 0) != 0;
            arguments.options.emplace_back(name, hasValue ? words[++w] : std::string("true"));
        }
        else
        {
            arguments.positional.push_back(words[w]);
        }
    }
    return arguments;
}

int printVersion()
{
    for (const auto& [component, version] : app::libraryVersions())
        std::cout << component << " " << version << "\n";
    return 0;
}

int printStudyInfo(const Arguments& arguments)
{
    if (arguments.positional.size() != 1)
        throw Error("usage: vascusim-cli info <study.vsim>");
    const study::Study study = study::Study::open(arguments.positional[0]);
    std::cout << app::studySummaryJson(study) << std::endl;
    return 0;
}

int importVolume(const Arguments& arguments, const Progress& progress)
{
    const std::string bundle = arguments.option("study");
    if (arguments.positional.size() != 1 || bundle.empty())
        throw Error("usage: vascusim-cli import <volume.nii|.nii.gz|.nrrd|.mha|.mhd> --study <study.vsim>");
    const fs::path file = arguments.positional[0];
    study::Study study = fs::exists(fs::path(bundle) / "study.json")
                             ? study::Study::open(bundle)
                             : study::Study::create(bundle, fs::path(bundle).stem().string());
    const std::string id = study::importVolumeFile(study, file, progress);
    study.save();
    const auto& artifact = study.artifact(id);
    std::cout << "imported " << file.filename().string() << " as " << id << "\n";
    for (const std::string& warning : artifact.warnings)
        std::cout << "warning: " << warning << "\n";
    return 0;
}

int writeDemoStudy(const Arguments& arguments, const Progress& progress)
{
    const fs::path bundle = arguments.option("out", app::defaultDemoStudyPath().string());
    std::cout << app::ensureDemoStudy(bundle, progress).string() << "\n";
    return 0;
}

} // namespace vsim::cli
