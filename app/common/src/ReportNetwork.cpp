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
    plot.caption = "Filling of the tree downstream of the tip";
    plot.xLabel = "Time from the start of the injection [s]";
    plot.yLabel = "Volume filled by the drug [%]";
    report::PlotSeries series{"filled", {}};
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
    table.caption = "Drug flow per branch (segments downstream of the tip, largest flow first)";
    table.columns = {"Segment", "Nodes", "Radius [mm]", "Length [mm]", "Drug flow [ml/min]", "Share [%]", "Filled after [s]"};
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
                              leave[s] >= 0.0 ? fixed(leave[s], 1) : std::string("never")});
    }
    if (order.size() > kBranchRows)
        table.rows.push_back({"...", std::to_string(order.size() - kBranchRows) + " more", "", "", "", "", ""});
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
    report::Section section{"chemoembolization", "Chemoembolization: drug delivery through the hepatic arteries", {}};
    const auto& source = run->provenance.parameters;
    const std::string tumour = textOr(source, "tumour_mm"), tumourLabel = textOr(source, "tumour_label");
    section.blocks.push_back(report::Paragraph{
        "Catheter tip: " + textOr(source, "tip", "the root of the tree") +
        " (a node of the network, or a point x,y,z in mm, patient LPS). Tumour: " +
        (!tumour.empty() ? "sphere x,y,z,radius " + tumour + " mm"
                         : !tumourLabel.empty() ? "label " + tumourLabel : std::string("none given")) +
        ". Blood enters at: " + textOr(source, "inlet", "the tree's largest end") +
        (textOr(source, "feeders_added").empty() ? std::string() : ". Feeders added by hand: segments " + textOr(source, "feeders_added")) +
        (textOr(source, "feeders_removed").empty() ? std::string() : ". Feeders removed by hand: segments " + textOr(source, "feeders_removed")) +
        "."});
    report::MetricTable injection{"Injection and filling", {}};
    addMetrics(injection, *run,
               {{"injection_rate_ml_min", "Injected mixture", "ml/min"},
                {"injection_mass_rate_g_min", "Injected mass", "g/min"},
                {"void_fraction", "Gas void fraction", "%", 100.0},
                {"mixture_density_kg_m3", "Mixture density", "kg/m3"},
                {"mixture_viscosity_mpa_s", "Mixture viscosity", "mPa s"},
                {"tip_pressure_mmhg", "Pressure at the tip", "mmHg"},
                {"first_arrival_s", "First outlet reached after", "s"},
                {"last_arrival_s", "Last outlet reached after", "s"},
                {"outlets", "Outlets downstream of the tip", ""},
                {"max_reynolds", "Largest Reynolds number", ""}});
    const auto note = markRunStatus(injection, *run);
    section.blocks.push_back(injection);
    if (note)
        section.blocks.push_back(*note);
    report::MetricTable blood{"Blood flow and the catheter (time-averaged, Newtonian blood)", {}};
    addMetrics(blood, *run,
               {{"arterial_inflow_ml_min", "Arterial inflow at the tree's root", "ml/min"},
                {"root_pressure_mmhg", "Mean pressure at the root", "mmHg"},
                {"tip_own_flow_ml_min", "Vessel's own flow at the tip (catheter in, no injection)", "ml/min"},
                {"tip_blood_inflow_ml_min", "Blood reaching the tip during the injection", "ml/min"},
                {"tip_injected_percent", "Injected mixture in the flow below the tip (volume)", "%"},
                {"tip_drug_percent", "Drug (liquid phase) in the flow below the tip (volume)", "%"},
                {"catheter_occlusion_percent", "Catheter's share of the lumen at the tip (area)", "%"},
                {"wedged", "Wedged catheter (1: yes)", ""},
                {"reflux_percent", "Drug refluxing past the tip", "%"},
                {"coupling_iterations", "Fixed-point iterations (fractions and viscosities)", ""}});
    if (!blood.rows.empty())
        section.blocks.push_back(blood);
    report::MetricTable coverage{"Perfusion territory and tumour coverage (TACE grading: A lesion and margin, B lesion "
                                 "only, C lesion partly; margin 5 mm under 25 mm, else 10 mm)", {}};
    addMetrics(coverage, *run,
               {{"liver_volume_ml", "Liver (label)", "ml"},
                {"perfused_volume_ml", "Perfused territory from the tip", "ml"},
                {"perfused_tumour_ml", "Tumour in the territory", "ml"},
                {"perfused_non_target_ml", "Non-tumour liver in the territory", "ml"},
                {"coverage_grade", "Coverage grade (1 A, 2 B, 3 C)", ""},
                {"lesion_1_diameter_mm", "Lesion 1: longest diameter", "mm"},
                {"lesion_1_margin_mm", "Lesion 1: margin", "mm"},
                {"lesion_1_covered_percent", "Lesion 1: covered", "%"},
                {"lesion_1_margin_covered_percent", "Lesion 1: margin covered", "%"},
                {"feeders", "Feeders (found: entering lesion + margin, or feeding 1 % of it; with the user's edits)", ""},
                {"feeders_added_by_hand", "Feeders added by hand", ""},
                {"feeders_removed_by_hand", "Feeders found and removed by hand", ""},
                {"feeders_reached", "Feeders the drug from the tip reaches", ""},
                {"drug_liver_percent", "Drug to non-tumour liver", "%"},
                {"drug_extrahepatic_percent", "Drug leaving the liver (extrahepatic outlets)", "%"},
                {"best_tip_grade", "Best tip position's grade (1 A, 2 B, 3 C)", ""},
                {"best_tip_non_target_ml", "Best tip position's non-tumour liver", "ml"}});
    if (!coverage.rows.empty())
    {
        section.blocks.push_back(coverage);
        section.blocks.push_back(territoryPicture(study, *run, options.snapshotPixels));
    }
    report::MetricTable angle{"Working C-arm angle for the path to the tip (patient supine; + LAO / - RAO, + cranial / "
                              "- caudal; within LAO/RAO 60 and cranial/caudal 40 degrees)", {}};
    addMetrics(angle, *run,
               {{"working_path_start_node", "Path from node (the common hepatic artery's upper end when named, else the root)", ""},
                {"working_lao_deg", "LAO (+) / RAO (-)", "deg"},
                {"working_cranial_deg", "Cranial (+) / caudal (-)", "deg"},
                {"working_foreshortening_percent", "Path foreshortened at the working angle", "%"},
                {"working_overlap_percent", "Path overlapped by other vessels at the working angle", "%"},
                {"frontal_foreshortening_percent", "Path foreshortened from the front (AP)", "%"},
                {"frontal_overlap_percent", "Path overlapped from the front (AP)", "%"}});
    if (!angle.rows.empty())
    {
        section.blocks.push_back(angle);
        section.blocks.push_back(workingViewPicture(network, *run, options.snapshotPixels / 2));
    }
    report::MetricTable targeting{"Targeting", {}};
    addMetrics(targeting, *run,
               {{"tumour_fraction", "Drug reaching the tumour", "%", 100.0},
                {"non_target_fraction", "Drug reaching non-target liver", "%", 100.0},
                {"tumour_outlets", "Outlets feeding the tumour", ""},
                {"best_tip_fraction", "Tumour share at the best tip position", "%", 100.0}});
    section.blocks.push_back(targeting);

    report::Table ranking;
    const bool byCoverage = !textOr(run->attributes, "tip_rank_1_grade").empty();
    ranking.caption = byCoverage ? "Candidate catheter tip positions, ranked by coverage grade, then the lesions' share "
                                   "perfused, then the least non-tumour liver perfused"
                                 : "Candidate catheter tip positions, ranked by the drug share reaching the tumour";
    ranking.columns = {"Rank", "Node", "Position x, y, z [mm]", "Tumour share [%]", "Depth [segments]"};
    if (byCoverage)
        ranking.columns.insert(ranking.columns.end(), {"Grade", "Lesions perfused [%]", "Non-tumour liver [ml]"});
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

    report::MetricTable controls{"Two-phase drug against a pure liquid at the control points", {}};
    addMetrics(controls, *run,
               {{"control_A_drug_flow_two_phase_ml_min", "A: drug flow, two-phase", "ml/min"},
                {"control_A_drug_flow_liquid_ml_min", "A: drug flow, pure liquid", "ml/min"},
                {"control_A_drop_percent", "A: two-phase lower by (same injected rate)", "%"},
                {"control_A_drop_same_pressure_percent", "A: two-phase lower by (same tip pressure)", "%"},
                {"control_A_split_shift_percent", "A: whole flow, two-phase against liquid (split shift)", "%"},
                {"control_B_drug_flow_two_phase_ml_min", "B: drug flow, two-phase", "ml/min"},
                {"control_B_drug_flow_liquid_ml_min", "B: drug flow, pure liquid", "ml/min"},
                {"control_B_drop_percent", "B: two-phase lower by (same injected rate)", "%"},
                {"control_B_drop_same_pressure_percent", "B: two-phase lower by (same tip pressure)", "%"},
                {"control_B_split_shift_percent", "B: whole flow, two-phase against liquid (split shift)", "%"}});
    section.blocks.push_back(controls);
    section.blocks.push_back(report::Paragraph{
        "The drug flow is the liquid phase's volume flow, (1 - v) c Q, with v the void fraction and c the injected "
        "mixture's share of the flow (1 when the drug flows alone); the pure liquid is the same injection with v = 0 "
        "(thesis ch. 6.4). Its drop is close to v by that definition. The split shift is the change of the whole "
        "flow: what the mixture's other viscosity does to the split."});

    const auto injected = runMetric(*run, "injection_rate_ml_min", "", "");
    const auto voidFraction = runMetric(*run, "void_fraction", "", "");
    section.blocks.push_back(
        branchTable(network, injected ? injected->value * (1.0 - (voidFraction ? voidFraction->value : 0.0)) : 0.0));
    section.blocks.push_back(fillingPlot(network));
    section.blocks.push_back(snapshotOrNote("The tree coloured by drug flow (ml/min; grey: no drug), seen from the front", options, [&] {
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
        return viz::snapshotTubes(lines, values, radii, {"drug flow [ml/min]", 0.0, high},
                                  QSize(options.snapshotPixels, options.snapshotPixels * 3 / 4));
    }));
    runs.push_back(run);
    return section;
}

} // namespace vsim::app::detail
