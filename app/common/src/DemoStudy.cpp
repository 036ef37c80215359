#include "vsim/app/DemoStudy.h"

#include "vsim/app/DicomStudyImport.h"
#include "vsim/core/Localized.h"
#include "vsim/core/OutputSafety.h"
#include "vsim/dicom/DicomScan.h"
#include "vsim/dicom/PhantomWriter.h"
#include "vsim/study/Study.h"

#include <cstdlib>

namespace vsim::app {
namespace fs = std::filesystem;

fs::path ensureDemoStudy(const fs::path& bundle, const Progress& progress)
{
    if (fs::exists(bundle / "study.json"))
        return bundle;
    // A new, empty or interrupted demo folder (marked by Study::create); a folder of anyone else's is refused.
    study::Study demo = study::Study::create(bundle, "Demo: abdominal aortic aneurysm (aaa phantom)");
    const fs::path scratch = bundle.parent_path() / (bundle.filename().string() + ".phantom");
    const dicom::PhantomOptions options; // full size, the analytic style (the CLI defaults to the patient-like one)
    const dicom::PhantomFiles phantom =
        dicom::writePhantom(dicom::PhantomKind::Aaa, options, dicom::phantomSeriesDescription(dicom::PhantomKind::Aaa),
                            scratch, progress.subRange(0.0, 0.6));
    const dicom::DicomScanResult scan = dicom::scanDicom(phantom.dicomFolder, progress.subRange(0.6, 0.65));
    importDicomSeriesIntoStudy(demo, chooseSeries(scan, {}), phantom.dicomFolder, {}, progress.subRange(0.65, 0.9));
    demo.save();
    progress.report(1.0, localized("vsim::Progress", "demo study written"));
    removeWrittenFiles(phantom.written(), scratch);
    return bundle;
}

fs::path defaultDemoStudyPath()
{
    const char* dataHome = std::getenv("XDG_DATA_HOME");
    const char* home = std::getenv("HOME");
    const fs::path base = dataHome && *dataHome ? fs::path(dataHome)
                          : home                 ? fs::path(home) / ".local/share"
                                                 : fs::temp_directory_path();
    return base / "VascuSim" / "demo.vsim";
}

} // namespace vsim::app
