// The report's measurements section: the rulers, angles and ROIs the user marked "in report" on the workstation
// (measurement artifacts with the attribute in_report = 1), each with its figure, unit, definition and where it
// was drawn.
#include "ReportSections.h"

#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/ViewMeasurement.h"

#include <cstdio>

namespace vsim::app::detail {
namespace {

std::string pointText(const Eigen::Vector3d& p)
{
    char text[96];
    std::snprintf(text, sizeof text, "(%.1f, %.1f, %.1f)", p.x(), p.y(), p.z());
    return text;
}

} // namespace

std::optional<report::Section> measurementsSection(const study::Study& study)
{
    report::Table table;
    table.caption = localized(
        "Report", "Measurements marked for the report on the workstation. Points in the patient frame (LPS, mm).");
    table.columns = {localized("Report", "Measurement"), localized("Report", "Figure"),
                     localized("Report", "Definition"), localized("Report", "Points [mm]")};
    for (const study::Artifact& artifact : study.artifacts())
    {
        const auto inReport = artifact.attributes.find("in_report");
        if (artifact.kind != study::ArtifactKind::Measurement || artifact.damaged || inReport == artifact.attributes.end() ||
            inReport->second != "1")
            continue;
        const ViewMeasurement m = study.loadMeasurement(artifact.id);
        std::string points;
        for (const Eigen::Vector3d& p : m.pointsMm)
            points += (points.empty() ? "" : " ") + pointText(p);
        const std::string name = storedTextForPeople(artifact.name);
        const std::size_t colon = name.find(':');
        table.rows.push_back({colon == std::string::npos ? name : name.substr(0, colon),
                              measurementText(m, true), measurementDefinition(m.kind, true), points});
    }
    if (table.rows.empty())
        return std::nullopt;
    report::Section section;
    section.id = "measurements";
    section.title = localized("Report", "Measurements");
    section.blocks.push_back(std::move(table));
    return section;
}

} // namespace vsim::app::detail
