#include "vsim/app/DemoStudy.h"

#include "vsim/study/Study.h"

#include <cmath>
#include <cstdlib>
#include <random>

namespace vsim::app {
namespace {

// Hounsfield units of the tissues (typical arterial-phase CTA values).
constexpr double kAirHu = -1000.0;
constexpr double kFatHu = -100.0;
constexpr double kSoftTissueHu = 40.0;
constexpr double kBoneHu = 800.0;
constexpr double kContrastBloodHu = 380.0;
constexpr double kNoiseHu = 20.0;

/// Aorta radius (mm) along z (mm from the volume centre): 10 mm with a Gaussian-profile aneurysm of 24 mm.
double aortaRadius(double z)
{
    return 10.0 + 14.0 * std::exp(-z * z / (2.0 * 25.0 * 25.0));
}

} // namespace

CtVolume makeDemoVolume(const Progress& progress)
{
    VolumeGeometry geometry;
    geometry.dims = {192, 192, 160};
    geometry.spacing = {0.8, 0.8, 1.0};
    geometry.origin = {-76.4, -76.4, -79.5}; // centres the volume on the patient-frame origin
    CtVolume volume(geometry);
    std::mt19937 random(2026);
    std::normal_distribution<double> noise(0.0, kNoiseHu);
    for (int k = 0; k < geometry.dims[2]; ++k)
    {
        for (int j = 0; j < geometry.dims[1]; ++j)
        {
            for (int i = 0; i < geometry.dims[0]; ++i)
            {
                const Eigen::Vector3d p = geometry.indexToPatient({double(i), double(j), double(k)});
                const double body = std::pow(p.x() / 72.0, 2) + std::pow(p.y() / 58.0, 2); // ellipse, 1 on the skin
                double hu = kAirHu;
                if (body < 1.0)
                    hu = body > 0.8 ? kFatHu : kSoftTissueHu;
                const Eigen::Vector2d spine(p.x(), p.y() - 30.0); // vertebral body, posterior (+y)
                if (spine.norm() < 14.0)
                    hu = kBoneHu;
                const Eigen::Vector2d aorta(p.x() - 8.0, p.y() - 2.0); // left of midline (+x), anterior to the spine
                if (aorta.norm() < aortaRadius(p.z()))
                    hu = kContrastBloodHu;
                volume.at(i, j, k) = static_cast<std::int16_t>(std::lround(hu + (body < 1.0 ? noise(random) : 0.0)));
            }
        }
        progress.report(double(k + 1) / geometry.dims[2], "generating demo CT");
    }
    return volume;
}

std::filesystem::path ensureDemoStudy(const std::filesystem::path& bundle, const Progress& progress)
{
    if (std::filesystem::exists(bundle / "study.json"))
        return bundle;
    std::filesystem::remove_all(bundle); // an interrupted first write leaves no manifest: start again
    study::Study demo = study::Study::create(bundle, "Demo: abdominal aortic aneurysm");
    demo.setMetadata("patient_name", "DEMO^PHANTOM");
    demo.setMetadata("study_description", "Synthetic CTA, fusiform AAA");
    study::Provenance provenance;
    provenance.command = "demo volume";
    provenance.parameters = {{"noise_hu", "20"}, {"seed", "2026"}, {"aneurysm_radius_mm", "24"}};
    demo.addImage(makeDemoVolume(progress), "Demo CTA", provenance);
    demo.save();
    return bundle;
}

std::filesystem::path defaultDemoStudyPath()
{
    const char* dataHome = std::getenv("XDG_DATA_HOME");
    const char* home = std::getenv("HOME");
    const std::filesystem::path base = dataHome && *dataHome ? std::filesystem::path(dataHome)
                                       : home                 ? std::filesystem::path(home) / ".local/share"
                                                              : std::filesystem::temp_directory_path();
    return base / "VascuSim" / "demo.vsim";
}

} // namespace vsim::app
