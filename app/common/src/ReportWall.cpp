#include "ReportSections.h"

#include "ReportSupport.h"
#include "vsim/app/SacRecord.h"
#include "vsim/app/WallPipeline.h"
#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"
#include "vsim/imaging/AneurysmSac.h"
#include "vsim/imaging/VesselMeasurements.h"
#include "vsim/viz/Snapshot.h"

#include <algorithm>
#include <optional>

namespace vsim::app::detail {
namespace {

constexpr double kRepairThresholdMenMm = 55.0;   // 5.5 cm (EVAR / open repair guidelines)
constexpr double kRepairThresholdWomenMm = 50.0; // 5.0 cm

/// The centerlines a wall run used (its second input), else the newest centerlines.
std::string centerlinesOf(const study::Study& study, const study::Artifact& run)
{
    const auto& inputs = run.provenance.inputs;
    if (inputs.size() > 1 && study.hasArtifact(inputs[1]) && !study.artifact(inputs[1]).damaged)
        return inputs[1];
    return study.newestArtifact(study::ArtifactKind::Skeleton, "centerline");
}

/// The diameter along the centerline of the segment with the largest maximum diameter, with the repair thresholds.
report::Plot aneurysmPlot(const imaging::VesselMeasurements& measured)
{
    const auto widest = std::max_element(measured.segments.begin(), measured.segments.end(),
                                         [](const auto& a, const auto& b) { return a.maxDiameterMm < b.maxDiameterMm; });
    report::Plot plot =
        diameterPlot(widest == measured.segments.end() ? imaging::SegmentMeasurements{} : *widest,
                     localized("Report", "Diameter along the centerline (the segment of the maximum diameter)"));
    plot.references = {{localized("Report", "repair threshold, men: 55 mm"), kRepairThresholdMenMm},
                       {localized("Report", "repair threshold, women: 50 mm"), kRepairThresholdWomenMm}};
    return plot;
}

std::string thresholdSentence(double diameterMm)
{
    if (diameterMm >= kRepairThresholdMenMm)
        return localized("Report",
                         "Repair is usually considered from a maximum diameter of 5.5 cm in men and 5.0 cm in "
                         "women; this one is at or above both repair thresholds.");
    if (diameterMm >= kRepairThresholdWomenMm)
        return localized("Report",
                         "Repair is usually considered from a maximum diameter of 5.5 cm in men and 5.0 cm in "
                         "women; this one is at or above the threshold for women (5.0 cm), below the one for "
                         "men (5.5 cm).");
    return localized("Report", "Repair is usually considered from a maximum diameter of 5.5 cm in men and 5.0 cm in "
                               "women; this one is below both repair thresholds.");
}

/// The sac's figures (the newest `vascusim-cli sac` label; its provenance holds them) by their definitions, the
/// repair thresholds against the SVS outer diameter. False when the study has no sac.
bool addSacGeometry(report::Section& section, const study::Study& study)
{
    std::string sacId;
    const std::map<std::string, double> figures = newestSacFigures(study, &sacId);
    const auto number = [&](const std::string& key) -> std::optional<double> {
        const auto found = figures.find(key);
        return found == figures.end() ? std::nullopt : std::optional<double>(found->second);
    };
    const std::optional<double> outer = number("max_outer_diameter_mm");
    if (!outer)
        return false;
    struct Row
    {
        const char* key;
        std::string label;
        const char* unit;
        int decimals;
    };
    const Row rows[] = {
        {"max_outer_diameter_mm", localized("Report", "Maximum diameter, outer wall to outer wall (SVS)"), "mm", 0},
        {"lumen_diameter_at_max_mm", localized("Report", "Lumen diameter there (equivalent)"), "mm", -1},
        {"max_thrombus_thickness_mm", localized("Report", "Largest thrombus thickness"), "mm", -1},
        {"sac_volume_ml", localized("Report", "Sac volume"), "ml", -1},
        {"sac_length_mm", localized("Report", "Sac length"), "mm", -1},
        {"neck_diameter_mm", localized("Report", "Neck diameter (outer, at the lowest renal artery)"), "mm", -1},
        {"neck_length_mm", localized("Report", "Neck length"), "mm", -1},
        {"neck_angulation_deg", localized("Report", "Neck angulation"), "deg", -1},
        {"right_common_iliac_diameter_mm", localized("Report", "Right common iliac diameter (outer)"), "mm", -1},
        {"left_common_iliac_diameter_mm", localized("Report", "Left common iliac diameter (outer)"), "mm", -1},
        {"wall_thickness_mm", localized("Report", "Wall thickness (assumed, not measured)"), "mm", -1}};
    report::MetricTable geometry{
        withArguments(localized("Report", "The aneurysm sac (%1)"), {storedTextForPeople(study.artifact(sacId).name)}), {}};
    std::string definitions = localized("Report", "Definitions.");
    for (const Row& row : rows)
        if (const std::optional<double> value = number(row.key))
        {
            geometry.rows.push_back(report::metric(row.key, row.label, *value, row.unit, row.decimals));
            const auto known = imaging::aneurysmSacDefinitions(true);
            if (const auto definition = known.find(row.key); definition != known.end())
                definitions += " " + withArguments(localized("Report", "%1: %2."), {row.label, definition->second});
        }
    section.blocks.push_back(geometry);
    section.blocks.push_back(report::Paragraph{thresholdSentence(*outer)});
    section.blocks.push_back(report::Paragraph{definitions});
    return true;
}

} // namespace

std::optional<report::Section> aaaSection(const study::Study& study, const ReportOptions& options,
                                          VesselSections& sections, std::vector<const study::Artifact*>& runs,
                                          const Progress& progress)
{
    const study::Artifact* physiological = newestRun(study, "simulate fem", "protocol", "physiological");
    const study::Artifact* rupture = newestRun(study, "simulate fem", "protocol", "thesis-rupture");
    if (!physiological && !rupture && newestSacFigures(study).empty())
        return std::nullopt;
    report::Section section{"aaa", localized("Report", "AAA rupture-risk review"), {}};

    // Geometry: the sac (SVS outer diameter) and the cross-sections of the centerlines the wall run used.
    const imaging::VesselMeasurements* measured =
        sections.of(physiological || rupture ? centerlinesOf(study, physiological ? *physiological : *rupture)
                                             : study.newestArtifact(study::ArtifactKind::Skeleton, "centerline"),
                    progress.subRange(0.0, 0.6));
    const bool outerMeasured = addSacGeometry(section, study);
    report::MetricTable geometry{
        localized("Report", "The contrast lumen (cross-sections perpendicular to the centerline)"), {}};
    if (measured)
    {
        geometry.rows.push_back(report::metric("measured_max_diameter_mm",
                                               localized("Report", "Maximum lumen diameter (equivalent)"),
                                               measured->maxDiameterMm, "mm", 0));
        geometry.rows.push_back(report::metric("measured_max_caliper_mm",
                                               localized("Report", "Largest lumen caliper width"),
                                               measured->maxCaliperMm, "mm"));
        section.blocks.push_back(geometry);
        if (!outerMeasured)
            section.blocks.push_back(report::Paragraph{withArguments(
                localized("Report",
                          "These are lumen diameters; guidelines measure the aneurysm outer wall to outer wall "
                          "with the thrombus (vascusim-cli sac). Against the lumen: %1"),
                {thresholdSentence(measured->maxDiameterMm)})});
        section.blocks.push_back(aneurysmPlot(*measured));
    }
    else if (!outerMeasured)
        section.blocks.push_back(report::Paragraph{
            localized("Report", "No centerlines and no sac: the maximum diameter was not measured.")});

    if (physiological)
    {
        report::MetricTable stress{localized("Report", "Wall stress at blood pressure (physiological protocol)"), {}};
        // Inside the sac: the figures a reader takes as the aneurysm's (issue 16); outside it, stress only.
        const bool sacFigures = runMetric(*physiological, "sac_pws_p99_kpa", "", "", 1.0).has_value();
        addMetrics(
            stress, *physiological,
            {{"pressure_kpa", localized("Report", "Target blood pressure on the lumen"), "kPa"},
             {"run_reached_pressure_kPa",
              localized("Report", "Pressure reached (the figures below are at this pressure)"), "kPa"},
             {"sac_pws_p99_kpa",
              localized("Report", "Peak wall stress in the sac (von Mises, 99th percentile of its elements)"), "kPa"},
             {"sac_pws_nodal_max_kpa",
              localized("Report", "Peak wall stress in the sac (von Mises, largest nodal value)"), "kPa"},
             {"sac_pws_along_centerline_mm",
              localized("Report", "  its place: along the centerline below the lowest renal artery"), "mm"},
             {"sac_pws_clock_h",
              localized("Report", "  its clock position (seen from the feet; 12 anterior, 3 patient's left)"), "h"},
             {"sac_pwri_p99",
              localized("Report", "Peak wall rupture index in the sac (stress / strength, 99th percentile)"), ""},
             {"sac_pwri_nodal_max", localized("Report", "Peak wall rupture index in the sac (largest nodal value)"),
              ""},
             {"sac_pwri_along_centerline_mm",
              localized("Report", "  its place: along the centerline below the lowest renal artery"), "mm"},
             {"sac_pwri_clock_h", localized("Report", "  its clock position"), "h"},
             {"peak_von_mises_kpa",
              sacFigures ? localized("Report", "Highest element stress on the whole wall (von Mises; a branch "
                                               "ostium or the iliac crotch may set it)")
                         : localized("Report", "Highest element stress on the whole wall (von Mises)"),
              "kPa"},
             {"peak_von_mises_x_mm", localized("Report", "  at x (patient LPS)"), "mm"},
             {"peak_von_mises_y_mm", localized("Report", "  at y"), "mm"},
             {"peak_von_mises_z_mm", localized("Report", "  at z"), "mm"},
             {"peak_max_principal_kpa", localized("Report", "Highest largest principal stress on the whole wall"),
              "kPa"},
             {"max_displacement_mm", localized("Report", "Largest wall displacement"), "mm"}});
        const auto note = markRunStatus(stress, *physiological);
        section.blocks.push_back(stress);
        if (note)
            section.blocks.push_back(*note);
        auto value = [&](const char* key) { return textOr(physiological->provenance.parameters, key, "?"); };
        auto given = [&](const char* key, const std::string& yes, const std::string& no)
        {
            const std::string v = value(key);
            return v == "1" ? yes : v == "0" ? no : localized("Report", "not given");
        };
        const bool indexComputed = runMetric(*physiological, "peak_rupture_index", "", "", 1.0).has_value();
        const auto fromSac = runMetric(*physiological, "strength_from_sac_elements", "", "", 1.0);
        const auto referenceUsed = runMetric(*physiological, "reference_diameter_used_mm", "", "", 1.0);
        const bool neckReference = value("reference_diameter_mm") == "0";
        const std::string referenceText =
            referenceUsed
                ? referenceUsed->text + " mm" +
                      (neckReference ? localized("Report", " (the sac's neck outer diameter, or 20 mm without a sac)")
                                     : std::string())
            : neckReference ? localized("Report", "the sac's neck outer diameter (20 mm without a sac)")
                            : value("reference_diameter_mm") + " mm";
        const std::string geometry =
            fromSac && fromSac->value > 0.0
                ? withArguments(localized("Report",
                                          "inside the sac the thrombus crossed along each element's radius from "
                                          "the centerline and the outer wall-to-wall chord through the "
                                          "centerline there (the sac's labels), elsewhere the centerline "
                                          "diameter and a thrombus of %1 mm"),
                                {value("thrombus_mm")})
                : withArguments(localized("Report", "thrombus %1 mm (assumed), the centerline diameter"),
                                {value("thrombus_mm")});
        const std::string indexSentence =
            !indexComputed ? localized("Report", "Sex and family history were not both given, so no rupture index is "
                                                 "reported (neither is assumed).")
            : sacFigures
                ? localized("Report", "A rupture index of 1 means the stress reaches the estimated strength; it "
                                      "is given inside the aneurysm sac only (the regression was fitted to sacs).")
                : localized("Report", "No sac was measured (vascusim-cli sac), so no rupture index is given: the "
                                      "regression holds for the aneurysm sac only.");
        section.blocks.push_back(report::Paragraph{withArguments(
            localized("Report",
                      "Strength model: Vande Geest et al. 2006 (wall strength from the local thrombus thickness, "
                      "the local diameter over the non-aneurysmal reference, family history and sex), with %1; "
                      "reference diameter %2, sex %3, family history of AAA %4. %5"),
            {geometry, referenceText, given("female", localized("Report", "female"), localized("Report", "male")),
             given("family_history", localized("Report", "yes"), localized("Report", "no")), indexSentence})});
        const std::string caption =
            localized("Report", "Wall stress (von Mises, kPa; the elements' values averaged to the surface points) at "
                                "blood pressure, seen from the front; PWS and PWRI mark the sac's nodal maxima (clock "
                                "position seen from the feet, 12 h anterior)");
        section.blocks.push_back(snapshotOrNote(caption, options, [&] {
            const TriangleMesh surface = frameSurface(study.loadTetMesh(physiological->id), "von_mises_kpa");
            const auto& values = surface.pointFields.at("von_mises_kpa");
            // The colour scale covers the figures printed above (the surface average runs below the element peaks).
            double high = values.empty() ? 1.0 : *std::max_element(values.begin(), values.end());
            for (const char* key : {"sac_pws_p99_kpa", "sac_pws_nodal_max_kpa"})
                if (const auto figure = runMetric(*physiological, key, "", "", 1.0))
                    high = std::max(high, figure->value);
            return viz::snapshotSurface(surface, "von_mises_kpa", {localized("Report", "von Mises [kPa]"), 0.0, high},
                                        QSize(options.snapshotPixels, options.snapshotPixels * 3 / 4),
                                        sacPeakCallouts(*physiological));
        }));
        runs.push_back(physiological);
    }
    else
        section.blocks.push_back(
            report::Paragraph{localized("Report", "The physiological wall-stress run was not made for this study.")});

    if (rupture)
    {
        report::MetricTable tearing{
            localized("Report", "Tearing (thesis protocol: pressure ramp on the middle of the vessel)"), {}};
        addMetrics(tearing, *rupture,
                   {{"tear_onset_pressure_mpa", localized("Report", "Pressure at the first tear (-1: none)"), "MPa"},
                    {"torn_elements", localized("Report", "Torn elements"), ""},
                    {"fracture_entropy", localized("Report", "Fracture entropy"), "nats"},
                    {"final_pressure_kpa", localized("Report", "Pressure at the end of the run"), "kPa"}});
        const auto note = markRunStatus(tearing, *rupture);
        section.blocks.push_back(tearing);
        if (note)
            section.blocks.push_back(*note);
        const bool quasiStatic = textOr(rupture->provenance.parameters, "quasi_static", "0") == "1";
        section.blocks.push_back(report::Paragraph{
            localized("Report", "Research protocol: the thesis's ramp pressures (by default 8-12 MPa, about 600 times "
                                "systolic) are not physiological, and its tear strength is no measured wall strength; "
                                "these figures reproduce the thesis's experiment and say nothing about this patient's "
                                "rupture risk.") +
            " " +
            (quasiStatic
                 ? localized("Report", "Tearing was quasi-static: the wall in equilibrium at each pressure, the "
                                       "onset bracketed by bisection to 0.5 %, one element released per "
                                       "equilibrium.")
                 : localized("Report", "Tearing followed the thesis's damped ramp: the wall lags the load, so the "
                                       "onset pressure depends on the ramp's rate."))});
        runs.push_back(rupture);
    }
    else
        section.blocks.push_back(
            report::Paragraph{localized("Report", "The thesis tearing protocol was not run for this study.")});
    progress.report(1.0, localized("vsim::Progress", "AAA section"));
    return section;
}

} // namespace vsim::app::detail
