#include "vsim/dicom/PhantomModel.h"

#include "vsim/core/Error.h"

#include <Eigen/Geometry>

#include <cmath>
#include <functional>
#include <numbers>

namespace vsim::dicom {
namespace {

using Eigen::Vector3d;
using Curve = std::function<Vector3d(double t)>;  // t in [0, 1], mm
using Profile = std::function<double(double t)>;  // radius in mm along t

constexpr double kSampleStepMm = 1.0; // centerline sampling of the truth polylines

Curve straight(const Vector3d& from, const Vector3d& to)
{
    return [=](double t) { return Vector3d(from + t * (to - from)); };
}

/// Quadratic Bezier curve from `from` to `to` pulled towards `control`.
Curve bent(const Vector3d& from, const Vector3d& control, const Vector3d& to)
{
    return [=](double t) { return Vector3d((1 - t) * (1 - t) * from + 2 * (1 - t) * t * control + t * t * to); };
}

Profile linearRadius(double start, double end)
{
    return [=](double t) { return start + t * (end - start); };
}

/// Raised-cosine bump: 1 at `centre`, 0 beyond `halfLength` (all in the curve's parameter units).
double cosineBump(double x, double centre, double halfLength)
{
    const double u = (x - centre) / halfLength;
    return std::abs(u) >= 1.0 ? 0.0 : 0.5 * (1.0 + std::cos(std::numbers::pi * u));
}

int addNode(PhantomModel& model, const Vector3d& position)
{
    model.nodes.push_back({position});
    return static_cast<int>(model.nodes.size()) - 1;
}

/// Samples a curve about every kSampleStepMm between two existing nodes; returns the segment index.
int addSegment(PhantomModel& model, int from, int to, const Curve& curve, const Profile& radius, int parent,
               int generation)
{
    // Estimate the length on a fine polyline, then sample uniformly in t.
    double length = 0.0;
    constexpr int kFine = 200;
    for (int s = 1; s <= kFine; ++s)
        length += (curve(double(s) / kFine) - curve(double(s - 1) / kFine)).norm();
    const int samples = std::max(2, static_cast<int>(std::ceil(length / kSampleStepMm)) + 1);
    VesselSegment segment;
    segment.from = from;
    segment.to = to;
    segment.parent = parent;
    segment.generation = generation;
    for (int s = 0; s < samples; ++s)
    {
        const double t = double(s) / (samples - 1);
        segment.points.push_back(curve(t));
        segment.radii.push_back(radius(t));
    }
    segment.points.front() = model.nodes[from].position;
    segment.points.back() = model.nodes[to].position;
    model.segments.push_back(std::move(segment));
    return static_cast<int>(model.segments.size()) - 1;
}

/// Soft tissue inside a fat layer: the body outline of every phantom.
void addBody(PhantomModel& model, const Vector3d& centre, double semiX, double semiY)
{
    model.tissues.push_back({"subcutaneous fat", TissueShape::Type::EllipticCylinder, centre,
                             Vector3d(semiX, semiY, 0), hu::kFat, label::kBackground});
    model.tissues.push_back({"soft tissue", TissueShape::Type::EllipticCylinder, centre,
                             Vector3d(semiX - 15, semiY - 15, 0), hu::kSoftTissue, label::kBackground});
}

double halfHeight(const PhantomOptions& options)
{
    return 0.5 * options.size[2] * options.spacing.z();
}

// --- kinds ---------------------------------------------------------------------------------------------------

PhantomModel buildAaa(const PhantomOptions& options)
{
    PhantomModel model;
    const Vector3d c = kPhantomCentre;
    addBody(model, c + Vector3d(0, 10, 0), 165, 120);
    model.tissues.push_back({"vertebral bodies", TissueShape::Type::EllipticCylinder, c + Vector3d(0, 45, 0),
                             Vector3d(22, 18, 0), hu::kBone, label::kBone});
    for (double side : {-1.0, 1.0})
        model.tissues.push_back({side < 0 ? "right kidney" : "left kidney", TissueShape::Type::Ellipsoid,
                                 c + Vector3d(side * 85, 30, 110), Vector3d(25, 30, 55), hu::kKidney,
                                 label::kBackground});

    // Aorta along -z (superior to inferior), 20 mm lumen, fusiform aneurysm centred 20 mm above the centre.
    const double top = std::max(halfHeight(options), 200.0) + 10.0;
    const double aortaRadius = 10.0;
    const double aneurysmRadius = 0.5 * options.aneurysmDiameterMm;
    const double aneurysmCentreZ = 20.0, aneurysmHalfLength = 45.0;
    const int superior = addNode(model, c + Vector3d(0, -5, top));
    const int renal = addNode(model, c + Vector3d(0, -5, 120));
    const int bifurcation = addNode(model, c + Vector3d(0, -5, -60));
    auto aortaRadiusAt = [=](double z) {
        return aortaRadius + (aneurysmRadius - aortaRadius) * cosineBump(z, aneurysmCentreZ, aneurysmHalfLength);
    };
    const int suprarenal = addSegment(model, superior, renal, straight(model.nodes[superior].position,
                                                                        model.nodes[renal].position),
                                      linearRadius(aortaRadius, aortaRadius), -1, 0);
    const Vector3d renalPoint = model.nodes[renal].position, bifurcationPoint = model.nodes[bifurcation].position;
    const int infrarenal = addSegment(
        model, renal, bifurcation, straight(renalPoint, bifurcationPoint),
        [=](double t) { return aortaRadiusAt(120.0 + t * (-60.0 - 120.0)); }, suprarenal, 1);
    for (double side : {-1.0, 1.0})
    {
        const int hilum = addNode(model, c + Vector3d(side * 62, 15, 112));
        addSegment(model, renal, hilum,
                   bent(renalPoint, c + Vector3d(side * 30, -2, 118), model.nodes[hilum].position),
                   linearRadius(3.0, 2.6), suprarenal, 1);
    }
    for (double side : {-1.0, 1.0})
    {
        const int distal = addNode(model, c + Vector3d(side * 55, 5, -top));
        addSegment(model, bifurcation, distal,
                   bent(bifurcationPoint, c + Vector3d(side * 15, -5, -110), model.nodes[distal].position),
                   linearRadius(6.0, 5.0), infrarenal, 2);
    }
    model.measures["max_diameter_mm"] = 2.0 * aneurysmRadius;
    model.measures["aortic_neck_diameter_mm"] = 2.0 * aortaRadius;
    model.measures["aneurysm_centre_z_mm"] = c.z() + aneurysmCentreZ;
    model.measures["aneurysm_length_mm"] = 2.0 * aneurysmHalfLength;
    return model;
}

PhantomModel buildStenosis(const PhantomOptions& options)
{
    PhantomModel model;
    const Vector3d c = kPhantomCentre;
    addBody(model, c, 80, 80);
    const double radius = 3.0, halfLength = 10.0, reach = halfHeight(options) + 20.0;
    const Vector3d axis = Vector3d(0.15, 0.10, 1.0).normalized(); // slightly oblique, as in a real leg artery
    const int proximal = addNode(model, c + reach * axis);
    const int distal = addNode(model, c - reach * axis);
    const double fraction = options.stenosisPercent / 100.0;
    addSegment(
        model, proximal, distal, straight(model.nodes[proximal].position, model.nodes[distal].position),
        [=](double t) { return radius * (1.0 - fraction * cosineBump((t - 0.5) * 2.0 * reach, 0.0, halfLength)); },
        -1, 0);
    model.measures["stenosis_percent"] = options.stenosisPercent;
    model.measures["reference_diameter_mm"] = 2.0 * radius;
    model.measures["minimal_diameter_mm"] = 2.0 * radius * (1.0 - fraction);
    model.measures["stenosis_length_mm"] = 2.0 * halfLength;
    model.measures["stenosis_centre_x_mm"] = c.x();
    model.measures["stenosis_centre_y_mm"] = c.y();
    model.measures["stenosis_centre_z_mm"] = c.z();
    return model;
}

PhantomModel buildBifurcation(const PhantomOptions& options)
{
    PhantomModel model;
    const Vector3d c = kPhantomCentre;
    addBody(model, c, 90, 90);
    const double reach = halfHeight(options) + 20.0;
    const double parentRadius = 4.0, daughterRadius = parentRadius * std::pow(2.0, -1.0 / 3.0); // Murray's law
    const int top = addNode(model, c + Vector3d(0, 0, reach));
    const int junction = addNode(model, c + Vector3d(0, 0, 20));
    const int parent = addSegment(model, top, junction, straight(model.nodes[top].position, c + Vector3d(0, 0, 20)),
                                  linearRadius(parentRadius, parentRadius), -1, 0);
    const double halfAngle = 30.0 * std::numbers::pi / 180.0;
    for (double side : {-1.0, 1.0})
    {
        const Vector3d direction(side * std::sin(halfAngle), 0, -std::cos(halfAngle));
        const double length = (reach + 20.0) / std::cos(halfAngle);
        const int end = addNode(model, model.nodes[junction].position + length * direction);
        addSegment(model, junction, end, straight(model.nodes[junction].position, model.nodes[end].position),
                   linearRadius(daughterRadius, daughterRadius), parent, 1);
    }
    model.measures["parent_diameter_mm"] = 2.0 * parentRadius;
    model.measures["daughter_diameter_mm"] = 2.0 * daughterRadius;
    model.measures["branch_angle_deg"] = 60.0;
    return model;
}

/// Binary hepatic artery tree: 5 generations (31 segments), each segment a cone tapering by 10 %, daughters
/// starting at the parent's end radius times 2^(-1/3) (Murray's law), the branching plane turned 90 degrees
/// each generation. Radii run from 3.0 mm at the root to 0.70 mm at the tips.
PhantomModel buildHepaticTree(const PhantomOptions& /*options*/)
{
    PhantomModel model;
    const Vector3d c = kPhantomCentre;
    addBody(model, c + Vector3d(0, 10, 0), 165, 120);
    model.tissues.push_back({"liver", TissueShape::Type::Ellipsoid, c + Vector3d(-60, 0, 10), Vector3d(95, 85, 80),
                             hu::kLiver, label::kBackground});
    constexpr int kGenerations = 5;
    constexpr double kRootRadius = 3.0, kTaper = 0.9, kRootLength = 38.0, kLengthRatio = 0.75;
    const double murray = std::pow(2.0, -1.0 / 3.0);
    const double branchAngle = 35.0 * std::numbers::pi / 180.0;

    struct Pending
    {
        int node;
        Vector3d direction;
        Vector3d planeNormal;
        double radius;
        int parent;
        int generation;
    };
    const Vector3d rootDirection = Vector3d(-1.0, 0.1, 0.25).normalized();
    std::vector<Pending> stack{{addNode(model, c + Vector3d(20, -25, -5)), rootDirection,
                                rootDirection.cross(Vector3d::UnitY()).normalized(), kRootRadius, -1, 0}};
    int deepestTip = -1;
    Vector3d deepestDirection = rootDirection;
    while (!stack.empty())
    {
        const Pending item = stack.back();
        stack.pop_back();
        const double length = kRootLength * std::pow(kLengthRatio, item.generation);
        const Vector3d start = model.nodes[item.node].position;
        const int end = addNode(model, start + length * item.direction);
        const int segment = addSegment(model, item.node, end, straight(start, model.nodes[end].position),
                                       linearRadius(item.radius, item.radius * kTaper), item.parent,
                                       item.generation);
        if (item.generation + 1 == kGenerations)
        {
            if (deepestTip < 0)
            {
                deepestTip = end;
                deepestDirection = item.direction;
            }
            continue;
        }
        const Vector3d nextPlane = item.direction.cross(item.planeNormal).normalized(); // turn the plane 90 deg
        for (double side : {1.0, -1.0}) // pushed so that the first child (+) is expanded first
        {
            const Vector3d direction =
                Eigen::AngleAxisd(side * branchAngle, item.planeNormal) * item.direction;
            stack.push_back({end, direction.normalized(), nextPlane, item.radius * kTaper * murray, segment,
                             item.generation + 1});
        }
    }
    const Vector3d tumourCentre = model.nodes[deepestTip].position + 8.0 * deepestDirection;
    const double tumourRadius = 15.0;
    model.tissues.push_back({"tumour blush", TissueShape::Type::Ellipsoid, tumourCentre,
                             Vector3d(tumourRadius, tumourRadius, tumourRadius), hu::kTumourBlush,
                             label::kTumour});
    model.measures["root_radius_mm"] = kRootRadius;
    model.measures["tip_radius_mm"] = kRootRadius * std::pow(kTaper * murray, kGenerations - 1) * kTaper;
    model.measures["generations"] = kGenerations;
    model.measures["tumour_radius_mm"] = tumourRadius;
    model.measures["tumour_centre_x_mm"] = tumourCentre.x();
    model.measures["tumour_centre_y_mm"] = tumourCentre.y();
    model.measures["tumour_centre_z_mm"] = tumourCentre.z();
    return model;
}

} // namespace

std::string phantomKindName(PhantomKind kind)
{
    switch (kind)
    {
    case PhantomKind::Aaa: return "aaa";
    case PhantomKind::Stenosis: return "stenosis";
    case PhantomKind::HepaticTree: return "hepatic-tree";
    case PhantomKind::Bifurcation: return "bifurcation";
    }
    return {};
}

PhantomKind phantomKindFromName(const std::string& name)
{
    for (PhantomKind kind :
         {PhantomKind::Aaa, PhantomKind::Stenosis, PhantomKind::HepaticTree, PhantomKind::Bifurcation})
        if (phantomKindName(kind) == name)
            return kind;
    throw Error(Pattern{"unknown phantom kind '%1'; known kinds: aaa, stenosis, hepatic-tree, bifurcation", {name}});
}

std::string phantomStyleName(PhantomStyle style)
{
    return style == PhantomStyle::Patient ? "patient" : "analytic";
}

PhantomStyle phantomStyleFromName(const std::string& name)
{
    for (PhantomStyle style : {PhantomStyle::Patient, PhantomStyle::Analytic})
        if (phantomStyleName(style) == name)
            return style;
    throw Error(Pattern{"unknown phantom style '%1'; known styles: patient, analytic", {name}});
}

double VesselSegment::lengthMm() const
{
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i)
        length += (points[i] - points[i - 1]).norm();
    return length;
}

