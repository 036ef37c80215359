#include "vsim/dicom/DicomImport.h"

#include "StackResampler.h"
#include "vsim/core/Localized.h"
#include "vsim/core/ParallelFor.h"
#include "vsim/core/StoredText.h"
#include "vsim/dicom/SeriesGeometry.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

namespace vsim::dicom {
namespace {

/// MemAvailable from /proc/meminfo in bytes; 0 when unknown.
std::uint64_t availableMemory()
{
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    std::uint64_t kib = 0;
    std::string unit;
    while (meminfo >> key >> kib >> unit)
        if (key == "MemAvailable:")
            return kib * 1024;
    return 0;
}

std::string gibibytes(std::uint64_t bytes)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f GiB", double(bytes) / double(1ull << 30));
    return buffer;
}

std::uint64_t voxelBytes(const VolumeGeometry& grid)
{
    return std::uint64_t(grid.voxelCount()) * sizeof(std::int16_t);
}

std::uint64_t memoryNeeded(const DicomSeries& series, const SeriesGeometry& plan)
{
    const std::uint64_t perSlice = std::uint64_t(series.format().pixelsPerFrame()) * sizeof(std::int16_t);
    std::uint64_t bytes = voxelBytes(plan.grid);
    if (plan.resample)
        bytes += perSlice * plan.sorted.size(); // the source stack, held while the grid is filled
    return bytes;
}

void refuseIfTooLarge(const DicomSeries& series, const SeriesGeometry& plan, const DicomImportOptions& options)
{
    const std::uint64_t needed = memoryNeeded(series, plan);
    const std::uint64_t limit = options.memoryLimitBytes ? options.memoryLimitBytes : availableMemory();
    if (limit != 0 && needed > limit)
    {
        const auto& d = plan.grid.dims;
        throw Error(Pattern{"the series needs %1 of memory for %2 x %3 x %4 voxels, but only %5 is available",
                            {gibibytes(needed), std::to_string(d[0]), std::to_string(d[1]), std::to_string(d[2]),
                             gibibytes(limit)}},
                    {{"needed_bytes", std::to_string(needed)}, {"available_bytes", std::to_string(limit)}});
    }
}

/// Decodes the sorted slices into consecutive slices of `destination`, one file at a time on every thread.
void decodeSorted(const DicomSeries& series, const std::vector<DicomSlice>& sorted, CtVolume& destination,
                  unsigned threads, const Progress& progress, std::size_t& clamped)
{
    const std::size_t perSlice = series.format().pixelsPerFrame();
    std::map<std::size_t, std::pair<std::vector<int>, std::vector<std::int16_t*>>> byFile;
    for (std::size_t k = 0; k < sorted.size(); ++k)
    {
        auto& [frames, outputs] = byFile[sorted[k].header];
        frames.push_back(sorted[k].frame);
        outputs.push_back(destination.data() + k * perSlice);
    }
    std::vector<const std::pair<std::vector<int>, std::vector<std::int16_t*>>*> work;
    std::vector<std::size_t> headerOfWork;
    for (const auto& [header, job] : byFile)
    {
        work.push_back(&job);
        headerOfWork.push_back(header);
    }
    std::atomic<std::size_t> clampedValues{0};
    parallelFor(
        work.size(),
        [&](std::size_t w) {
            const DicomImageHeader& header = series.headers[headerOfWork[w]];
            try
            {
                clampedValues += decodeFramesToHu(header, work[w]->first, work[w]->second);
            }
            catch (const Cancelled&)
            {
                throw;
            }
            catch (const Error& error)
            {
                throw Error(Pattern{"cannot decode image %1 of the series: %2",
                                    {std::to_string(header.instanceNumber), error.message()}},
                            error.context());
            }
        },
        [&](std::size_t done) { progress.report(double(done) / double(work.size()), localized("vsim::Progress", "decoding DICOM")); }, threads);
    clamped = clampedValues;
}

} // namespace

std::uint64_t importMemoryNeeded(const DicomSeries& series)
{
    return memoryNeeded(series, planSeriesGeometry(series));
}

