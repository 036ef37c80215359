#pragma once

// The clinical report of a study as the CLI (`vascusim-cli report`) and the workstation (File > Export Report)
// make it: a section for each analysis the study holds a run of (AAA wall mechanics, stenosis, chemoembolization),
// the analyses not run named as such, and for every run its parameters, solver, backend, steps, time and the
// validation status of its solver in this build.

#include "vsim/core/Progress.h"
#include "vsim/report/EncapsulatedPdf.h"
#include "vsim/report/ReportModel.h"
#include "vsim/study/Study.h"

#include <QImage>

#include <functional>
#include <set>
#include <string>

namespace vsim::app {

/// Section ids: "aaa", "stenosis", "chemoembolization", "smoke", "measurements" (those marked in the workstation), "runs".
std::vector<std::string> reportSectionIds();

struct ReportOptions
{
    bool anonymize = false;         ///< no patient identifiers in the header (nor in documentIdentity())
    std::set<std::string> sections; ///< empty: every section the study can fill; else these (reportSectionIds())
    bool validate = true;           ///< run the validation cases of the solvers reported (a few seconds)
    int snapshotPixels = 2000;      ///< width of the 3D snapshots (print resolution over the text width)
    /// The report's language (TextLanguage.h: textLanguages() or a catalogue file), for its provenance: the
    /// caller builds and renders the report inside a ScopedTextLanguage of it.
    std::string language = "en";
    /// Runs a snapshot's rendering and returns the picture; empty: right here. The workstation renders on its GUI
    /// thread (OpenGL) while the report is built in the background.
    std::function<QImage(const std::function<QImage()>&)> renderSnapshot;
};

/// Builds the report of `study`. Throws vsim::Error for an unknown section id.
report::Report buildStudyReport(const study::Study& study, const ReportOptions& options, const Progress& progress = {});

/// Adds the report's PDF to the study (reports/<id>.pdf; provenance: the runs reported, the sections, anonymized,
/// the paper `page`); returns its id. The study is not saved.
std::string addReport(study::Study& study, const report::Report& report, const std::string& pdf,
                      const ReportOptions& options, const std::string& page);

/// Who the report's DICOM instance belongs to: the study's Study Instance UID and dates; the patient's name, ID,
/// birth date and sex unless anonymized (then "ANONYMIZED" and an ID that does not identify).
report::DocumentIdentity documentIdentity(const study::Study& study, bool anonymize);

} // namespace vsim::app
