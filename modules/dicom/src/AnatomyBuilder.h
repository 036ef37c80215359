#pragma once

// Building blocks of the patient-like anatomies: layers from simple solids, sampled curves, and the arterial
// tree (lumen, wall, thrombus layers plus the truth centerlines), shared by the aaa, hepatic and stenosis builds.

#include "vsim/dicom/AnatomyPhantom.h"

#include <functional>
#include <random>
#include <string>
#include <vector>

namespace vsim::dicom::detail {

using Eigen::Vector3d;

/// A position given as an offset (mm) from kPhantomCentre, where every phantom is centred.
inline Vector3d at(const Vector3d& offset)
{
    return kPhantomCentre + offset;
}

/// The anatomy's own random stream: the phantom's seed mixed with a per-kind salt (independent of the scanner's).
inline std::mt19937_64 anatomyRandom(std::uint64_t seed, std::uint64_t salt)
{
    return std::mt19937_64(seed * 0x9E3779B97F4A7C15ull + salt);
}

/// A curve sampled about every millimetre: positions (mm) and arc length from its start (mm).
struct SampledCurve
{
    std::vector<Vector3d> points;
    std::vector<double> arc;
    double length() const { return arc.empty() ? 0.0 : arc.back(); }
};

/// Samples curve(t), t in [0, 1], about every `stepMm`.
SampledCurve sampleCurve(const std::function<Vector3d(double)>& curve, double stepMm = 1.0);
/// Quadratic Bezier from `from` to `to` pulled towards `control`.
std::function<Vector3d(double)> bezier(const Vector3d& from, const Vector3d& control, const Vector3d& to);

AnatomyLayer ellipsoid(const std::string& name, const Vector3d& centre, const Vector3d& semiAxes, double hu,
                       std::uint8_t label, const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity());
/// An elliptic cylinder along patient z between zMin and zMax.
AnatomyLayer cylinder(const std::string& name, const Vector3d& centre, double semiX, double semiY, double hu,
                      std::uint8_t label, double zMin = -1e9, double zMax = 1e9);
/// A tube along `curve` with radius(s) and HU(s) of the arc length s (mm).
AnatomyLayer tube(const std::string& name, const SampledCurve& curve, const std::function<double(double)>& radius,
                  const std::function<double(double)>& hu, std::uint8_t label);

/// Rotation about patient z by `degrees`, then about x by `tiltDegrees`.
Eigen::Matrix3d rotationZx(double degrees, double tiltDegrees);

/// The arterial tree: every artery is a lumen tube inside a wall of given thickness; the truth centerlines go to
/// `arteries` (PhantomModel segments with names). Layers come out as wall, thrombus, lumen (that order), so that
/// a branch's wall never covers another artery's lumen.
class ArterialTree
{
public:
    explicit ArterialTree(double bloodHu) : m_bloodHu(bloodHu) {}

    /// Adds an artery from node `fromNode` (-1: a new node at the curve's start) along `curve`, lumen radius(s),
    /// wall thickness (mm), blood HU falling from `huFraction0` to `huFraction1` of the blood HU. Returns the
    /// segment index; its end node is segmentEndNode(index).
    int addArtery(const std::string& name, int fromNode, const SampledCurve& curve,
                  const std::function<double(double)>& lumenRadius, double wallMm, double huFraction0,
                  double huFraction1, int parent);
    /// An outer contour and the thrombus beneath it, for a segment whose wall is not the lumen plus a constant
    /// (the aneurysm): the outer tube (wall layer) and the tube inside the wall (thrombus layer).
    void addOuterContour(const SampledCurve& outerCurve, const std::function<double(double)>& outerRadius,
                         double wallMm);
    int segmentEndNode(int segment) const { return m_model.segments[std::size_t(segment)].to; }
    const PhantomModel& model() const { return m_model; }
    /// Blood HU at a fraction of the aortic value.
    double bloodHu(double fraction) const { return m_bloodHu * fraction; }

    /// Appends the wall, thrombus and lumen layers to `layers`.
    void emitLayers(std::vector<AnatomyLayer>& layers) const;

private:
    double m_bloodHu;
    PhantomModel m_model;
    std::vector<TubePiece> m_wall, m_thrombus, m_lumen;
};

/// HU of the walls and thrombus: about the same on CT (the outer contour against fat is what is visible).
inline constexpr double kWallHu = 50.0;
inline constexpr double kThrombusHu = 40.0;

/// The torso shared by the abdominal phantoms: body wall, fat, spine (vertebral bodies touching the aorta's
/// posterior wall at x = kAortaX), psoas, kidneys with cortex, liver, spleen, bowel with gas, IVC and iliac veins.
/// `liverCentre` and `liverSemiAxes` place the liver (offsets from kPhantomCentre).
void addAbdominalTorso(AnatomyPhantom& phantom, std::mt19937_64& random, const Vector3d& liverCentre,
                       const Vector3d& liverSemiAxes);

/// Where the abdominal aorta runs (offsets from kPhantomCentre, mm): left of the midline, its posterior outer wall
/// on the vertebral bodies' anterior surface for an outer radius kAortaOuterRadius.
inline constexpr double kAortaX = 12.0;
inline constexpr double kAortaOuterRadius = 11.8;
/// y of the aortic centre for outer radius kAortaOuterRadius (touches the vertebral body, 0.3 mm gap).
double aortaCentreY();

/// The right renal vein and the left one crossing in front of the aorta into the IVC, touching it.
void addRenalVeins(AnatomyPhantom& phantom, double aortaAnteriorY);

} // namespace vsim::dicom::detail
