#include "CliSupport.h"

#include "CommandLine.h"
#include "vsim/core/Error.h"

#include <iostream>
#include <sstream>

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

double waitSeconds(const Arguments& arguments)
{
    const double seconds = quantityOption(arguments, "wait", "s", 0.0);
    if (!(seconds >= 0.0))
        throw UsageError("--wait expects seconds >= 0");
    return seconds;
}

study::Study openStudyForWriting(const Arguments& arguments)
{
    const std::string bundle = arguments.option("study");
    if (bundle.empty())
        throw UsageError("--study <study.vsim> is required");
    return study::Study::open(bundle, study::Access::Write, waitSeconds(arguments));
}

study::Study openStudyForReading(const std::string& bundle)
{
    if (bundle.empty())
        throw UsageError("--study <study.vsim> is required");
    return study::Study::open(bundle, study::Access::ReadOnly);
}

int runExitCode(const RunStatus& status, const std::string& artifact)
{
    if (status.stoppedBy != RunStatus::StoppedBy::Guard)
        return 0;
    std::cerr << "vascusim-cli: the run " << status.stopText() << "; its last good state is saved as " << artifact << "\n";
    return 3;
}

void applyParameters(const Arguments& arguments, ParameterSet& parameters)
{
    for (const auto& [name, value] : arguments.options)
        if (name == "param")
            parameters.setFromText(value);
}

std::vector<double> parseNumbers(const std::string& text, char separator, std::size_t count, const std::string& option)
{
    const std::string expected = "--" + option + " expects " + std::to_string(count) + " numbers separated by '" +
                                 std::string(1, separator) + "', got '" + text + "'";
    std::vector<double> values;
    std::istringstream stream(text);
    std::string part;
    while (std::getline(stream, part, separator))
    {
        std::size_t used = 0;
        double value = 0.0;
        try
        {
            value = std::stod(part, &used);
        }
        catch (const std::exception&)
        {
            used = 0;
        }
        if (used == 0 || used != part.size())
            throw Error(expected);
        values.push_back(value);
    }
    if (values.size() != count)
        throw Error(expected);
    return values;
}

} // namespace vsim::cli
