#include "ReportSections.h"

#include "ReportSupport.h"
#include "ReportTacePictures.h"
#include "vsim/core/Units.h"
#include "vsim/sim/network/ConicalPipe.h"
#include "vsim/viz/Snapshot.h"

#include <algorithm>
#include <limits>

namespace vsim::app::detail {
namespace {

constexpr std::size_t kBranchRows = 60; // branches listed by drug flow; the rest counted in one line

/// The share (%) of the downstream tree's volume that the drug has filled over time: each segment fills linearly
/// in time between entering and leaving (plug flow at a steady rate through a cone).
report::Plot fillingPlot(const VesselNetwork& network)
{
    const auto& enter = network.segmentFields.at("fill_enter_s");
    const auto& leave = network.segmentFields.at("fill_leave_s");
    std::vector<double> volume(network.segments.size(), 0.0);
    double total = 0.0, end = 0.0;
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (enter[s] >= 0.0 && leave[s] >= enter[s])
        {
            const auto& segment = network.segments[s];
            const double length = units::mmToM(segment.lengthMm);
            volume[s] = sim::network::conicalVolume(units::mmToM(segment.startRadiusMm), units::mmToM(segment.endRadiusMm),
                                                    length, length);
            total += volume[s], end = std::max(end, leave[s]);
        }
    report::Plot plot;
    plot.caption = localized("Report", "Filling of the tree downstream of the tip");
    plot.xLabel = localized("Report", "Time from the start of the injection [s]");
    plot.yLabel = localized("Report", "Volume filled by the drug [%]");
    report::PlotSeries series{localized("Report", "filled"), {}};
    constexpr int kSamples = 200;
    for (int i = 0; i <= kSamples && total > 0.0; ++i)
    {
        const double t = end * i / kSamples;
        double filled = 0.0;
        for (std::size_t s = 0; s < volume.size(); ++s)
            if (volume[s] > 0.0)
                filled += volume[s] * (leave[s] > enter[s] ? std::clamp((t - enter[s]) / (leave[s] - enter[s]), 0.0, 1.0)
                                                           : (t >= leave[s] ? 1.0 : 0.0));
        series.points.emplace_back(t, 100.0 * filled / total);
    }
    plot.series.push_back(series);
    return plot;
}

/// Drug flow per branch, largest first; shares of `drugInjectedMlMin`.
report::Table branchTable(const VesselNetwork& network, double drugInjectedMlMin)
{
    report::Table table;
    table.caption = localized("Report", "Drug flow per branch (segments downstream of the tip, largest flow first)");
    table.columns = {localized("Report", "Segment"),
                     localized("Report", "Nodes"),
                     localized("Report", "Radius [mm]"),
                     localized("Report", "Length [mm]"),
                     localized("Report", "Drug flow [ml/min]"),
                     localized("Report", "Share [%]"),
                     localized("Report", "Filled after [s]")};
    const auto& drug = network.segmentFields.at("drug_flow_ml_min");
    const auto& downstream = network.segmentFields.at("downstream");
    const auto& leave = network.segmentFields.at("fill_leave_s");
    std::vector<std::size_t> order;
    for (std::size_t s = 0; s < network.segments.size(); ++s)
        if (downstream[s] > 0.0)
            order.push_back(s);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return drug[a] > drug[b]; });
    const double injected = std::max(1e-300, drugInjectedMlMin);
    for (std::size_t i = 0; i < order.size() && i < kBranchRows; ++i)
    {
        const std::size_t s = order[i];
        const auto& segment = network.segments[s];
        table.rows.push_back({std::to_string(s), std::to_string(segment.from) + " - " + std::to_string(segment.to),
                              fixed(segment.startRadiusMm, 2) + " - " + fixed(segment.endRadiusMm, 2),
                              fixed(segment.lengthMm, 1), report::formatMetric(drug[s]),
                              fixed(100.0 * drug[s] / injected, 1),
                              leave[s] >= 0.0 ? fixed(leave[s], 1) : localized("Report", "never")});
    }
    if (order.size() > kBranchRows)
        table.rows.push_back(
            {"...", withArguments(localized("Report", "%1 more"), {std::to_string(order.size() - kBranchRows)}), "", "",
             "", "", ""});
    return table;
}

} // namespace

