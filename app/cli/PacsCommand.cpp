#include "PacsCommand.h"

#include "vsim/core/OutputSafety.h"
#include "vsim/dicom/PacsClient.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace vsim::cli {
namespace {

/// A whole number from `low` to `high` given to `option`; UsageError naming `what` it must be otherwise.
int wholeNumber(const std::string& text, const std::string& option, long low, long high, const std::string& what)
{
    char* end = nullptr;
    const long number = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || number < low || number > high)
        throw UsageError(option + ": " + what + ", not '" + text + "'");
    return int(number);
}

int portNumber(const std::string& text, const std::string& option)
{
    return wholeNumber(text, option, 1, 65535, "a TCP port from 1 to 65535");
}

dicom::PacsNode nodeFrom(const Arguments& arguments)
{
    dicom::PacsNode node;
    node.calledAeTitle = arguments.option("aet");
    node.host = arguments.option("host");
    node.port = portNumber(arguments.option("port"), "--port");
    node.callingAeTitle = arguments.option("calling-aet", node.callingAeTitle);
    if (arguments.hasOption("timeout"))
        node.timeoutS = wholeNumber(arguments.option("timeout"), "--timeout", 1, 600, "whole seconds from 1 to 600");
    node.tls.enabled = arguments.hasOption("tls");
    node.tls.trustedCertificates = arguments.option("tls-trusted");
    node.tls.certificate = arguments.option("tls-cert");
    node.tls.privateKey = arguments.option("tls-key");
    const bool anyFile = !node.tls.trustedCertificates.empty() || !node.tls.certificate.empty() || !node.tls.privateKey.empty();
    if (anyFile && !node.tls.enabled)
        throw UsageError("--tls-trusted, --tls-cert and --tls-key go with --tls (DICOM TLS)");
    if (node.tls.enabled && node.tls.trustedCertificates.empty())
        throw UsageError("--tls needs --tls-trusted: the PACS's certificate or its authority's (PEM)");
    if (node.tls.certificate.empty() != node.tls.privateKey.empty())
        throw UsageError("--tls-cert and --tls-key go together (our certificate and its private key)");
    return node;
}

/// YYYYMMDD, or empty.
std::string checkedDate(const std::string& date)
{
    if (!date.empty() && (date.size() != 8 || date.find_first_not_of("0123456789") != std::string::npos))
        throw UsageError("--date: YYYYMMDD, YYYYMMDD-YYYYMMDD, YYYYMMDD- or -YYYYMMDD, not '" + date + "'");
    return date;
}

} // namespace

int pacsEchoCommand(const Arguments& arguments, const Progress&)
{
    const dicom::PacsNode node = nodeFrom(arguments);
    dicom::pacsEcho(node);
    std::cout << nlohmann::json{{"echo", "ok"}, {"pacs", dicom::describe(node)}, {"calling_aet", node.callingAeTitle}}.dump(2)
              << "\n";
    return 0;
}

namespace {

nlohmann::json findPatientsJson(const dicom::PacsNode& node, const Arguments& arguments, const Progress& progress)
{
    nlohmann::json patients = nlohmann::json::array();
    for (const dicom::PatientMatch& match :
         dicom::findPatients(node, {arguments.option("patient-name"), arguments.option("patient-id")}, progress))
        patients.push_back({{"patient_name", match.patientName},
                            {"patient_id", match.patientId},
                            {"birth_date", match.birthDate},
                            {"sex", match.sex},
                            {"studies", match.studyCount}});
    return {{"pacs", dicom::describe(node)}, {"level", "PATIENT"}, {"patients", patients}};
}

nlohmann::json findSeriesJson(const dicom::PacsNode& node, const Arguments& arguments, const Progress& progress)
{
    const std::string studyUid = arguments.option("study-uid");
    nlohmann::json series = nlohmann::json::array();
    for (const dicom::SeriesMatch& match : dicom::findSeries(node, studyUid, arguments.option("modality"), progress))
        series.push_back({{"series_instance_uid", match.seriesInstanceUid},
                          {"modality", match.modality},
                          {"series_number", match.seriesNumber},
                          {"series_description", match.seriesDescription},
                          {"series_date", match.seriesDate},
                          {"instances", match.instanceCount}});
    return {{"pacs", dicom::describe(node)}, {"level", "SERIES"}, {"study_instance_uid", studyUid}, {"series", series}};
}

nlohmann::json findStudiesJson(const dicom::PacsNode& node, const Arguments& arguments, const Progress& progress)
{
    dicom::StudyQuery query;
    query.patientName = arguments.option("patient-name");
    query.patientId = arguments.option("patient-id");
    query.modality = arguments.option("modality");
    if (arguments.hasOption("date"))
    {
        const std::string range = arguments.option("date");
        const std::size_t dash = range.find('-');
        query.dateFrom = checkedDate(dash == std::string::npos ? range : range.substr(0, dash));
        query.dateTo = checkedDate(dash == std::string::npos ? range : range.substr(dash + 1));
    }
    nlohmann::json studies = nlohmann::json::array();
    for (const dicom::StudyMatch& match : dicom::findStudies(node, query, progress))
        studies.push_back({{"study_instance_uid", match.studyInstanceUid},
                           {"patient_name", match.patientName},
                           {"patient_id", match.patientId},
                           {"study_date", match.studyDate},
                           {"study_description", match.studyDescription},
                           {"accession_number", match.accessionNumber},
                           {"modalities", match.modalities},
                           {"series", match.seriesCount}});
    return {{"pacs", dicom::describe(node)}, {"level", "STUDY"}, {"studies", studies}};
}

} // namespace

