// The report's surgical-smoke section (issue 21): the newest smoke run's endoscope obscuration (the times to 50 %
// and 90 %, the peak, with a suction the time to clear and the smoke removed in 10 s), its obscuration curve, what
// the scene models and what is synthetic.
#include "ReportSections.h"

#include "ReportSupport.h"

#include <nlohmann/json.hpp>

#include <cstdlib>

namespace vsim::app::detail {
namespace {

std::string sceneText(const std::string& scenario)
{
    if (scenario == "evh")
        return localized("Report", "Endoscopic vessel harvesting: a CO2 tunnel drawn around 60 mm of the study's longest "
                                   "centerline segment (a pre-operative CT shows no tunnel), the cautery's contact on the "
                                   "vessel's anterior wall, smoke from 9 s after contact (thesis ch. 7), the endoscope "
                                   "25 mm back in the tunnel.");
    if (scenario == "liver-ablation")
        return localized("Report", "Liver ablation under laparoscopy: an insufflated dome over the liver (the study's liver "
                                   "label, or a box phantom without one), the probe's smoke at the liver's surface, the "
                                   "insufflator a vent in the roof, a suction port beside the probe, the laparoscope "
                                   "looking down at the site.");
    return localized("Report", "The thesis demo: a 1 m box open at the top, smoke rising from the floor, a ball dropped "
                               "through it.");
}

} // namespace

std::optional<report::Section> smokeSection(const study::Study& study, std::vector<const study::Artifact*>& runs)
{
    const study::Artifact* run = newestRun(study, "simulate smoke", {}, {}, study::ArtifactKind::Run);
    if (!run)
        return std::nullopt;
    report::Section section{"smoke", localized("Report", "Surgical smoke (illustrative scene)"), {}};
    const std::string scenario = textOr(run->provenance.parameters, "scenario", "ball-drop");
    section.blocks.push_back(report::Paragraph{
        sceneText(scenario) + " " +
        localized("Report", "The scene is illustrative: its geometry is synthetic and the smoke's emission is an "
                            "assumption; the figures show how the smoke spreads and clears, not this patient's case.")});
    report::MetricTable view{localized("Report", "The endoscope's view"), {}};
    std::vector<std::string> notReached;
    const auto time = [&](const char* key, const std::string& label) {
        if (const auto m = runMetric(*run, key, label, "s"))
        {
            if (m->value >= 0.0)
                view.rows.push_back(*m);
            else
                notReached.push_back(label);
        }
    };
    time("time_to_50_percent_obscuration_s", localized("Report", "Time to 50 % of the view obscured"));
    time("time_to_90_percent_obscuration_s", localized("Report", "Time to 90 % of the view obscured"));
    addMetrics(view, *run,
               {{"peak_obscured_fraction", localized("Report", "Largest share of the view obscured"), "%", 100.0},
                {"obscured_fraction", localized("Report", "Share of the view obscured at the end"), "%", 100.0},
                {"smoke_mass_mg", localized("Report", "Smoke in the cavity at the end"), "mg"}});
    time("time_to_clear_s", localized("Report", "Time to clear after the suction starts (under 10 % obscured)"));
    addMetrics(view, *run,
               {{"smoke_removed_in_10s_percent", localized("Report", "Smoke removed in the suction's first 10 s"), "%"}});
    const auto note = markRunStatus(view, *run);
    section.blocks.push_back(view);
    if (note)
        section.blocks.push_back(*note);
    std::string definitions = withArguments(
        localized("Report", "A pixel of the endoscope's view is obscured when less than %1 % of the light from the scene "
                            "passes the smoke (Beer-Lambert, the mass extinction coefficient %2 m^2/g: Mulholland & "
                            "Croarkin 2000)."),
        {fixed(100.0 * std::atof(textOr(run->provenance.parameters, "visible_transmittance", "0.5").c_str()), 0),
         textOr(run->provenance.parameters, "mass_extinction_m2_g", "8.7")});
    for (const std::string& label : notReached)
        definitions += " " + withArguments(localized("Report", "Not reached within the run: %1."), {label});
    if (std::atof(textOr(run->provenance.parameters, "suction_l_min", "0").c_str()) > 0.0)
        definitions += " " + localized("Report", "The suction's flow is calibrated to a published measurement (proximal "
                                                 "evacuation removing about 85 % of the smoke in 10 s, Chou 2024): a "
                                                 "calibration, not a validation.");
    section.blocks.push_back(report::Paragraph{definitions});
    report::Plot plot;
    plot.caption = localized("Report", "The endoscope's view obscured by the smoke over time");
    plot.xLabel = localized("Report", "Time [s]");
    plot.yLabel = localized("Report", "View obscured [%]");
    report::PlotSeries series{localized("Report", "obscured"), {}};
    try
    {
        for (const auto& row : nlohmann::json::parse(textOr(run->attributes, "obscuration_curve", "[]")))
            series.points.emplace_back(row.at(0).get<double>(), 100.0 * row.at(1).get<double>());
    }
    catch (const nlohmann::json::exception&)
    {
        series.points.clear(); // a damaged attribute: no curve rather than a wrong one
    }
    if (!series.points.empty())
    {
        plot.series.push_back(series);
        plot.references = {{localized("Report", "50 %"), 50.0}, {localized("Report", "90 %"), 90.0}};
        section.blocks.push_back(plot);
    }
    runs.push_back(run);
    return section;
}

} // namespace vsim::app::detail
