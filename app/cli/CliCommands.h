#pragma once

#include "vsim/core/Progress.h"

#include <string>
#include <vector>

namespace vsim::cli {

/// Arguments after the command name, with "--name value" options split out (CommandLine.h parses them; a flag
/// has the value "true").
struct Arguments
{
    std::vector<std::string> positional;
    std::vector<std::pair<std::string, std::string>> options;

    /// The value of --name, or `fallback` when absent.
    std::string option(const std::string& name, const std::string& fallback = {}) const;
    bool hasOption(const std::string& name) const;
};

/// Each command returns the process exit code and throws vsim::Error for bad input.
int printVersion();
int printStudyInfo(const Arguments& arguments);
/// `parameters [TABLE] [--json]`: the declared parameters of every step (ParametersCommand.cpp).
int printParameters(const Arguments& arguments);
/// `import <dir|DICOMDIR|file> --study S [--series KEY] [--list] [--memory-limit-mb N]`: DICOM, or a
/// NIfTI / NRRD / MetaImage volume file.
int importIntoStudy(const Arguments& arguments, const Progress& progress);
/// `import <mask> --study S --as-label [--label-value N] [--image ID] [--series KEY]`: a mask from elsewhere as a
/// label on the study's image grid (ImportLabelCommand.cpp).
int importLabelIntoStudy(const Arguments& arguments, const Progress& progress);
/// `phantom <kind> --out DIR [--size CxRxS] [--spacing x,y,z] [--noise HU] [--seed N] [--transfer-syntax T]
/// [--max-diameter mm] [--stenosis percent] [--blur mm] [--enhanced]`.
int writePhantomSeries(const Arguments& arguments, const Progress& progress);
/// `segment --study S [--image ID] [--seed x,y,z] [--param key=value ...]`: adds a vessel label to the study.
int segmentStudy(const Arguments& arguments, const Progress& progress);
/// `sac --study S [--label ID] [--image ID] [--wall-thickness mm]`: the AAA sac (outer contour, thrombus, wall) of
/// a lumen label as a label artifact, and its figures (SacCommand.cpp).
int sacStudy(const Arguments& arguments, const Progress& progress);
/// `segment-organ`: a liver or tumour label grown from points (OrganCommand.cpp).
int segmentOrgan(const Arguments& arguments, const Progress& progress);
/// `surface --study S [--label ID] [--target-vertices N] [--stl FILE] [--param key=value ...]`: adds the lumen
/// surface of a vessel label to the study (and writes it as STL when asked).
int surfaceStudy(const Arguments& arguments, const Progress& progress);
/// `skeleton --study S [--label ID] [--param key=value ...]`: adds the unit-width skeleton graph of a vessel label.
int skeletonStudy(const Arguments& arguments, const Progress& progress);
/// `centerline --study S [--skeleton ID] [--label ID] [--from NODE --to NODE] [--param key=value ...]`: smoothed
/// centerlines of every skeleton edge (or of one path) into the study.
int centerlineStudy(const Arguments& arguments, const Progress& progress);
/// `measure --study S [--centerlines ID] [--label ID] [--json FILE]`: cross-sections, lengths, radii, maximum
/// diameter and stenosis along the newest centerlines, printed (and written as JSON when asked).
int measureStudy(const Arguments& arguments, const Progress& progress);
/// `export-label --study S [--label ID] --out FILE`: a label as a DICOM SEG (ExportLabelCommand.cpp).
int exportLabelFromStudy(const Arguments& arguments, const Progress& progress);
/// `rename-segment --study S [--centerlines ID] --segment N --name TEXT`: the user's name for a segment.
int renameSegmentInStudy(const Arguments& arguments, const Progress& progress);
int writeDemoStudy(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
