// vascusim-cli: the headless twin of the workstation. Every step the GUI offers is a command here, with the same
// parameters, writing into the same study bundle. Exit codes: 0 success, 1 an error (one line on stderr naming
// what was wrong), 2 usage, 130 cancelled (Ctrl-C).

#include "CliCommands.h"
#include "DemoCommand.h"
#include "NetworkCommands.h"
#include "ReportCommand.h"
#include "ValidateCommand.h"
#include "WallCommands.h"
#include "vsim/core/Error.h"

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

constexpr const char* kUsage = R"(usage: vascusim-cli <command> [arguments]

commands:
  --version                                  versions of VascuSim and its libraries, CUDA and GPUs found
  info <study.vsim>                          the study's metadata and artifacts as JSON
  import <dir|DICOMDIR|file> --study <study.vsim> [--series KEY] [--list] [--memory-limit-mb N]
                                             add a DICOM series (the CT with most slices unless --series) or a
                                             NIfTI / NRRD / MetaImage volume; creates the study if needed;
                                             --list prints the series found as JSON and imports nothing
  phantom <aaa|stenosis|hepatic-tree|bifurcation> --out <dir> [--size 512x512x400] [--spacing 0.7,0.7,1.0]
          [--noise 20] [--seed 1] [--transfer-syntax explicit-le|implicit-le|jpeg-lossless|jpeg-ls|rle]
          [--max-diameter 55] [--stenosis 50] [--blur mm] [--enhanced]
                                             write a CT phantom series (<dir>/dicom) with truth.json and
                                             truth-label.nrrd
  segment --study <study.vsim> [--image ID] [--seed x,y,z] [--param key=value ...]
                                             segment the contrast-filled vessels (automatic seed unless given, mm)
                                             into a label artifact
  surface --study <study.vsim> [--label ID] [--target-vertices N] [--stl FILE] [--param key=value ...]
                                             the lumen surface of the newest vessel label (VTP in the study)
  skeleton --study <study.vsim> [--label ID] [--param key=value ...]
                                             unit-width skeleton graph (thinning + VDSM) of the newest label
  centerline --study <study.vsim> [--skeleton ID] [--from NODE --to NODE] [--param key=value ...]
                                             B-spline centerlines (fast marching + minimal paths) of every skeleton
                                             edge, or of one path between two skeleton nodes
  measure --study <study.vsim> [--centerlines ID] [--json FILE]
                                             cross-sections, lengths, radii, maximum diameter, stenosis
  mesh wall --study <study.vsim> [--label ID] [--centerlines ID] [--thickness 1.5] [--target-vertices 3000]
                                             tetrahedral vessel wall (one layer) around the lumen, opened at the
                                             centerline ends (fixed sets)
  mesh sheet --study <study.vsim> [--width 40] [--length 40] [--thickness 0.5] [--cell 1]
                                             a thin cloth-type sheet (thesis 4.7.3), edges across x fixed
  mesh import <mesh.vtu> --study <study.vsim> a tetrahedral mesh from outside as a wall (its ends fixed)
  simulate fem --study <study.vsim> --protocol thesis-rupture|physiological [--mesh ID] [--backend auto|cpu|cuda]
               [--param key=value ...] [--out DIR]
                                             wall mechanics: the last frame (stresses, rupture index) and the metrics
                                             into the study; the frame series (.vtu, series.pvd, metrics.json) to DIR
  simulate network --study <study.vsim> --tip NODE|x,y,z [--rate 2ml/min|g/min | --tip-pressure mmHg]
                   [--void-fraction 0.1]
                   [--tumour x,y,z,r | --tumour-label ID [--tumour-value N]] [--control x,y,z ...]
                   [--network FILE [--default-outlets murray]]
                   [--param key=value ...] [--out DIR]
                                             drug delivery (two-phase conical Hagen-Poiseuille network): flow split,
                                             filling, control points two-phase vs liquid, tumour share and the best
                                             tip positions; the solved network into the study, the run files to DIR
  validate <case|fem|network|all>            analytic validation (JSON) of the wall solver (fem-patch, fem-rotation,
                                             fem-cantilever, fem-lame, fem-damping) and the drug network
                                             (network-cylinder, network-cone, network-conservation,
                                             network-bifurcation, network-confluence); exit 0 only when every
                                             figure is within its tolerance
  report --study <study.vsim> --out <report.pdf> [--sections aaa,stenosis,chemoembolization,smoke,runs]
         [--page a4|letter] [--dicom-pdf <out.dcm>] [--anonymize] [--metrics-csv F] [--metrics-json F]
         [--no-validation]
                                             the clinical report (PDF): a section per analysis run, the analyses not
                                             run, each run's parameters and its solver's validation; as DICOM
                                             Encapsulated PDF in a new series of the study; the metrics as CSV / JSON
  demo --out <dir> [--size 512x512x400]      the aaa, hepatic-tree and stenosis phantoms through the whole
                                             pipeline with default parameters (the AAA wall at blood pressure, the
                                             drug network from the hepatic root), each study with its report
  demo-study [--out <study.vsim>]            write the built-in demo study (default: ~/.local/share/VascuSim)
)";

} // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> words(argv + 1, argv + argc);
    if (words.empty() || words[0] == "--help" || words[0] == "-h")
    {
        std::cout << kUsage;
        return words.empty() ? 2 : 0;
    }
    std::signal(SIGINT, onInterrupt);
    const std::string command = words[0];
    const vsim::cli::Arguments arguments = vsim::cli::parseArguments({words.begin() + 1, words.end()});
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
        if (command == "--version")
            return vsim::cli::printVersion();
        if (command == "info")
            return vsim::cli::printStudyInfo(arguments);
        if (command == "import")
            return vsim::cli::importIntoStudy(arguments, progress);
        if (command == "segment")
            return vsim::cli::segmentStudy(arguments, progress);
        if (command == "surface")
            return vsim::cli::surfaceStudy(arguments, progress);
        if (command == "skeleton")
            return vsim::cli::skeletonStudy(arguments, progress);
        if (command == "centerline")
            return vsim::cli::centerlineStudy(arguments, progress);
        if (command == "measure")
            return vsim::cli::measureStudy(arguments, progress);
        if (command == "phantom")
            return vsim::cli::writePhantomSeries(arguments, progress);
        if (command == "mesh")
            return vsim::cli::meshWall(arguments, progress);
        if (command == "simulate" && !arguments.positional.empty() && arguments.positional.front() == "network")
            return vsim::cli::simulateNetwork(arguments, progress);
        if (command == "simulate")
            return vsim::cli::simulateFem(arguments, progress);
        if (command == "validate")
            return vsim::cli::validateSolvers(arguments, progress);
        if (command == "report")
            return vsim::cli::writeReport(arguments, progress);
        if (command == "demo")
            return vsim::cli::runDemo(arguments, progress);
        if (command == "demo-study")
            return vsim::cli::writeDemoStudy(arguments, progress);
        std::cerr << "unknown command '" << command << "'\n" << kUsage;
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
