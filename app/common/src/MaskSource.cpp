#include "vsim/app/MaskSource.h"

#include "vsim/app/DicomStudyImport.h"
#include "vsim/core/Localized.h"
#include "vsim/dicom/DicomImport.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/dicom/DicomSegmentation.h"
#include "vsim/study/VolumeFileImport.h"

namespace vsim::app {

bool isVolumeFile(const std::filesystem::path& file)
{
    const std::string name = file.filename().string();
    for (const char* extension : {".nii", ".nii.gz", ".nrrd", ".nhdr", ".mha", ".mhd"})
        if (name.size() > std::string(extension).size() &&
            name.compare(name.size() - std::string(extension).size(), std::string::npos, extension) == 0)
            return true;
    return false;
}

MaskSource readMaskSource(const std::filesystem::path& input, const std::string& seriesKey, const Progress& progress)
{
    MaskSource source;
    if (isVolumeFile(input))
    {
        study::ImportedVolume read = study::readVolumeFile(input, progress);
        source.mask = read.image;
        source.warnings = read.warnings;
        source.kind = "volume file";
    }
    else if (dicom::isDicomSegmentation(input))
    {
        dicom::SegmentationMask seg = dicom::readDicomSegmentation(input);
        source.mask = seg.mask;
        source.segmentLabels = seg.segmentLabels;
        source.warnings = seg.warnings;
        source.kind = "DICOM SEG";
    }
    else
    {
        const dicom::DicomScanResult scan = dicom::scanDicom(input, progress.subRange(0.0, 0.2));
        dicom::DicomVolume volume = dicom::importDicomSeries(chooseSeries(scan, seriesKey), {}, progress.subRange(0.2, 1.0));
        source.mask = volume.image;
        source.warnings = volume.warnings;
        source.kind = "DICOM mask series";
    }
    progress.report(1.0, localized("vsim::Progress", "mask read"));
    return source;
}

} // namespace vsim::app
