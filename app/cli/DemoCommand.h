#pragma once

#include "CliCommands.h"

namespace vsim::cli {

/// `demo --out DIR [--size 512x512x400]`: the `aaa`, `hepatic-tree` and `stenosis` phantoms through the whole
/// pipeline with default parameters (import, segment, skeleton, centerlines; the AAA wall at blood pressure on the
/// GPU when there is one, else the CPU; the drug network from the hepatic root with the phantom's tumour), each
/// into DIR/<case>/<case>.vsim with its report (report.pdf, report.dcm, metrics.json, metrics.csv) and the runs'
/// own files (wall-run/, network-run/). The headless form of the README's run command.
int runDemo(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
