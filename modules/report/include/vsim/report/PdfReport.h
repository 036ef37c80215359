#pragma once

// A report as PDF (QPdfWriter): text and tables as text, plots as vector paths, pictures at their resolution, fonts
// embedded, A4 or Letter. Needs a QGuiApplication (fonts); the CLI starts one on the offscreen platform.

#include "vsim/report/ReportModel.h"

#include <QByteArray>

#include <filesystem>
#include <string>

namespace vsim::report {

enum class PageSize
{
    A4,
    Letter,
};

/// "a4" or "letter" (any case); throws vsim::Error for another name.
PageSize pageSizeFromName(const std::string& name);

/// The report as PDF bytes.
QByteArray renderPdf(const Report& report, PageSize size = PageSize::A4);

/// Writes renderPdf() to `file`; throws vsim::Error when it cannot be written.
void writePdf(const Report& report, const std::filesystem::path& file, PageSize size = PageSize::A4);

} // namespace vsim::report
