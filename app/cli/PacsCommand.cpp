#include "PacsCommand.h"

#include "vsim/core/OutputSafety.h"
#include "vsim/dicom/PacsClient.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace vsim::cli {
namespace {

dicom::PacsNode nodeFrom(const Arguments& arguments)
{
    dicom::PacsNode node;
    node.calledAeTitle = arguments.option("aet");
    node.host = arguments.option("host");
    const std::string port = arguments.option("port");
    char* end = nullptr;
    const long number = std::strtol(port.c_str(), &end, 10);
    if (port.empty() || *end != '\0' || number < 1 || number > 65535)
        throw UsageError("--port: a TCP port from 1 to 65535, not '" + port + "'");
    node.port = int(number);
    node.callingAeTitle = arguments.option("calling-aet", node.callingAeTitle);
    if (arguments.hasOption("timeout"))
    {
        const long seconds = std::strtol(arguments.option("timeout").c_str(), &end, 10);
        if (*end != '\0' || seconds < 1 || seconds > 600)
            throw UsageError("--timeout: whole seconds from 1 to 600");
        node.timeoutS = int(seconds);
    }
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

int pacsFindCommand(const Arguments& arguments, const Progress&)
{
    const dicom::PacsNode node = nodeFrom(arguments);
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
    for (const dicom::StudyMatch& match : dicom::findStudies(node, query))
        studies.push_back({{"study_instance_uid", match.studyInstanceUid},
                           {"patient_name", match.patientName},
                           {"patient_id", match.patientId},
                           {"study_date", match.studyDate},
                           {"study_description", match.studyDescription},
                           {"accession_number", match.accessionNumber},
                           {"modalities", match.modalities},
                           {"series", match.seriesCount}});
    std::cout << nlohmann::json{{"pacs", dicom::describe(node)}, {"level", "STUDY"}, {"studies", studies}}.dump(2) << "\n";
    return 0;
}

int pacsGetCommand(const Arguments& arguments, const Progress& progress)
{
    const dicom::PacsNode node = nodeFrom(arguments);
    const std::filesystem::path out = arguments.option("out");
    checkOutputFolder(out, "pacs retrieve");
    claimOutputFolder(out, "pacs retrieve");
    const std::filesystem::path folder = out / "dicom";
    const std::vector<std::filesystem::path> files = dicom::retrieveStudy(node, arguments.option("study-uid"), folder, progress);
    std::cout << nlohmann::json{{"pacs", dicom::describe(node)},
                                {"study_instance_uid", arguments.option("study-uid")},
                                {"files", files.size()},
                                {"folder", folder.string()},
                                {"next", "vascusim-cli import " + folder.string() + " --study <study.vsim>"}}
                     .dump(2)
              << "\n";
    return 0;
}

} // namespace vsim::cli
