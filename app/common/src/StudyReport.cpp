#include "vsim/app/StudyReport.h"

#include "ReportSections.h"
#include "ReportSupport.h"
#include "vsim/core/Error.h"
#include "vsim/core/Localized.h"
#include "vsim/core/StoredText.h"
#include "vsim/core/Version.h"

#include <algorithm>

namespace vsim::app {
namespace {

using study::Artifact;

std::string metadata(const study::Study& study, const std::string& key)
{
    return detail::textOr(study.metadata(), key);
}

/// An attribute of the study's newest image (the CT series), e.g. "series_description".
std::string imageAttribute(const study::Study& study, const std::string& key)
{
    const std::string image = study.newestArtifact(study::ArtifactKind::Image);
    if (image.empty())
        return {};
    return detail::textOr(study.artifact(image).attributes, key);
}

/// YYYYMMDD -> YYYY-MM-DD; other text unchanged.
std::string readableDate(const std::string& date)
{
    if (date.size() == 8 && std::all_of(date.begin(), date.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return date.substr(0, 4) + "-" + date.substr(4, 2) + "-" + date.substr(6, 2);
    return date;
}

report::ReportHeader header(const study::Study& study, bool anonymize)
{
    report::ReportHeader h;
    h.title = localized("Report", "VascuSim planning report");
    h.anonymized = anonymize;
    if (!anonymize)
    {
        h.patientName = metadata(study, "patient_name");
        std::replace(h.patientName.begin(), h.patientName.end(), '^', ' ');
        h.patientId = metadata(study, "patient_id");
        h.patientBirthDate = readableDate(metadata(study, "patient_birth_date"));
        h.institution = imageAttribute(study, "institution_name");
    }
    h.studyDate = readableDate(metadata(study, "study_date"));
    h.studyDescription = metadata(study, "study_description");
    h.seriesDescription = imageAttribute(study, "series_description");
    h.softwareVersion = std::string("VascuSim ") + kVersion;
    h.reportDate = study::utcTimestamp();
    return h;
}

} // namespace

std::vector<std::string> reportSectionIds()
{
    return {"aaa", "stenosis", "chemoembolization", "smoke", "measurements", "runs"};
}

report::Report buildStudyReport(const study::Study& study, const ReportOptions& options, const Progress& progress)
{
    const std::vector<std::string> known = reportSectionIds();
    for (const std::string& id : options.sections)
        if (std::find(known.begin(), known.end(), id) == known.end())
            throw Error(Pattern{"unknown report section '%1'; sections: aaa, stenosis, chemoembolization, smoke, "
                                "measurements, runs",
                                {id}});
    auto wanted = [&](const std::string& id) { return options.sections.empty() || options.sections.count(id) > 0; };

    report::Report report;
    report.header = header(study, options.anonymize);
    std::vector<const Artifact*> runs;
    detail::VesselSections sections(study);
    if (wanted("aaa"))
    {
        if (auto section = detail::aaaSection(study, options, sections, runs, progress.subRange(0.0, 0.4)))
            report.sections.push_back(std::move(*section));
        else
            report.notRun.push_back(localized("Report",
                                              "AAA rupture-risk review: the study has no AAA sac (vascusim-cli "
                                              "sac) and no wall-mechanics run (simulate fem)."));
    }
    if (wanted("stenosis"))
    {
        if (auto section = detail::stenosisSection(study, sections, options, progress.subRange(0.4, 0.6)))
            report.sections.push_back(std::move(*section));
        else
            report.notRun.push_back(localized("Report", "Stenosis / blockage: no segment of the centerlines narrows by "
                                                        "40 % or more, and the study has no blood-flow run (velocity "
                                                        "ratios, pressure drop)."));
    }
    if (wanted("chemoembolization"))
    {
        if (auto section = detail::drugSection(study, options, runs))
            report.sections.push_back(std::move(*section));
        else
            report.notRun.push_back(
                localized("Report", "Chemoembolization: the study has no drug-delivery run (simulate network)."));
    }
    if (wanted("smoke"))
    {
        if (auto section = detail::smokeSection(study, runs))
            report.sections.push_back(std::move(*section));
        else
            report.notRun.push_back(localized("Report", "Surgical smoke: the study has no smoke run (simulate smoke)."));
    }
    if (wanted("measurements"))
        if (auto section = detail::measurementsSection(study))
            report.sections.push_back(std::move(*section));
    for (const Artifact* run : runs)
        report.sources.push_back(run->id);
    if (wanted("runs") && !runs.empty())
        report.sections.push_back(detail::runsSection(runs, options, progress.subRange(0.6, 1.0)));
    progress.report(1.0, localized("vsim::Progress", "report"));
    return report;
}

std::string addReport(study::Study& study, const report::Report& report, const std::string& pdf,
                      const ReportOptions& options, const std::string& page)
{
    study::Provenance provenance;
    provenance.command = "report";
    provenance.inputs = report.sources;
    std::string sections;
    for (const report::Section& section : report.sections)
        sections += (sections.empty() ? "" : ",") + section.id;
    provenance.parameters = {{"sections", sections},
                             {"anonymized", options.anonymize ? "1" : "0"},
                             {"page", page},
                             {"language", options.language},
                             {"validation", options.validate ? "1" : "0"}};
    const std::string id = study.addReport(
        pdf, options.anonymize ? storedText("Report (anonymized)") : storedText("Report"), provenance);
    std::map<std::string, std::string> attributes;
    attributes["metrics"] = std::to_string(report.metrics().size());
    attributes["analyses_not_run"] = std::to_string(report.notRun.size());
    study.setArtifactAttributes(id, attributes);
    return id;
}

report::DocumentIdentity documentIdentity(const study::Study& study, bool anonymize)
{
    report::DocumentIdentity identity;
    identity.softwareVersion = kVersion;
    identity.identifiesPatient = !anonymize;
    if (anonymize)
    {
        // Its own new study (an empty UID makes one): the patient's study UID, dates and texts identify the patient.
        identity.patientName = "ANONYMIZED";
        identity.patientId = "ANONYMIZED";
        return identity;
    }
    identity.studyInstanceUid = metadata(study, "study_instance_uid");
    identity.studyDate = metadata(study, "study_date");
    identity.studyTime = imageAttribute(study, "study_time");
    identity.studyDescription = metadata(study, "study_description");
    identity.patientName = metadata(study, "patient_name");
    identity.patientId = metadata(study, "patient_id");
    identity.patientBirthDate = metadata(study, "patient_birth_date");
    identity.patientSex = metadata(study, "patient_sex");
    identity.accessionNumber = metadata(study, "accession_number");
    identity.studyId = imageAttribute(study, "study_id");
    identity.institution = imageAttribute(study, "institution_name");
    return identity;
}

} // namespace vsim::app
