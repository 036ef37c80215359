#include "ReportCommand.h"

#include "CliSupport.h"
#include "vsim/app/StudyReport.h"
#include "vsim/app/TextLanguage.h"
#include "vsim/core/Error.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/report/EncapsulatedPdf.h"
#include "vsim/report/MetricsExport.h"
#include "vsim/report/PdfReport.h"

#include <QGuiApplication>

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace vsim::cli {
namespace {

/// Fonts and painting need a QGuiApplication; the CLI starts one on the offscreen platform (no display needed).
std::unique_ptr<QGuiApplication> guiApplication()
{
    if (QGuiApplication::instance())
        return nullptr;
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    static int argc = 1;
    static char name[] = "vascusim-cli";
    static char* argv[] = {name, nullptr};
    return std::make_unique<QGuiApplication>(argc, argv);
}

std::set<std::string> sectionList(const std::string& text)
{
    std::set<std::string> sections;
    std::istringstream stream(text);
    for (std::string id; std::getline(stream, id, ',');)
        if (!id.empty())
            sections.insert(id);
    return sections;
}

} // namespace

int writeReport(const Arguments& arguments, const Progress& progress)
{
    const std::string bundle = arguments.option("study"), out = arguments.option("out");
    const std::string pageName = arguments.option("page", "a4");
    const report::PageSize page = report::pageSizeFromName(pageName);
    // Every output file is checked before the report is built: an existing one is replaced only with --overwrite.
    for (const char* option : {"out", "dicom-pdf", "metrics-csv", "metrics-json"})
        if (arguments.hasOption(option))
            checkOutputFile(arguments.option(option), arguments.hasOption("overwrite"));
    // A reader: a study another process is writing is reported all the same, and the PDF is not kept in it.
    std::string notKept;
    std::optional<study::Study> opened;
    try
    {
        opened.emplace(study::Study::open(bundle, study::Access::Write, waitSeconds(arguments)));
    }
    catch (const Error& error)
    {
        if (error.contextValue("holder").empty())
            throw;
        notKept = error.message();
        opened.emplace(study::Study::open(bundle, study::Access::ReadOnly));
    }
    study::Study& study = *opened;
    app::ReportOptions options;
    options.anonymize = arguments.hasOption("anonymize");
    options.validate = !arguments.hasOption("no-validation");
    options.sections = sectionList(arguments.option("sections"));
    options.language = arguments.option("language", "en");
    const auto application = guiApplication();
    const app::ScopedTextLanguage language{app::TextLanguage(options.language)}; // the texts built and rendered here
    const report::Report report = app::buildStudyReport(study, options, progress.subRange(0.0, 0.9));
    const QByteArray pdf = report::renderPdf(report, page);
    report::writeText(std::string(pdf.constData(), std::size_t(pdf.size())), out);
    nlohmann::json summary = {{"pdf", out}, {"bytes", pdf.size()}, {"anonymized", options.anonymize}};
    try // the report is written; keeping it in the study too may fail (a read-only study) without losing it
    {
        if (!notKept.empty())
            throw Error(notKept);
        summary["artifact"] = app::addReport(study, report, std::string(pdf.constData(), std::size_t(pdf.size())),
                                             options, pageName);
        study.save();
    }
    catch (const Error& error)
    {
        summary["warning"] = "the report was not kept in the study: " + error.message();
    }
    if (arguments.hasOption("dicom-pdf"))
    {
        const std::string series =
            report::writeEncapsulatedPdf(pdf, app::documentIdentity(study, options.anonymize), arguments.option("dicom-pdf"));
        summary["dicom_pdf"] = arguments.option("dicom-pdf");
        summary["series_instance_uid"] = series;
    }
    if (arguments.hasOption("metrics-csv"))
        report::writeText(report::metricsCsv(report), arguments.option("metrics-csv"));
    if (arguments.hasOption("metrics-json"))
        report::writeText(report::metricsJson(report), arguments.option("metrics-json"));
    nlohmann::json sections = nlohmann::json::array();
    for (const report::Section& section : report.sections)
        sections.push_back(section.id);
    summary["sections"] = sections;
    summary["not_run"] = report.notRun;
    summary["metrics"] = report.metrics().size();
    progress.report(1.0, "report written");
    std::cout << summary.dump(2) << "\n";
    return 0;
}

} // namespace vsim::cli
