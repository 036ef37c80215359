// vascusim-cli: the headless twin of the workstation. Every step the GUI offers is a command here, with the same
// parameters, writing into the same study bundle. Exit codes: 0 success, 1 an error (one line on stderr naming
// what was wrong), 2 usage, 3 a simulation stopped by a guard (diverging, inverted elements: its last good state
// is saved and printed, and one line on stderr says where it stopped), 130 cancelled (Ctrl-C).

#include "CliCommands.h"
#include "CommandLine.h"
#include "vsim/core/Error.h"
#include "vsim/dicom/PacsClient.h"
#include "vsim/study/StudyLock.h"

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace {

vsim::CancellationToken g_cancel;

void onInterrupt(int)
{
    g_cancel.cancel();
}

} // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h")
    {
        std::cout << vsim::cli::usageText();
        return words.empty() ? 2 : 0;
    }
    if (words[0] == "--version" && words.size() == 1)
        return vsim::cli::printVersion();
    std::signal(SIGINT, onInterrupt);
    vsim::dicom::prepareDicomNetworking(); // before any thread reads the environment
    // A progress line only on a terminal: logs and pipes get the result and the errors alone.
    const bool showProgress = isatty(STDERR_FILENO) == 1;
    int lastPercent = -1;
    const vsim::Progress progress(
        [&lastPercent, showProgress](double fraction, const std::string& stage) {
            const int percent = static_cast<int>(fraction * 100.0);
            if (!showProgress)
                return;
            if (percent == lastPercent)
                return;
            lastPercent = percent;
            std::fprintf(stderr, "\r%3d%% %-40s%s", percent, stage.c_str(), percent >= 100 ? "\n" : "");
        },
        g_cancel);
    try
    {
        const vsim::cli::CommandSpec& spec = vsim::cli::findCommand(words);
        const std::vector<std::string> rest(words.begin() + 1, words.end());
        if (std::find(rest.begin(), rest.end(), "--help") != rest.end())
        {
            std::cout << "usage: vascusim-cli " << spec.usage << "\n";
            return 0;
        }
        const vsim::cli::Arguments arguments = vsim::cli::parseArguments(spec, rest);
        vsim::cli::applyProcessOptions(arguments);
        vsim::study::setLockProgramName("vascusim-cli " + spec.name);
        return spec.run(arguments, progress);
    }
    catch (const vsim::cli::UsageError& error)
    {
        std::cerr << "usage error: " << error.message() << "\n";
        return 2;
    }
    catch (const vsim::Cancelled&)
    {
        std::cerr << (lastPercent >= 0 ? "\n" : "") << "cancelled; nothing was written\n";
        return 130;
    }
    catch (const vsim::Error& error)
    {
        std::cerr << (lastPercent >= 0 ? "\n" : "") << "error: " << error.message() << "\n";
        for (const auto& [key, value] : error.context())
            std::cerr << "  " << key << ": " << value << "\n";
        return 1;
    }
    catch (const std::exception& error)
    {
        std::cerr << (lastPercent >= 0 ? "\n" : "") << "error: " << error.what() << "\n";
        return 1;
    }
}