DicomVolume importDicomSeries(const DicomSeries& series, const DicomImportOptions& options, const Progress& progress)
{
    const SeriesGeometry plan = planSeriesGeometry(series);
    refuseIfTooLarge(series, plan, options);
    DicomVolume result;
    result.warnings = series.warnings;
    result.warnings.insert(result.warnings.end(), plan.warnings.begin(), plan.warnings.end());
    if (series.modality != "CT")
        result.warnings.push_back(
            series.modality.empty()
                ? storedText("modality is missing, not CT: values are not Hounsfield units")
                : storedText(Pattern{"modality is %1, not CT: values are not Hounsfield units", {series.modality}}));

    std::size_t clamped = 0;
    if (!plan.resample)
    {
        result.image = CtVolume::uninitialized(plan.grid); // every slice is decoded into
        decodeSorted(series, plan.sorted, result.image, options.threads, progress, clamped);
    }
    else
    {
        const SliceStack stack = plan.sourceStack(series);
        CtVolume source = CtVolume::uninitialized(stack.nominalGeometry());
        decodeSorted(series, plan.sorted, source, options.threads, progress.subRange(0.0, 0.6), clamped);
        result.image = resampleStack(source, stack, plan.offsets, plan.grid, progress.subRange(0.6, 1.0));
    }
    if (clamped > 0)
        result.warnings.push_back(
            storedText(Pattern{"%1 values outside -32768..32767 HU were clamped", {std::to_string(clamped)}}));

    result.attributes = series.attributes();
    result.attributes["series_key"] = series.key;
    result.attributes["image_type"] = series.imageType;
    result.attributes["transfer_syntax_uid"] = series.format().transferSyntaxUid;
    result.attributes["source_slices"] = std::to_string(plan.sorted.size());
    // The source instances slice by slice, for the references of a DICOM SEG made on this grid: only where each
    // slice of the grid is one single-frame file of one SOP class (not resampled, not an enhanced multi-frame).
    std::string classUid = series.headerOf(plan.sorted.front()).sopClassUid, instances;
    bool referable = !plan.resample && !classUid.empty();
    for (const DicomSlice& slice : plan.sorted)
    {
        const DicomImageHeader& header = series.headerOf(slice);
        referable = referable && slice.frame == 0 && header.frames.size() == 1 && header.sopClassUid == classUid &&
                    !header.sopInstanceUid.empty();
        instances += (instances.empty() ? "" : "\\") + header.sopInstanceUid;
    }
    if (referable)
    {
        result.attributes["source_sop_class_uid"] = classUid;
        result.attributes["source_sop_instance_uids"] = instances; // in slice order, backslash-separated as in DICOM
    }
    if (plan.tiltDegrees > 1e-3)
    {
        char tilt[32];
        std::snprintf(tilt, sizeof tilt, "%.3f", plan.tiltDegrees);
        result.attributes["gantry_tilt_deg"] = tilt;
    }
    progress.report(1.0, localized("vsim::Progress", "DICOM imported"));
    return result;
}

std::vector<std::uint8_t> seriesThumbnail(const DicomSeries& series, int size)
{
    const SeriesGeometry plan = planSeriesGeometry(series);
    const DicomSlice& middle = plan.sorted[plan.sorted.size() / 2];
    const PixelFormat& format = series.format();
    std::vector<std::int16_t> hu(format.pixelsPerFrame());
    decodeFramesToHu(series.headerOf(middle), {middle.frame}, {hu.data()});

    constexpr double kWidth = 700.0, kLevel = 200.0; // CTA window
    std::vector<std::uint8_t> thumbnail(std::size_t(size) * std::size_t(size), 0);
    const double scale = double(std::max(format.columns, format.rows)) / size;
    const double offsetX = 0.5 * (size - format.columns / scale), offsetY = 0.5 * (size - format.rows / scale);
    for (int v = 0; v < size; ++v)
        for (int u = 0; u < size; ++u)
        {
            const int i = int((u - offsetX + 0.5) * scale), j = int((v - offsetY + 0.5) * scale);
            if (i < 0 || j < 0 || i >= format.columns || j >= format.rows)
                continue;
            const double value = (hu[std::size_t(j) * format.columns + i] - (kLevel - 0.5 * kWidth)) / kWidth;
            thumbnail[std::size_t(v) * size + u] = std::uint8_t(std::clamp(value, 0.0, 1.0) * 255.0 + 0.5);
        }
    return thumbnail;
}

} // namespace vsim::dicom
