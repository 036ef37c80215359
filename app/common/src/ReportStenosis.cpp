#include "ReportSections.h"

#include "ReportSupport.h"

namespace vsim::app::detail {
namespace {

constexpr double kReportedStenosisPercent = 40.0; // a narrowing from which the stenosis section is written

} // namespace

std::optional<report::Section> stenosisSection(const study::Study& study, VesselSections& sections,
                                               const Progress& progress)
{
    const imaging::VesselMeasurements* measured =
        sections.of(study.newestArtifact(study::ArtifactKind::Skeleton, "centerline"), progress);
    if (!measured || measured->worstStenosisSegment < 0)
        return std::nullopt;
    const imaging::SegmentMeasurements& worst = measured->segments[std::size_t(measured->worstStenosisSegment)];
    if (worst.diameterStenosisPercent < kReportedStenosisPercent)
        return std::nullopt;
    report::Section section{"stenosis", "Stenosis / blockage", {}};
    report::MetricTable geometry{"The narrowest segment (cross-sections perpendicular to the centerline)", {}};
    geometry.rows = {report::metric("diameter_stenosis_percent", "Diameter stenosis", worst.diameterStenosisPercent, "%"),
                     report::metric("area_stenosis_percent", "Area stenosis", worst.areaStenosisPercent, "%"),
                     report::metric("reference_diameter_mm", "Reference diameter (median)", worst.referenceDiameterMm, "mm"),
                     report::metric("minimal_diameter_mm", "Minimal diameter", worst.minimalDiameterMm, "mm"),
                     report::metric("segment_length_mm", "Segment length", worst.lengthMm, "mm")};
    section.blocks.push_back(geometry);
    report::Plot plot = diameterPlot(worst, "Diameter along the narrowest segment");
    plot.references = {{"reference diameter", worst.referenceDiameterMm}};
    section.blocks.push_back(plot);
    section.blocks.push_back(report::Paragraph{
        "Blockage velocity ratios, the pressure drop, the velocity along the centerline and the wall pressure come "
        "from a blood-flow run; this study has none (the blood-flow solver is not part of this version)."});
    return section;
}

} // namespace vsim::app::detail
