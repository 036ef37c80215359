#pragma once

#include "CliCommands.h"

namespace vsim::cli {

/// `report --study S --out report.pdf [--sections aaa,stenosis,chemoembolization,smoke,runs] [--page a4|letter]
/// [--dicom-pdf out.dcm] [--anonymize] [--metrics-csv F] [--metrics-json F] [--no-validation]`: the study's
/// clinical report as PDF (also kept in the study: reports/<id>.pdf), optionally as a DICOM Encapsulated PDF in a
/// new series of the study, and its metrics.
int writeReport(const Arguments& arguments, const Progress& progress);

} // namespace vsim::cli