int pacsFindCommand(const Arguments& arguments, const Progress& progress)
{
    const dicom::PacsNode node = nodeFrom(arguments);
    const std::string level = arguments.option("level", "study");
    const auto refuse = [&](const char* option, const char* levels) {
        if (arguments.hasOption(option))
            throw UsageError(std::string("--") + option + " is a filter of the " + levels + ", not of --level " + level);
    };
    if (level == "patient")
    {
        for (const char* option : {"date", "modality", "study-uid"})
            refuse(option, "study and series levels");
        std::cout << findPatientsJson(node, arguments, progress).dump(2) << "\n";
    }
    else if (level == "series")
    {
        if (!arguments.hasOption("study-uid"))
            throw UsageError("--level series needs --study-uid: the study whose series are listed");
        for (const char* option : {"patient-name", "patient-id", "date"})
            refuse(option, "patient and study levels");
        std::cout << findSeriesJson(node, arguments, progress).dump(2) << "\n";
    }
    else if (level == "study")
    {
        refuse("study-uid", "series level");
        std::cout << findStudiesJson(node, arguments, progress).dump(2) << "\n";
    }
    else
        throw UsageError("--level: patient, study or series, not '" + level + "'");
    return 0;
}

int pacsGetCommand(const Arguments& arguments, const Progress& progress)
{
    const dicom::PacsNode node = nodeFrom(arguments);
    const int movePort = arguments.hasOption("move") ? portNumber(arguments.option("move"), "--move") : 0;
    const dicom::RetrieveTarget target(arguments.option("study-uid"), arguments.option("series-uid"));
    const std::filesystem::path out = arguments.option("out");
    checkOutputFolder(out, "pacs retrieve"); // every option checked before the folder is claimed
    claimOutputFolder(out, "pacs retrieve");
    const std::filesystem::path folder = out / "dicom";
    const std::vector<std::filesystem::path> files = movePort > 0
                                                         ? dicom::moveStudy(node, target, folder, movePort, progress)
                                                         : dicom::retrieveStudy(node, target, folder, progress);
    std::cout << nlohmann::json{{"pacs", dicom::describe(node)},
                                {"retrieve", movePort > 0 ? "C-MOVE to port " + std::to_string(movePort) : "C-GET"},
                                {"study_instance_uid", target.studyInstanceUid},
                                {"series_instance_uid", target.seriesInstanceUid},
                                {"files", files.size()},
                                {"folder", folder.string()},
                                {"next", "vascusim-cli import " + folder.string() + " --study <study.vsim>"}}
                     .dump(2)
              << "\n";
    return 0;
}

int pacsStoreCommand(const Arguments& arguments, const Progress& progress)
{
    const dicom::PacsNode node = nodeFrom(arguments);
    const std::string anonymized = arguments.option("anonymized", "refuse");
    if (anonymized != "refuse" && anonymized != "new-study")
        throw UsageError("--anonymized: refuse or new-study, not '" + anonymized + "'");
    const std::vector<std::filesystem::path> files(arguments.positional.begin() + 1, arguments.positional.end());
    const std::vector<dicom::StoredObject> stored = dicom::storeFiles(
        node, files, anonymized == "new-study" ? dicom::AnonymizedObjects::NewStudy : dicom::AnonymizedObjects::Refuse,
        progress);
    nlohmann::json objects = nlohmann::json::array();
    for (const dicom::StoredObject& object : stored)
        objects.push_back({{"file", object.file.string()},
                           {"modality", object.modality},
                           {"sop_class_uid", object.sopClassUid},
                           {"sop_instance_uid", object.sopInstanceUid},
                           {"series_instance_uid", object.seriesInstanceUid},
                           {"study_instance_uid", object.studyInstanceUid},
                           {"as_new_study", object.asNewStudy}});
    std::cout << nlohmann::json{{"pacs", dicom::describe(node)}, {"stored", objects}}.dump(2) << "\n";
    return 0;
}

} // namespace vsim::cli
