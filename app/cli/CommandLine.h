#pragma once

// The command line, declared once per command: its options (flag, one value, or repeatable), its positional
// arguments and its usage text. Parsing against the declaration is strict: an unknown option, a missing value, a
// single option given twice, a required option missing or an extra positional argument is a UsageError (exit code 2) naming the option and
// the accepted ones. The declarations also give the top-level usage and every command's --help.

#include "CliCommands.h"
#include "vsim/core/Error.h"

#include <string>
#include <vector>

namespace vsim::cli {

/// Bad command-line usage: main() prints it on one line and exits with code 2.
class UsageError : public Error
{
public:
    using Error::Error;
};

struct OptionSpec
{
    enum class Arity
    {
        Flag,      ///< --anonymize
        Value,     ///< --study S, once
        Repeatable ///< --param k=v, any number of times
    };
    std::string name;
    Arity arity = Arity::Value;
    bool required = false; ///< the command cannot run without it
};

struct CommandSpec
{
    std::string name;           ///< "segment", or a command with its subcommand: "mesh wall", "simulate fem"
    std::size_t minPositional;  ///< positional words after the name (a subcommand counts as one)
    std::size_t maxPositional;
    std::vector<OptionSpec> options;
    std::string usage;          ///< the synopsis and a description, as --help prints them
    int (*run)(const Arguments&, const Progress&) = nullptr; ///< the command; returns the exit code
};

/// Every command vascusim-cli knows, in the order of the top-level usage.
const std::vector<CommandSpec>& commandSpecs();
/// The declaration of the command that `words` (everything after the program name) start with; throws UsageError
/// for an unknown command or subcommand, listing the known ones.
const CommandSpec& findCommand(const std::vector<std::string>& words);
/// The top-level usage: every command's synopsis.
std::string usageText();

/// Parses the words after the command name (the subcommand included) against `spec`; --name=value is accepted
/// too. Throws UsageError as the header says.
Arguments parseArguments(const CommandSpec& spec, const std::vector<std::string>& words);
/// Applies the options that set process-wide state before a command runs (--uid-root); throws UsageError for a bad
/// value.
void applyProcessOptions(const Arguments& arguments);
/// Runs `words` (a command name and its arguments) as vascusim-cli would; returns its exit code and throws what
/// the command throws (UsageError for bad usage).
int runCommandLine(const std::vector<std::string>& words, const Progress& progress);

/// A number with an optional unit suffix that must be `unit` ("1.5" or "1.5mm" for mm); `fallback` when the
/// option is absent. Throws UsageError for another unit and vsim::Error for text that is not a number.
double quantityOption(const Arguments& arguments, const std::string& option, const std::string& unit, double fallback);
/// The same for a piece of an option's text (a list's item).
double quantityText(const std::string& text, const std::string& option, const std::string& unit);

} // namespace vsim::cli