void PhantomOptions::validate() const
{
    for (int axis = 0; axis < 3; ++axis)
        if (size[axis] < 8 || size[axis] > 4096)
            throw Error("phantom size must be 8..4096 voxels per axis",
                        {{"option", "size"}, {"axis", std::to_string(axis)}, {"value", std::to_string(size[axis])}});
    for (int axis = 0; axis < 3; ++axis)
        if (!(spacing[axis] >= 0.05 && spacing[axis] <= 20.0))
            throw Error("phantom spacing must be 0.05..20 mm",
                        {{"option", "spacing"}, {"value", std::to_string(spacing[axis])}});
    if (!(noiseHu >= 0.0 && noiseHu <= 500.0))
        throw Error("phantom noise must be 0..500 HU", {{"option", "noise"}, {"value", std::to_string(noiseHu)}});
    if (!(blurMm <= 10.0))
        throw Error("phantom blur must be at most 10 mm", {{"option", "blur"}, {"value", std::to_string(blurMm)}});
    if (!(aneurysmDiameterMm >= 20.0 && aneurysmDiameterMm <= 120.0))
        throw Error("aneurysm diameter must be 20..120 mm",
                    {{"option", "max-diameter"}, {"value", std::to_string(aneurysmDiameterMm)}});
    if (psfFwhmMm && !(*psfFwhmMm >= 0.1 && *psfFwhmMm <= 5.0))
        throw Error("phantom PSF FWHM must be 0.1..5 mm", {{"option", "psf-fwhm"}, {"value", std::to_string(*psfFwhmMm)}});
    if (scannerNoiseHu && !(*scannerNoiseHu >= 0.0 && *scannerNoiseHu <= 500.0))
        throw Error("phantom noise must be 0..500 HU", {{"option", "noise"}, {"value", std::to_string(*scannerNoiseHu)}});
    if (!(stenosisPercent >= 0.0 && stenosisPercent <= 95.0))
        throw Error("stenosis must be 0..95 percent",
                    {{"option", "stenosis"}, {"value", std::to_string(stenosisPercent)}});
    if (!(secondStenosisPercent >= 0.0 && secondStenosisPercent <= 95.0))
        throw Error("the second stenosis must be 0..95 percent",
                    {{"option", "stenosis"}, {"value", std::to_string(secondStenosisPercent)}});
    if (!(vesselDiameterMm >= 1.0 && vesselDiameterMm <= 40.0))
        throw Error("the vessel diameter must be 1..40 mm",
                    {{"option", "vessel-diameter"}, {"value", std::to_string(vesselDiameterMm)}});
    if (!(stenosisLengthMm == 0.0 || (stenosisLengthMm >= 2.0 && stenosisLengthMm <= 100.0)))
        throw Error("the stenosis length must be 2..100 mm (0: drawn from the seed)",
                    {{"option", "stenosis-length"}, {"value", std::to_string(stenosisLengthMm)}});
}

VolumeGeometry phantomGeometry(const PhantomOptions& options)
{
    VolumeGeometry geometry;
    geometry.dims = options.size;
    geometry.spacing = options.spacing;
    const Vector3d extent(options.size[0] - 1, options.size[1] - 1, options.size[2] - 1);
    geometry.origin = kPhantomCentre - 0.5 * extent.cwiseProduct(options.spacing);
    geometry.direction.setIdentity();
    return geometry;
}

PhantomModel buildPhantomModel(PhantomKind kind, const PhantomOptions& options)
{
    options.validate();
    PhantomModel model;
    switch (kind)
    {
    case PhantomKind::Aaa: model = buildAaa(options); break;
    case PhantomKind::Stenosis: model = buildStenosis(options); break;
    case PhantomKind::HepaticTree: model = buildHepaticTree(options); break;
    case PhantomKind::Bifurcation: model = buildBifurcation(options); break;
    }
    model.kind = kind;
    return model;
}

} // namespace vsim::dicom
