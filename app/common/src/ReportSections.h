#pragma once

// The sections of the study report (StudyReport.cpp): each returns nothing when the study holds no run of its
// analysis, and adds the runs it reports to `runs` for the runs section.

#include "ReportSupport.h"
#include "vsim/app/StudyReport.h"
#include "vsim/report/ReportModel.h"
#include "vsim/study/Study.h"

#include <optional>
#include <vector>

namespace vsim::app::detail {

/// AAA rupture-risk review: maximum diameter against the repair thresholds, peak wall stress and rupture index
/// (physiological run), tearing onset (thesis protocol), a stress snapshot and the diameter along the centerline.
std::optional<report::Section> aaaSection(const study::Study& study, const ReportOptions& options,
                                          VesselSections& sections, std::vector<const study::Artifact*>& runs,
                                          const Progress& progress);

/// Stenosis from the cross-sections of the newest centerlines when a segment narrows by 40 % or more; with the
/// newest blood-flow run its figures (velocity ratios, pressure drop, wall loads), its velocity and pressure along
/// the centerline as plots, and its time-averaged wall shear stress on the lumen surface as a picture.
std::optional<report::Section> stenosisSection(const study::Study& study, VesselSections& sections,
                                               const ReportOptions& options, const Progress& progress);

/// Chemoembolization: the newest drug network run.
std::optional<report::Section> drugSection(const study::Study& study, const ReportOptions& options,
                                           std::vector<const study::Artifact*>& runs);

/// Surgical smoke: the newest smoke run's obscuration of the endoscope's view (times, curve), the scene labelled
/// illustrative.
std::optional<report::Section> smokeSection(const study::Study& study, std::vector<const study::Artifact*>& runs);

/// The measurements (rulers, angles, ROIs) marked "in report" on the workstation; nothing when none is marked.
std::optional<report::Section> measurementsSection(const study::Study& study);

/// For each reported run: solver, backend, steps, wall-clock time, its parameters, and the validation cases of its
/// solver run in this build (options.validate).
report::Section runsSection(const std::vector<const study::Artifact*>& runs, const ReportOptions& options,
                            const Progress& progress);

} // namespace vsim::app::detail
