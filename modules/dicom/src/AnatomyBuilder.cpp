#include "AnatomyBuilder.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vsim::dicom::detail {

SampledCurve sampleCurve(const std::function<Vector3d(double)>& curve, double stepMm)
{
    double length = 0.0;
    constexpr int kFine = 400;
    for (int s = 1; s <= kFine; ++s)
        length += (curve(double(s) / kFine) - curve(double(s - 1) / kFine)).norm();
    const int samples = std::max(2, int(std::ceil(length / stepMm)) + 1);
    SampledCurve sampled;
    for (int s = 0; s < samples; ++s)
    {
        sampled.points.push_back(curve(double(s) / (samples - 1)));
        sampled.arc.push_back(s == 0 ? 0.0 : sampled.arc.back() + (sampled.points[std::size_t(s)] -
                                                                  sampled.points[std::size_t(s) - 1]).norm());
    }
    return sampled;
}

std::function<Vector3d(double)> bezier(const Vector3d& from, const Vector3d& control, const Vector3d& to)
{
    return [=](double t) { return Vector3d((1 - t) * (1 - t) * from + 2 * (1 - t) * t * control + t * t * to); };
}

AnatomyLayer ellipsoid(const std::string& name, const Vector3d& centre, const Vector3d& semiAxes, double hu,
                       std::uint8_t label, const Eigen::Matrix3d& rotation)
{
    AnatomyLayer layer{name, {}, hu, label, false};
    layer.solid.type = Solid::Type::Ellipsoid;
    layer.solid.centre = centre;
    layer.solid.semiAxes = semiAxes;
    layer.solid.rotation = rotation;
    return layer;
}

AnatomyLayer cylinder(const std::string& name, const Vector3d& centre, double semiX, double semiY, double hu,
                      std::uint8_t label, double zMin, double zMax)
{
    AnatomyLayer layer{name, {}, hu, label, false};
    layer.solid.type = Solid::Type::EllipticCylinder;
    layer.solid.centre = centre;
    layer.solid.semiAxes = Vector3d(semiX, semiY, 1.0);
    layer.solid.zMin = zMin;
    layer.solid.zMax = zMax;
    return layer;
}

namespace {

void appendPieces(std::vector<TubePiece>& pieces, const SampledCurve& curve,
                  const std::function<double(double)>& radius, const std::function<double(double)>& hu)
{
    for (std::size_t s = 1; s < curve.points.size(); ++s)
        pieces.push_back({curve.points[s - 1], curve.points[s], radius(curve.arc[s - 1]), radius(curve.arc[s]),
                          hu(curve.arc[s - 1]), hu(curve.arc[s])});
}

AnatomyLayer tubeLayer(const std::string& name, std::vector<TubePiece> pieces, std::uint8_t label)
{
    AnatomyLayer layer{name, {}, 0.0, label, false};
    layer.solid.type = Solid::Type::Tubes;
    layer.solid.pieces = std::move(pieces);
    return layer;
}

} // namespace

AnatomyLayer tube(const std::string& name, const SampledCurve& curve, const std::function<double(double)>& radius,
                  const std::function<double(double)>& hu, std::uint8_t label)
{
    std::vector<TubePiece> pieces;
    appendPieces(pieces, curve, radius, hu);
    return tubeLayer(name, std::move(pieces), label);
}

Eigen::Matrix3d rotationZx(double degrees, double tiltDegrees)
{
    const double toRadians = std::numbers::pi / 180.0;
    return (Eigen::AngleAxisd(degrees * toRadians, Vector3d::UnitZ()) *
            Eigen::AngleAxisd(tiltDegrees * toRadians, Vector3d::UnitX()))
        .toRotationMatrix();
}

int ArterialTree::addArtery(const std::string& name, int fromNode, const SampledCurve& curve,
                            const std::function<double(double)>& lumenRadius, double wallMm, double huFraction0,
                            double huFraction1, int parent)
{
    if (fromNode < 0)
    {
        m_model.nodes.push_back({curve.points.front()});
        fromNode = int(m_model.nodes.size()) - 1;
    }
    m_model.nodes.push_back({curve.points.back()});
    VesselSegment segment;
    segment.from = fromNode;
    segment.to = int(m_model.nodes.size()) - 1;
    segment.parent = parent;
    segment.generation = parent < 0 ? 0 : m_model.segments[std::size_t(parent)].generation + 1;
    segment.points = curve.points;
    segment.points.front() = m_model.nodes[std::size_t(fromNode)].position;
    for (double s : curve.arc)
        segment.radii.push_back(lumenRadius(s));
    segment.name = name;
    m_model.segments.push_back(segment);

    const double length = std::max(curve.length(), 1e-9);
    const auto hu = [&](double s) { return m_bloodHu * (huFraction0 + (huFraction1 - huFraction0) * s / length); };
    appendPieces(m_lumen, curve, lumenRadius, hu);
    if (wallMm > 0.0)
        appendPieces(m_wall, curve, [&](double s) { return lumenRadius(s) + wallMm; },
                     [](double) { return kWallHu; });
    return int(m_model.segments.size()) - 1;
}

void ArterialTree::addOuterContour(const SampledCurve& outerCurve, const std::function<double(double)>& outerRadius,
                                   double wallMm)
{
    appendPieces(m_wall, outerCurve, outerRadius, [](double) { return kWallHu; });
    appendPieces(m_thrombus, outerCurve, [&](double s) { return outerRadius(s) - wallMm; },
                 [](double) { return kThrombusHu; });
}

void ArterialTree::emitLayers(std::vector<AnatomyLayer>& layers) const
{
    layers.push_back(tubeLayer("arterial wall", m_wall, label::kWall));
    if (!m_thrombus.empty())
        layers.push_back(tubeLayer("intraluminal thrombus", m_thrombus, label::kThrombus));
    layers.push_back(tubeLayer("arterial lumen", m_lumen, label::kVesselLumen));
}

} // namespace vsim::dicom::detail
