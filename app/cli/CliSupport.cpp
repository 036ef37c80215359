#include "CliSupport.h"

#include "vsim/core/Error.h"


namespace vsim::cli {

std::string chooseArtifact(const study::Study& study, const std::string& wanted, study::ArtifactKind kind,
                           const std::string& missing)
{
    return chooseMadeBy(study, wanted, kind, {}, missing);
}

std::string chooseMadeBy(const study::Study& study, const std::string& wanted, study::ArtifactKind kind,
                         const std::string& command, const std::string& missing)
{
    if (!wanted.empty())
        return study.artifact(wanted).id;
    const std::string newest = study.newestArtifact(kind, command);
    if (newest.empty())
        throw Error(missing);
    return newest;
}

std::string chooseCenterlines(const study::Study& study, const std::string& wanted)
{
    return chooseMadeBy(study, wanted, study::ArtifactKind::Skeleton, "centerline",
                        "the study has no centerlines: run vascusim-cli centerline first");
}

void applyParameters(const Arguments& arguments, ParameterSet& parameters)
{
    for (const auto& [name, value] : arguments.options)
        if (name == "param")
            parameters.setFromText(value);
}

} // namespace vsim::cli
