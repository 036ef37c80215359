#pragma once

// A DICOM element's value as text, the padding trimmed: what the importer's headers and the PACS client's answers
// read (internal to the dicom module; DCMTK types).

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcitem.h>

#include <string>

namespace vsim::dicom::detail {

/// `text` without leading and trailing blanks (DICOM pads values to an even length).
inline std::string trimmed(const char* text)
{
    std::string value = text ? text : "";
    const auto begin = value.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos)
        return {};
    return value.substr(begin, value.find_last_not_of(" \t\r\n") - begin + 1);
}

/// The element's whole value (all its values, backslash-separated), trimmed; empty when absent.
inline std::string datasetText(DcmItem& item, const DcmTagKey& tag)
{
    OFString value;
    return item.findAndGetOFStringArray(tag, value).good() ? trimmed(value.c_str()) : std::string();
}

} // namespace vsim::dicom::detail
