#include "CommandLine.h"

#include "vsim/core/DicomUid.h"
#include "vsim/core/Error.h"

#include <algorithm>
#include <set>

namespace vsim::cli {
namespace {

std::string acceptedOptions(const CommandSpec& spec)
{
    std::string list;
    for (const OptionSpec& option : spec.options)
        list += (list.empty() ? "--" : ", --") + option.name;
    return list.empty() ? "none" : list;
}

std::string knownCommands()
{
    std::string list;
    for (const CommandSpec& spec : commandSpecs())
        list += (list.empty() ? "" : ", ") + spec.name;
    return list;
}

std::string synopsis(const CommandSpec& spec) { return spec.usage.substr(0, spec.usage.find("\n    ")); }

} // namespace

const CommandSpec& findCommand(const std::vector<std::string>& words)
{
    if (words.empty())
        throw UsageError("no command given; commands: " + knownCommands());
    for (const CommandSpec& spec : commandSpecs())
    {
        const auto space = spec.name.find(' ');
        if (space == std::string::npos ? spec.name == words[0]
                                       : words.size() > 1 && spec.name.substr(0, space) == words[0] &&
                                             spec.name.substr(space + 1) == words[1])
            return spec;
    }
    std::string subcommands;
    for (const CommandSpec& spec : commandSpecs())
        if (spec.name.rfind(words[0] + " ", 0) == 0)
            subcommands += (subcommands.empty() ? "" : ", ") + spec.name;
    if (!subcommands.empty())
        throw UsageError("'" + words[0] + "' needs one of: " + subcommands);
    throw UsageError("unknown command '" + words[0] + "'; commands: " + knownCommands());
}

std::string usageText()
{
    std::string text = "usage: vascusim-cli <command> [arguments]   (vascusim-cli <command> --help for one command)\n\n"
                       "  --version\n    versions of VascuSim and its libraries, CUDA and GPUs found\n";
    for (const CommandSpec& spec : commandSpecs())
        text += "  " + synopsis(spec) + "\n";
    return text;
}

Arguments parseArguments(const CommandSpec& spec, const std::vector<std::string>& words)
{
    const std::string command = "vascusim-cli " + spec.name;
    Arguments arguments;
    std::set<std::string> seen;
    for (std::size_t w = 0; w < words.size(); ++w)
    {
        const std::string& word = words[w];
        if (word.rfind("--", 0) != 0)
        {
            arguments.positional.push_back(word);
            continue;
        }
        std::string name = word.substr(2), value;
        const auto equals = name.find('=');
        const bool inlineValue = equals != std::string::npos;
        if (inlineValue)
            value = name.substr(equals + 1), name = name.substr(0, equals);
        const auto option = std::find_if(spec.options.begin(), spec.options.end(),
                                         [&](const OptionSpec& candidate) { return candidate.name == name; });
        if (option == spec.options.end())
            throw UsageError(command + ": unknown option --" + name + " (accepted: " + acceptedOptions(spec) + ")");
        if (option->arity != OptionSpec::Arity::Repeatable && !seen.insert(name).second)
            throw UsageError(command + ": --" + name + " is given twice; give it once");
        if (option->arity == OptionSpec::Arity::Flag)
        {
            if (inlineValue)
                throw UsageError(command + ": --" + name + " takes no value");
            value = "true";
        }
        else if (!inlineValue)
        {
            if (w + 1 >= words.size() || words[w + 1].rfind("--", 0) == 0)
                throw UsageError(command + ": --" + name + " needs a value");
            value = words[++w];
        }
        if (value.empty())
            throw UsageError(command + ": --" + name + " needs a value");
        arguments.options.emplace_back(name, value);
    }
    for (const OptionSpec& option : spec.options)
        if (option.required && !arguments.hasOption(option.name))
            throw UsageError(command + ": --" + option.name + " is required; usage: vascusim-cli " + synopsis(spec));
    if (arguments.positional.size() < spec.minPositional || arguments.positional.size() > spec.maxPositional)
    {
        const std::string extra = arguments.positional.size() > spec.maxPositional
                                      ? "unexpected argument '" + arguments.positional.back() + "'"
                                      : "missing argument";
        throw UsageError(command + ": " + extra + "; usage: vascusim-cli " + synopsis(spec));
    }
    return arguments;
}

void applyProcessOptions(const Arguments& arguments)
{
    // The commands that make DICOM objects take --uid-root (vsim/core/DicomUid.h): the organisation's UID root.
    if (!arguments.hasOption("uid-root"))
        return;
    try
    {
        setDicomUidRoot(arguments.option("uid-root"));
    }
    catch (const Error& error)
    {
        throw UsageError(std::string("--uid-root: ") + error.what());
    }
}

int runCommandLine(const std::vector<std::string>& words, const Progress& progress)
{
    const CommandSpec& spec = findCommand(words);
    const Arguments arguments = parseArguments(spec, {words.begin() + 1, words.end()});
    applyProcessOptions(arguments);
    return spec.run(arguments, progress);
}

double quantityOption(const Arguments& arguments, const std::string& option, const std::string& unit, double fallback)
{
    return arguments.hasOption(option) ? quantityText(arguments.option(option), option, unit) : fallback;
}

double quantityText(const std::string& text, const std::string& option, const std::string& unit)
{
    std::size_t used = 0;
    double number = 0.0;
    try
    {
        number = std::stod(text, &used);
    }
    catch (const std::exception&)
    {
        throw Error("--" + option + " expects a number" + (unit.empty() ? "" : " in " + unit) + ", got '" + text + "'");
    }
    std::string suffix = text.substr(used);
    suffix.erase(std::remove(suffix.begin(), suffix.end(), ' '), suffix.end());
    if (!suffix.empty() && suffix != unit)
        throw UsageError("--" + option + ": unknown unit '" + suffix + "' (give " +
                         (unit.empty() ? std::string("a plain number") : unit) + ")");
    return number;
}

} // namespace vsim::cli