std::optional<report::Section> drugSection(const study::Study& study, const ReportOptions& options,
                                           std::vector<const study::Artifact*>& runs)
{
    const study::Artifact* run = newestRun(study, "simulate network");
    if (!run)
        return std::nullopt;
    const VesselNetwork network = study.loadNetwork(run->id);
    report::Section section{
        "chemoembolization", localized("Report", "Chemoembolization: drug delivery through the hepatic arteries"), {}};
    const auto& source = run->provenance.parameters;
    const std::string tumour = textOr(source, "tumour_mm"), tumourLabel = textOr(source, "tumour_label");
    const std::string tumourText =
        !tumour.empty()        ? withArguments(localized("Report", "sphere x,y,z,radius %1 mm"), {tumour})
        : !tumourLabel.empty() ? withArguments(localized("Report", "label %1"), {tumourLabel})
                               : localized("Report", "none given");
    std::string setting = withArguments(
        localized("Report",
                  "Catheter tip: %1 (a node of the network, or a point x,y,z in mm, patient LPS). Tumour: %2. "
                  "Blood enters at: %3."),
        {textOr(source, "tip", localized("Report", "the root of the tree")), tumourText,
         textOr(source, "inlet", localized("Report", "the tree's largest end"))});
    if (const std::string added = textOr(source, "feeders_added"); !added.empty())
        setting += " " + withArguments(localized("Report", "Feeders added by hand: segments %1."), {added});
    if (const std::string removed = textOr(source, "feeders_removed"); !removed.empty())
        setting += " " + withArguments(localized("Report", "Feeders removed by hand: segments %1."), {removed});
    section.blocks.push_back(report::Paragraph{setting});
    report::MetricTable injection{localized("Report", "Injection and filling"), {}};
    addMetrics(injection, *run,
               {{"injection_rate_ml_min", localized("Report", "Injected mixture"), "ml/min"},
                {"injection_mass_rate_g_min", localized("Report", "Injected mass"), "g/min"},
                {"void_fraction", localized("Report", "Gas void fraction"), "%", 100.0},
                {"mixture_density_kg_m3", localized("Report", "Mixture density"), "kg/m3"},
                {"mixture_viscosity_mpa_s", localized("Report", "Mixture viscosity"), "mPa s"},
                {"tip_pressure_mmhg", localized("Report", "Pressure at the tip"), "mmHg"},
                {"first_arrival_s", localized("Report", "First outlet reached after"), "s"},
                {"last_arrival_s", localized("Report", "Last outlet reached after"), "s"},
                {"outlets", localized("Report", "Outlets downstream of the tip"), ""},
                {"max_reynolds", localized("Report", "Largest Reynolds number"), ""}});
    const auto note = markRunStatus(injection, *run);
    section.blocks.push_back(injection);
    if (note)
        section.blocks.push_back(*note);
    report::MetricTable blood{localized("Report", "Blood flow and the catheter (time-averaged, Newtonian blood)"), {}};
    addMetrics(
        blood, *run,
        {{"arterial_inflow_ml_min", localized("Report", "Arterial inflow at the tree's root"), "ml/min"},
         {"root_pressure_mmhg", localized("Report", "Mean pressure at the root"), "mmHg"},
         {"tip_own_flow_ml_min", localized("Report", "Vessel's own flow at the tip (catheter in, no injection)"),
          "ml/min"},
         {"tip_blood_inflow_ml_min", localized("Report", "Blood reaching the tip during the injection"), "ml/min"},
         {"tip_injected_percent", localized("Report", "Injected mixture in the flow below the tip (volume)"), "%"},
         {"tip_drug_percent", localized("Report", "Drug (liquid phase) in the flow below the tip (volume)"), "%"},
         {"catheter_occlusion_percent", localized("Report", "Catheter's share of the lumen at the tip (area)"), "%"},
         {"wedged", localized("Report", "Wedged catheter (1: yes)"), ""},
         {"reflux_percent", localized("Report", "Drug refluxing past the tip"), "%"},
         {"coupling_iterations", localized("Report", "Fixed-point iterations (fractions and viscosities)"), ""}});
    if (!blood.rows.empty())
        section.blocks.push_back(blood);
    report::MetricTable coverage{localized("Report",
                                           "Perfusion territory and tumour coverage (TACE grading: A lesion and "
                                           "margin, B lesion only, C lesion partly; margin 5 mm under 25 mm, "
                                           "else 10 mm)"),
                                 {}};
    addMetrics(
        coverage, *run,
        {{"liver_volume_ml", localized("Report", "Liver (label)"), "ml"},
         {"perfused_volume_ml", localized("Report", "Perfused territory from the tip"), "ml"},
         {"perfused_tumour_ml", localized("Report", "Tumour in the territory"), "ml"},
         {"perfused_non_target_ml", localized("Report", "Non-tumour liver in the territory"), "ml"},
         {"coverage_grade", localized("Report", "Coverage grade (1 A, 2 B, 3 C)"), ""},
         {"lesion_1_diameter_mm", localized("Report", "Lesion 1: longest diameter"), "mm"},
         {"lesion_1_margin_mm", localized("Report", "Lesion 1: margin"), "mm"},
         {"lesion_1_covered_percent", localized("Report", "Lesion 1: covered"), "%"},
         {"lesion_1_margin_covered_percent", localized("Report", "Lesion 1: margin covered"), "%"},
         {"feeders",
          localized("Report", "Feeders (found: entering lesion + margin, or feeding 1 % of it; with the user's edits)"),
          ""},
         {"feeders_added_by_hand", localized("Report", "Feeders added by hand"), ""},
         {"feeders_removed_by_hand", localized("Report", "Feeders found and removed by hand"), ""},
         {"feeders_reached", localized("Report", "Feeders the drug from the tip reaches"), ""},
         {"drug_liver_percent", localized("Report", "Drug to non-tumour liver"), "%"},
         {"drug_extrahepatic_percent", localized("Report", "Drug leaving the liver (extrahepatic outlets)"), "%"},
         {"best_tip_grade", localized("Report", "Best tip position's grade (1 A, 2 B, 3 C)"), ""},
         {"best_tip_non_target_ml", localized("Report", "Best tip position's non-tumour liver"), "ml"}});
    if (!coverage.rows.empty())
    {
        section.blocks.push_back(coverage);
        section.blocks.push_back(territoryPicture(study, *run, options.snapshotPixels));
    }
    report::MetricTable angle{localized("Report",
                                        "Working C-arm angle for the path to the tip (patient supine; + LAO / "
                                        "- RAO, + cranial / - caudal; within LAO/RAO 60 and cranial/caudal 40 "
                                        "degrees)"),
                              {}};
    addMetrics(
        angle, *run,
        {{"working_path_start_node",
          localized("Report", "Path from node (the common hepatic artery's upper end when named, else the root)"), ""},
         {"working_lao_deg", localized("Report", "LAO (+) / RAO (-)"), "deg"},
         {"working_cranial_deg", localized("Report", "Cranial (+) / caudal (-)"), "deg"},
         {"working_foreshortening_percent", localized("Report", "Path foreshortened at the working angle"), "%"},
         {"working_overlap_percent", localized("Report", "Path overlapped by other vessels at the working angle"), "%"},
         {"frontal_foreshortening_percent", localized("Report", "Path foreshortened from the front (AP)"), "%"},
         {"frontal_overlap_percent", localized("Report", "Path overlapped from the front (AP)"), "%"}});
    if (!angle.rows.empty())
    {
        section.blocks.push_back(angle);
        section.blocks.push_back(workingViewPicture(network, *run, options.snapshotPixels / 2));
    }
    report::MetricTable targeting{localized("Report", "Targeting"), {}};
    addMetrics(targeting, *run,
               {{"tumour_fraction", localized("Report", "Drug reaching the tumour"), "%", 100.0},
                {"non_target_fraction", localized("Report", "Drug reaching non-target liver"), "%", 100.0},
                {"tumour_outlets", localized("Report", "Outlets feeding the tumour"), ""},
                {"best_tip_fraction", localized("Report", "Tumour share at the best tip position"), "%", 100.0}});
    section.blocks.push_back(targeting);

    report::Table ranking;
    const bool byCoverage = !textOr(run->attributes, "tip_rank_1_grade").empty();
    ranking.caption = byCoverage
                          ? localized("Report", "Candidate catheter tip positions, ranked by coverage grade, then "
                                                "the lesions' share perfused, then the least non-tumour liver perfused")
                          : localized("Report", "Candidate catheter tip positions, ranked by the drug share "
                                                "reaching the tumour");
    ranking.columns = {localized("Report", "Rank"), localized("Report", "Node"),
                       localized("Report", "Position x, y, z [mm]"), localized("Report", "Tumour share [%]"),
                       localized("Report", "Depth [segments]")};
    if (byCoverage)
        ranking.columns.insert(ranking.columns.end(),
                               {localized("Report", "Grade"), localized("Report", "Lesions perfused [%]"),
                                localized("Report", "Non-tumour liver [ml]")});
    for (int k = 1;; ++k)
    {
        const std::string prefix = "tip_rank_" + std::to_string(k) + "_";
        auto at = [&](const std::string& key) { return textOr(run->attributes, prefix + key); };
        if (at("node").empty())
            break;
        std::vector<std::string> row{std::to_string(k), at("node"),
                                     fixed(std::stod(at("x_mm")), 1) + ", " + fixed(std::stod(at("y_mm")), 1) + ", " +
                                         fixed(std::stod(at("z_mm")), 1),
                                     fixed(100.0 * std::stod(at("tumour_fraction")), 1), at("depth")};
        if (byCoverage)
            row.insert(row.end(), {at("grade"), fixed(std::stod(at("covered_percent")), 1), fixed(std::stod(at("non_target_ml")), 1)});
        ranking.rows.push_back(row);
    }
    if (!ranking.rows.empty())
        section.blocks.push_back(ranking);

    report::MetricTable controls{localized("Report", "Two-phase drug against a pure liquid at the control points"), {}};
    addMetrics(controls, *run,
               {{"control_A_drug_flow_two_phase_ml_min", localized("Report", "A: drug flow, two-phase"), "ml/min"},
                {"control_A_drug_flow_liquid_ml_min", localized("Report", "A: drug flow, pure liquid"), "ml/min"},
                {"control_A_drop_percent", localized("Report", "A: two-phase lower by (same injected rate)"), "%"},
                {"control_A_drop_same_pressure_percent",
                 localized("Report", "A: two-phase lower by (same tip pressure)"), "%"},
                {"control_A_split_shift_percent",
                 localized("Report", "A: whole flow, two-phase against liquid (split shift)"), "%"},
                {"control_B_drug_flow_two_phase_ml_min", localized("Report", "B: drug flow, two-phase"), "ml/min"},
                {"control_B_drug_flow_liquid_ml_min", localized("Report", "B: drug flow, pure liquid"), "ml/min"},
                {"control_B_drop_percent", localized("Report", "B: two-phase lower by (same injected rate)"), "%"},
                {"control_B_drop_same_pressure_percent",
                 localized("Report", "B: two-phase lower by (same tip pressure)"), "%"},
                {"control_B_split_shift_percent",
                 localized("Report", "B: whole flow, two-phase against liquid (split shift)"), "%"}});
    section.blocks.push_back(controls);
    section.blocks.push_back(report::Paragraph{localized(
        "Report",
        "The drug flow is the liquid phase's volume flow, (1 - v) c Q, with v the void fraction and c the "
        "injected mixture's share of the flow (1 when the drug flows alone); the pure liquid is the same "
        "injection with v = 0 (thesis ch. 6.4). Its drop is close to v by that definition. The split shift is "
        "the change of the whole flow: what the mixture's other viscosity does to the split.")});

    const auto injected = runMetric(*run, "injection_rate_ml_min", "", "");
    const auto voidFraction = runMetric(*run, "void_fraction", "", "");
    section.blocks.push_back(
        branchTable(network, injected ? injected->value * (1.0 - (voidFraction ? voidFraction->value : 0.0)) : 0.0));
    section.blocks.push_back(fillingPlot(network));
    const std::string caption =
        localized("Report", "The tree coloured by drug flow (ml/min; grey: no drug), seen from the front");
    section.blocks.push_back(snapshotOrNote(
        caption, options,
        [&]
        {
            std::vector<std::vector<Eigen::Vector3d>> lines;
            std::vector<double> values;
            std::vector<std::array<double, 2>> radii;
            const auto& drug = network.segmentFields.at("drug_flow_ml_min");
            for (std::size_t s = 0; s < network.segments.size(); ++s)
            {
                const auto& segment = network.segments[s];
                lines.push_back(network.segmentPath(s));
                values.push_back(drug[s] > 0.0 ? drug[s] : std::numeric_limits<double>::quiet_NaN()); // grey: no drug
                radii.push_back({segment.startRadiusMm, segment.endRadiusMm});
            }
            const double high = drug.empty() ? 1.0 : std::max(1e-12, *std::max_element(drug.begin(), drug.end()));
            return viz::snapshotTubes(lines, values, radii, {localized("Report", "drug flow [ml/min]"), 0.0, high},
                                      QSize(options.snapshotPixels, options.snapshotPixels * 3 / 4));
        }));
    runs.push_back(run);
    return section;
}

} // namespace vsim::app::detail
