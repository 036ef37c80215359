#pragma once

// Analytic CT angiography phantoms: the demo data and the ground truth of every later test. A phantom is a
// set of tissue shapes painted in order, then a vessel network of tapered tubes (piecewise-conical along
// sampled centerlines). All positions are millimetres in the DICOM patient frame (LPS).

#include "vsim/core/VolumeGeometry.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vsim::dicom {

enum class PhantomKind
{
    Aaa,         ///< abdominal aorta with a fusiform aneurysm, renal branches, iliac bifurcation, spine
    Stenosis,    ///< straight artery with a smooth stenosis
    HepaticTree, ///< tapering hepatic artery tree (5 generations, 31 segments) in a liver, with a tumour blush
    Bifurcation, ///< one Y bifurcation
};

/// "aaa", "stenosis", "hepatic-tree", "bifurcation".
std::string phantomKindName(PhantomKind kind);
/// Throws vsim::Error for an unknown name (the message lists the known ones).
PhantomKind phantomKindFromName(const std::string& name);

/// Tissue HU values of the phantoms (contrast-enhanced arterial phase).
namespace hu {
inline constexpr double kAir = -1000.0;
inline constexpr double kFat = -100.0;
inline constexpr double kSoftTissue = 40.0;
inline constexpr double kLiver = 60.0;
inline constexpr double kKidney = 150.0;
inline constexpr double kTumourBlush = 140.0;
inline constexpr double kBone = 750.0;
inline constexpr double kContrastBlood = 380.0;
/// The range a 12-bit CT stores (stored value = HU + 1024).
inline constexpr double kMinimum = -1024.0;
inline constexpr double kMaximum = 3071.0;
} // namespace hu

/// Labels of truth-label.nrrd.
namespace label {
inline constexpr std::uint8_t kBackground = 0;
inline constexpr std::uint8_t kVesselLumen = 1;
inline constexpr std::uint8_t kTumour = 2;
inline constexpr std::uint8_t kBone = 3;
} // namespace label

/// How a phantom's CT is made: Analytic (the exact partial-volume model Phi(-d/sigma), uniform tissues: for tests
/// that need an exact case) or Patient (AnatomyPhantom.h: anatomy and a scanner model no estimator assumes).
enum class PhantomStyle
{
    Analytic,
    Patient,
};
/// "analytic", "patient"; the parser throws vsim::Error naming the known styles.
std::string phantomStyleName(PhantomStyle style);
PhantomStyle phantomStyleFromName(const std::string& name);

struct PhantomOptions
{
    PhantomStyle style = PhantomStyle::Analytic;
    std::array<int, 3> size{512, 512, 400};      ///< columns, rows, slices
    Eigen::Vector3d spacing{0.7, 0.7, 1.0};      ///< mm: column spacing, row spacing, slice spacing
    double noiseHu = 20.0;                       ///< standard deviation of the Gaussian noise, HU
    std::uint64_t seed = 1;
    double blurMm = -1.0;                        ///< partial-volume blur sigma; < 0: half the in-plane spacing
    double aneurysmDiameterMm = 55.0;            ///< aaa: maximum outer lumen diameter of the aneurysm
    double stenosisPercent = 50.0;               ///< stenosis: diameter reduction, percent
    /// Patient-style stenosis only (the thesis's hand and heart cases): the reference lumen diameter (mm), the
    /// stenosis's length (mm; 0: drawn from the seed, 20-28 mm) and a second, milder blockage downstream of the
    /// first (percent, 0: none; the thesis's blockage B).
    double vesselDiameterMm = 6.0;
    double stenosisLengthMm = 0.0;
    double secondStenosisPercent = 0.0;
    std::optional<double> psfFwhmMm;             ///< patient style: in-plane PSF FWHM (mm); drawn from the seed if unset
    std::optional<double> scannerNoiseHu;        ///< patient style: noise (HU); drawn from the seed if unset
    /// Throws vsim::Error naming the option when a value is out of range.
    void validate() const;
    double effectiveBlurMm() const { return blurMm >= 0.0 ? blurMm : 0.25 * (spacing.x() + spacing.y()); }
};

/// A shape painted with one HU value (tissues, bone, tumour). Painted in list order; later shapes cover earlier.
struct TissueShape
{
    enum class Type
    {
        EllipticCylinder, ///< axis along patient z, unbounded
        Ellipsoid,
    };
    std::string name;
    Type type = Type::Ellipsoid;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero(); ///< mm
    Eigen::Vector3d semiAxes{1.0, 1.0, 1.0};         ///< mm (z unused for cylinders)
    double hu = 0.0;
    std::uint8_t label = label::kBackground;         ///< truth label where the shape is, 0 for none
};

struct VesselNode
{
    Eigen::Vector3d position = Eigen::Vector3d::Zero(); ///< mm
};

/// One vessel segment between two nodes: a centerline sampled about every millimetre with the lumen radius at
/// each sample; between samples the lumen is a truncated cone (exact perpendicular cross-section radius).
struct VesselSegment
{
    int from = -1;                        ///< node index (proximal)
    int to = -1;                          ///< node index (distal)
    int parent = -1;                      ///< segment index of the parent, -1 for a root
    int generation = 0;                   ///< 0 for a root
    std::vector<Eigen::Vector3d> points;  ///< mm, from node `from` to node `to`
    std::vector<double> radii;            ///< mm, one per point
    std::string name;                     ///< anatomical name ("aorta", "right renal artery", ...) or empty
    double lengthMm() const;
};

struct PhantomModel
{
    PhantomKind kind = PhantomKind::Aaa;
    std::vector<TissueShape> tissues;
    std::vector<VesselNode> nodes;
    std::vector<VesselSegment> segments;
    double bloodHu = hu::kContrastBlood;
    /// Kind-specific truth figures with units in their keys: max_diameter_mm, stenosis_percent, ...
    std::map<std::string, double> measures;
};

/// The axial grid of a phantom: LPS axes, centred on kPhantomCentre.
VolumeGeometry phantomGeometry(const PhantomOptions& options);
/// Where phantoms are centred in the patient frame (mm), away from 0 so that origin errors show.
inline const Eigen::Vector3d kPhantomCentre{0.0, 0.0, -300.0};

/// Builds the model of a kind; throws vsim::Error for invalid options.
PhantomModel buildPhantomModel(PhantomKind kind, const PhantomOptions& options);

/// truth.json: centerlines (mm), radii, segment lengths, topology, kind-specific measures, labels, options.
std::string phantomTruthJson(const PhantomModel& model, const PhantomOptions& options);

} // namespace vsim::dicom
