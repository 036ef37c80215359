// `import <mask> --study S --as-label`: a reference mask or another program's segmentation (NIfTI, NRRD,
// MetaImage, or a DICOM mask series) as a label artifact on the study's image grid (study::maskOnImageGrid).

#include "CliCommands.h"
#include "CliSupport.h"
#include "CommandLine.h"
#include "vsim/app/DicomStudyImport.h"
#include "vsim/dicom/DicomImport.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/study/LabelImport.h"
#include "vsim/study/VolumeFileImport.h"

#include <cmath>
#include <iostream>

namespace vsim::cli {
namespace fs = std::filesystem;

int importLabelIntoStudy(const Arguments& arguments, const Progress& progress)
{
    const fs::path input = arguments.positional.at(0);
    study::Study study = openStudyForWriting(arguments);
    const std::string imageId = chooseArtifact(study, arguments.option("image"), study::ArtifactKind::Image,
                                               "the study has no CT image for the label's grid: import the CT first");
    std::optional<std::uint8_t> value; // the mask's own labels unless one value is asked for
    if (arguments.hasOption("label-value"))
    {
        const double given = quantityOption(arguments, "label-value", "", 1.0);
        if (given < 1.0 || given > 255.0 || given != std::floor(given))
            throw Error("--label-value expects a whole number from 1 to 255");
        value = std::uint8_t(given);
    }
    std::vector<std::string> warnings;
    CtVolume mask;
    if (isVolumeFile(input))
    {
        study::ImportedVolume read = study::readVolumeFile(input, progress.subRange(0.0, 0.8));
        mask = read.image;
        warnings = read.warnings;
    }
    else
    {
        const dicom::DicomScanResult scan = dicom::scanDicom(input, progress.subRange(0.0, 0.2));
        dicom::DicomVolume volume =
            dicom::importDicomSeries(app::chooseSeries(scan, arguments.option("series")), {}, progress.subRange(0.2, 0.8));
        mask = volume.image;
        warnings = volume.warnings;
    }
    const LabelVolume label =
        study::maskOnImageGrid(mask, study.volumeGeometry(imageId), value, warnings);
    study::Provenance provenance;
    provenance.command = "import label";
    provenance.inputs = {input.filename().string(), imageId};
    provenance.parameters = {{"label_value", value ? std::to_string(int(*value)) : std::string("as in the mask")}};
    const std::string name = input.filename().string();
    const std::string id = study.addLabel(label, name.empty() ? "Imported label" : name, provenance, warnings);
    study.save();
    progress.report(1.0, "saved");
    std::size_t voxels = 0;
    for (std::size_t v = 0; v < label.size(); ++v)
        voxels += label.data()[v] != 0;
    std::cout << "imported " << name << " as " << id << " on the grid of " << imageId << ": " << voxels
              << " labelled voxels\n";
    for (const std::string& warning : warnings)
        std::cout << "warning: " << warning << "\n";
    return 0;
}

} // namespace vsim::cli
