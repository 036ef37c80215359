#include "vsim/dicom/DicomScan.h"

#include "DcmtkSetup.h"
#include "vsim/core/Localized.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/core/ParallelFor.h"
#include "vsim/core/StoredText.h"

#include <dcmtk/config/osconfig.h>
#include <dcmtk/dcmdata/dcdeftag.h>
#include <dcmtk/dcmdata/dcfilefo.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <variant>

namespace vsim::dicom {
namespace fs = std::filesystem;
namespace {

/// A stored text about `count` things: the first pattern for one, the second for several (%1: the count).
std::string counted(std::size_t count, const Pattern& one, const Pattern& several)
{
    return storedText(Pattern{count == 1 ? one.text : several.text, {std::to_string(count)}});
}

bool isDicomDir(const fs::path& file)
{
    std::string name = file.filename().string();
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return name == "DICOMDIR";
}

/// The image files a DICOMDIR references (Referenced File ID, relative to the DICOMDIR's folder).
std::vector<fs::path> filesOfDicomDir(const fs::path& dicomDir)
{
    ensureDcmtkCodecs();
    DcmFileFormat file;
    if (file.loadFile(dicomDir.string().c_str()).bad())
        throw Error("cannot read the DICOMDIR", {{"file", dicomDir.string()}});
    DcmSequenceOfItems* records = nullptr;
    if (file.getDataset()->findAndGetSequence(DCM_DirectoryRecordSequence, records).bad() || !records)
        throw Error("the DICOMDIR has no directory records", {{"file", dicomDir.string()}});
    std::vector<fs::path> files;
    for (unsigned long r = 0; r < records->card(); ++r)
    {
        DcmItem* record = records->getItem(r);
        OFString component;
        fs::path relative;
        for (unsigned long c = 0; record->findAndGetOFString(DCM_ReferencedFileID, component, c).good(); ++c)
            relative /= component.c_str();
        if (relative.empty())
            continue;
        fs::path candidate = dicomDir.parent_path() / relative;
        if (!fs::exists(candidate)) // media written with upper-case IDs, copied to a case-sensitive disk in lower case
        {
            std::string lower = relative.string();
            std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
            candidate = dicomDir.parent_path() / lower;
        }
        files.push_back(candidate);
    }
    return files;
}

std::vector<fs::path> listInputFiles(const fs::path& input)
{
    std::error_code error;
    if (fs::is_regular_file(input, error))
        return isDicomDir(input) ? filesOfDicomDir(input) : std::vector<fs::path>{input};
    if (!fs::is_directory(input, error))
        throw Error("no such file or folder", {{"path", input.string()}});
    std::vector<fs::path> files;
    for (fs::recursive_directory_iterator it(input, fs::directory_options::skip_permission_denied, error), end;
         !error && it != end; it.increment(error))
        if (it->is_regular_file(error) && it->path().filename() != vsim::kOwnedFolderMarker) // VascuSim's own marker
            files.push_back(it->path());
    std::sort(files.begin(), files.end());
    return files;
}

// --- grouping ------------------------------------------------------------------------------------------------

long rounded(double value, double step)
{
    return std::lround(value / step);
}

/// What must agree within a sub-series.
struct SubSeriesKey
{
    std::vector<long> values;
    std::string imageType;
    bool operator<(const SubSeriesKey& other) const
    {
        return std::tie(values, imageType) < std::tie(other.values, other.imageType);
    }
};

SubSeriesKey subSeriesKey(const DicomImageHeader& header, const FrameGeometry& geometry)
{
    SubSeriesKey key;
    for (const Eigen::Vector3d& axis : {geometry.xDirection, geometry.yDirection})
        for (int c = 0; c < 3; ++c)
            key.values.push_back(rounded(axis[c], 1e-3));
    key.values.push_back(header.format.rows);
    key.values.push_back(header.format.columns);
    key.values.push_back(rounded(geometry.rowSpacing, 1e-4));
    key.values.push_back(rounded(geometry.columnSpacing, 1e-4));
    key.imageType = header.imageType;
    return key;
}

/// Positions along the normal, rounded to 0.01 mm: used to see repeated positions.
long positionKey(const DicomSeries& series, const DicomSlice& slice)
{
    const FrameGeometry& geometry = series.geometryOf(slice);
    return rounded(geometry.position.dot(geometry.xDirection.cross(geometry.yDirection)), 0.01);
}

/// Splits a sub-series by acquisition number when that removes repeated positions (two acquisitions of the
/// same region under one Series Instance UID).
std::vector<std::vector<DicomSlice>> splitByAcquisition(const DicomSeries& series)
{
    std::map<int, std::vector<DicomSlice>> byAcquisition;
    std::set<long> positions;
    bool repeats = false;
    for (const DicomSlice& slice : series.slices)
    {
        byAcquisition[series.headerOf(slice).acquisitionNumber].push_back(slice);
        repeats |= !positions.insert(positionKey(series, slice)).second;
    }
    if (!repeats || byAcquisition.size() < 2)
        return {series.slices};
    std::vector<std::vector<DicomSlice>> parts;
    for (auto& [number, slices] : byAcquisition)
        parts.push_back(std::move(slices));
    return parts;
}

DicomSeries seriesFrom(const std::vector<DicomImageHeader>& headers, std::vector<DicomSlice> slices)
{
    DicomSeries series;
    std::map<std::size_t, std::size_t> remap;
    for (DicomSlice& slice : slices)
    {
        auto [it, inserted] = remap.emplace(slice.header, series.headers.size());
        if (inserted)
            series.headers.push_back(headers[slice.header]);
        slice.header = it->second;
    }
    series.slices = std::move(slices);
    const DicomImageHeader& first = series.headers.front();
    series.studyInstanceUid = first.studyInstanceUid;
    series.seriesInstanceUid = first.seriesInstanceUid;
    series.modality = first.modality;
    series.imageType = first.imageType;
    series.seriesNumber = first.seriesNumber;
    const auto description = first.attributes.find("series_description");
    series.description = description == first.attributes.end() ? std::string() : description->second;
    return series;
}

} // namespace

std::vector<DicomSeries> groupIntoSeries(std::vector<DicomImageHeader> headers, std::vector<std::string>& warnings)
{
    // Series in order of first appearance.
    std::vector<std::pair<std::string, std::vector<std::size_t>>> bySeries;
    std::map<std::string, std::size_t> seriesIndex;
    std::size_t localizers = 0;
    for (std::size_t h = 0; h < headers.size(); ++h)
    {
        if (headers[h].isLocalizer())
        {
            ++localizers;
            continue;
        }
        const std::string key = headers[h].studyInstanceUid + "|" + headers[h].seriesInstanceUid;
        auto [it, inserted] = seriesIndex.emplace(key, bySeries.size());
        if (inserted)
            bySeries.push_back({headers[h].seriesInstanceUid, {}});
        bySeries[it->second].second.push_back(h);
    }
    if (localizers > 0)
        warnings.push_back(counted(localizers, Pattern{"%1 localizer image skipped", {}},
                                   Pattern{"%1 localizer images skipped", {}}));

    std::vector<DicomSeries> result;
    for (const auto& [uid, members] : bySeries)
    {
        std::map<SubSeriesKey, std::vector<DicomSlice>> bySubKey;
        for (std::size_t h : members)
            for (std::size_t f = 0; f < headers[h].frames.size(); ++f)
                bySubKey[subSeriesKey(headers[h], headers[h].frames[f])].push_back({h, int(f)});
        std::vector<DicomSeries> parts;
        for (auto& [key, slices] : bySubKey)
        {
            const DicomSeries part = seriesFrom(headers, std::move(slices));
            for (std::vector<DicomSlice>& acquisition : splitByAcquisition(part))
                parts.push_back(seriesFrom(part.headers, std::move(acquisition)));
        }
        std::stable_sort(parts.begin(), parts.end(),
                         [](const DicomSeries& a, const DicomSeries& b) { return a.slices.size() > b.slices.size(); });
        for (std::size_t p = 0; p < parts.size(); ++p)
        {
            parts[p].key = uid;
            if (p > 0)
                parts[p].key += '#' + std::to_string(p + 1);
            if (parts.size() > 1)
                parts[p].warnings.push_back(storedText(Pattern{
                    "series split into %1 sub-series (orientation, image size, pixel spacing, image type or "
                    "acquisition differ); this is part %2",
                    {std::to_string(parts.size()), std::to_string(p + 1)}}));
            result.push_back(std::move(parts[p]));
        }
    }
    return result;
}

const DicomSeries* DicomScanResult::find(const std::string& keyOrUid) const
{
    for (const DicomSeries& candidate : series)
        if (candidate.key == keyOrUid)
            return &candidate;
    for (const DicomSeries& candidate : series)
        if (candidate.seriesInstanceUid == keyOrUid)
            return &candidate;
    return nullptr;
}

const DicomSeries* DicomScanResult::defaultSeries() const
{
    const DicomSeries* best = nullptr;
    for (bool ctOnly : {true, false})
    {
        for (const DicomSeries& candidate : series)
            if ((!ctOnly || candidate.modality == "CT") && (!best || candidate.slices.size() > best->slices.size()))
                best = &candidate;
        if (best)
            return best;
    }
    return nullptr;
}

DicomScanResult scanDicom(const fs::path& input, const Progress& progress)
{
    const std::vector<fs::path> files = listInputFiles(input);
    DicomScanResult result;
    result.filesSeen = files.size();

    enum class Outcome { Image, NotDicom, NotImage, Damaged };
    std::vector<Outcome> outcomes(files.size(), Outcome::Damaged);
    std::vector<std::optional<DicomImageHeader>> headers(files.size());
    parallelFor(
        files.size(),
        [&](std::size_t f) {
            try
            {
                headers[f] = readDicomHeader(files[f]);
                outcomes[f] = Outcome::Image;
            }
            catch (const NotDicomFile&)
            {
                outcomes[f] = Outcome::NotDicom;
            }
            catch (const NotAnImage&)
            {
                outcomes[f] = Outcome::NotImage;
            }
            catch (const Error&)
            {
                outcomes[f] = Outcome::Damaged;
            }
        },
        [&](std::size_t done) { progress.report(double(done) / double(files.size()), localized("vsim::Progress", "reading DICOM headers")); });

    std::vector<DicomImageHeader> images;
    for (std::size_t f = 0; f < files.size(); ++f)
    {
        switch (outcomes[f])
        {
        case Outcome::Image: images.push_back(std::move(*headers[f])); break;
        case Outcome::NotDicom: ++result.nonDicomFiles; break;
        case Outcome::NotImage: ++result.nonImageFiles; break;
        case Outcome::Damaged: ++result.damagedFiles; break;
        }
    }
    result.imageFiles = images.size();
    if (result.nonDicomFiles)
        result.warnings.push_back(counted(result.nonDicomFiles, Pattern{"%1 file is not DICOM (skipped)", {}},
                                          Pattern{"%1 files are not DICOM (skipped)", {}}));
    if (result.nonImageFiles)
        result.warnings.push_back(counted(result.nonImageFiles,
                                          Pattern{"%1 DICOM file holds no image (DICOMDIR, reports, ...; skipped)", {}},
                                          Pattern{"%1 DICOM files hold no image (DICOMDIR, reports, ...; skipped)", {}}));
    if (result.damagedFiles)
        result.warnings.push_back(counted(result.damagedFiles, Pattern{"%1 DICOM file is damaged or truncated (skipped)", {}},
                                          Pattern{"%1 DICOM files are damaged or truncated (skipped)", {}}));
    result.series = groupIntoSeries(std::move(images), result.warnings);
    return result;
}

} // namespace vsim::dicom
