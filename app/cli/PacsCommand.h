#pragma once

// vascusim-cli pacs echo | find | get | store (issue 22): a PACS node given by --aet, --host and --port.

#include "CommandLine.h"
#include "vsim/core/Progress.h"

namespace vsim::cli {

/// C-ECHO; prints {"echo": "ok", ...}. Exit 1 with the reason when the node does not answer.
int pacsEchoCommand(const Arguments& arguments, const Progress& progress);
/// Study-level C-FIND with --patient-name, --patient-id, --date FROM-TO (YYYYMMDD), --modality; prints the matches.
int pacsFindCommand(const Arguments& arguments, const Progress& progress);
/// C-GET (or C-MOVE with --move PORT) of --study-uid into <--out>/dicom (--out new, empty or VascuSim's); prints the
/// files' count and folder.
int pacsGetCommand(const Arguments& arguments, const Progress& progress);
/// C-STORE of the positional files (--anonymized refuse|new-study); prints what was stored, in which study.
int pacsStoreCommand(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
