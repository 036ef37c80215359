#pragma once

// Patient-like CT angiography phantoms ("style patient"): anatomy painted as solids in order (later solids cover
// earlier ones), imaged by a scanner model that none of VascuSim's estimators assumes:
//   1. occupancy sampled on 4 x 4 x 4 sub-voxels (exact painter's order inside each voxel);
//   2. a point-spread function: in-plane Gaussian of 0.6..1.0 mm FWHM, a Gaussian slice sensitivity profile whose
//      FWHM is the slice thickness (1.0..1.5 x the slice spacing);
//   3. calcium blooming: the excess HU of calcified plaque spread by a PSF 2.5 x wider;
//   4. noise with a CT-like noise power spectrum (white noise through a difference of Gaussians in-plane: no power
//      at zero frequency, a peak at mid frequencies, as filtered back-projection gives), 10..30 HU.
// Blur, slice thickness, noise and contrast are drawn from the seed within those clinical ranges unless given.
// The estimators (segmentation thresholds, the blurred-tube radius fit, the partial-volume model Phi(-d/sigma))
// assume one Gaussian edge of a uniform disc on uniform tissue without noise correlation: here the edges are
// box-sampled then PSF-blurred, tissues touch, contrast falls along the arteries and the noise is correlated.
// Positions are mm in the DICOM patient frame (LPS), centred at kPhantomCentre like the analytic phantoms.

#include "vsim/core/ImageVolume.h"
#include "vsim/core/Progress.h"
#include "vsim/dicom/PhantomModel.h"

#include <Eigen/Core>

#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace vsim::dicom {

/// One truncated cone of a tube solid, with the HU at both ends (contrast falls along an artery).
struct TubePiece
{
    Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero(); ///< axis ends, mm
    double ra = 1.0, rb = 1.0;                                               ///< radii, mm
    double huA = 0.0, huB = 0.0;
};

/// A region of space: inside where signedDistanceBound() < 0.
struct Solid
{
    enum class Type
    {
        Ellipsoid,        ///< centre, semiAxes in the rotated frame
        EllipticCylinder, ///< axis along patient z between zMin and zMax, centre and semiAxes x, y
        Tubes,            ///< union of cone pieces
    };
    Type type = Type::Ellipsoid;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    Eigen::Vector3d semiAxes{1.0, 1.0, 1.0};
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity(); ///< columns: the solid's axes in the patient frame
    double zMin = -std::numeric_limits<double>::infinity(), zMax = std::numeric_limits<double>::infinity();
    std::vector<TubePiece> pieces;
};

/// One painted layer: a solid with its HU (tubes carry their own) and its truth label.
struct AnatomyLayer
{
    std::string name;
    Solid solid;
    double hu = 0.0;
    std::uint8_t label = label::kBackground;
    bool blooms = false; ///< calcium: its excess over the tissue beneath spreads by the wider blooming PSF
};

/// The scanner of one phantom, drawn from the seed within clinical ranges (or given).
struct ScannerSettings
{
    double psfFwhmMm = 0.8;         ///< in-plane PSF, FWHM mm (0.6..1.0)
    double sliceThicknessMm = 1.0;  ///< slice sensitivity profile, FWHM mm (1.0..1.5 x slice spacing)
    double noiseHu = 20.0;          ///< standard deviation of the noise, HU (10..30)
    double bloodHu = 350.0;         ///< aortic lumen, HU (280..420); falls along the arteries
    double bloomFactor = 2.5;       ///< blooming PSF width / PSF width
};

struct AnatomyPhantom
{
    PhantomKind kind = PhantomKind::Aaa;
    std::vector<AnatomyLayer> layers;        ///< painted in order
    PhantomModel arteries;                   ///< lumen centerlines, radii, topology and names (truth.json)
    std::map<std::string, double> measures;  ///< truth by the clinical definitions, units in the keys
    std::map<std::string, std::string> definitions; ///< how each measure is defined
    ScannerSettings scanner;
};

/// The labels of the patient-like truth-label.nrrd beyond the analytic ones (1 lumen, 2 tumour, 3 bone).
namespace label {
inline constexpr std::uint8_t kThrombus = 4;
inline constexpr std::uint8_t kWall = 5;
inline constexpr std::uint8_t kCalcium = 6;
inline constexpr std::uint8_t kVein = 7;       ///< systemic veins: IVC, renal, hepatic veins
inline constexpr std::uint8_t kPortalVein = 8;
inline constexpr std::uint8_t kLiver = 9;
inline constexpr std::uint8_t kKidney = 10;
inline constexpr std::uint8_t kSpleen = 11;
inline constexpr std::uint8_t kBowel = 12;
inline constexpr std::uint8_t kHeart = 13;
/// "lumen", "thrombus", ...; "" for an unknown value.
std::string labelName(std::uint8_t value);
} // namespace label

/// The scanner drawn from options.seed (blur, thickness, noise, contrast within clinical ranges); options that
/// were given (blurMm >= 0: a Gaussian sigma, noiseHu >= 0 when noiseGiven) override the draw.
ScannerSettings drawScanner(const PhantomOptions& options);

/// Builds the patient-like anatomy of a kind (aaa, hepatic-tree, stenosis; bifurcation is analytic only).
/// Throws vsim::Error for invalid options or a kind without a patient-like model.
AnatomyPhantom buildAnatomyPhantom(PhantomKind kind, const PhantomOptions& options);

/// The CT of the anatomy on `geometry` (axial grid): sub-voxel painting, PSF, blooming, correlated noise,
/// rounded and clamped to -1024..3071 HU. Identical on any thread count. Throws vsim::Cancelled.
CtVolume renderAnatomyCt(const AnatomyPhantom& phantom, const VolumeGeometry& geometry, std::uint64_t seed,
                         const Progress& progress = {});

/// The truth labels at voxel centres, in painting order (the last layer containing the centre wins).
LabelVolume renderAnatomyLabels(const AnatomyPhantom& phantom, const VolumeGeometry& geometry,
                                const Progress& progress = {});

/// truth.json of a patient-like phantom: the artery centerlines and radii, the layers, the labels, the scanner,
/// the measures with their definitions.
std::string anatomyTruthJson(const AnatomyPhantom& phantom, const PhantomOptions& options);

} // namespace vsim::dicom
