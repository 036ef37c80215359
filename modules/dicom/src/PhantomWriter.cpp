#include "vsim/dicom/PhantomWriter.h"

#include "vsim/core/Localized.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/dicom/AnatomyPhantom.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/interop/NrrdFile.h"

#include <algorithm>
#include <cctype>
#include <fstream>

namespace vsim::dicom {

CtSeriesDescription phantomSeriesDescription(PhantomKind kind)
{
    std::string upper = phantomKindName(kind);
    std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    CtSeriesDescription description;
    description.patientName = "PHANTOM^" + upper;
    description.patientId = "VSIM-" + upper;
    description.studyDescription = "CT angiography phantom (" + phantomKindName(kind) + ")";
    description.seriesDescription = "CTA arterial phase, " + phantomKindName(kind) + " phantom";
    return description;
}

PhantomFiles writePhantom(PhantomKind kind, const PhantomOptions& options, const CtSeriesDescription& description,
                          const std::filesystem::path& out, const Progress& progress)
{
    claimOutputFolder(out, "phantom"); // before the rendering: a refused folder costs no time
    PhantomFiles files;
    files.geometry = phantomGeometry(options);
    files.dicomFolder = out / "dicom";
    files.truthJson = out / "truth.json";
    files.truthLabels = out / "truth-label.nrrd";

    CtVolume ct;
    LabelVolume labels;
    std::string truth;
    if (options.style == PhantomStyle::Patient)
    {
        const AnatomyPhantom phantom = buildAnatomyPhantom(kind, options);
        ct = renderAnatomyCt(phantom, files.geometry, options.seed, progress.subRange(0.0, 0.45));
        labels = renderAnatomyLabels(phantom, files.geometry, progress.subRange(0.85, 0.97));
        truth = anatomyTruthJson(phantom, options);
    }
    else
    {
        const PhantomModel model = buildPhantomModel(kind, options);
        ct = renderPhantomCt(model, stackOf(files.geometry), options, progress.subRange(0.0, 0.45));
        labels = renderPhantomLabels(model, files.geometry, progress.subRange(0.85, 0.97));
        truth = phantomTruthJson(model, options);
    }
    files.series = writeCtSeries(ct, stackOf(files.geometry), description, files.dicomFolder,
                                 progress.subRange(0.45, 0.85));
    interop::writeNrrd(labels, files.truthLabels, true);
    std::ofstream truthFile(files.truthJson, std::ios::trunc);
    truthFile << truth;
    if (!truthFile.flush())
        throw Error("cannot write truth.json", {{"file", files.truthJson.string()}});
    progress.report(1.0, localized("vsim::Progress", "phantom written"));
    return files;
}

std::vector<std::filesystem::path> PhantomFiles::written() const
{
    std::vector<std::filesystem::path> all = series.files;
    all.insert(all.end(), {truthJson, truthLabels, truthJson.parent_path() / kOwnedFolderMarker});
    return all;
}

} // namespace vsim::dicom
