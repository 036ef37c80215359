#include "vsim/dicom/PhantomRender.h"

#include "vsim/core/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace vsim::dicom {
namespace {

using Eigen::Vector3d;

constexpr float kFar = std::numeric_limits<float>::infinity();

/// One truncated cone between two centerline samples, with its bounding box grown by the largest radius and
/// the blur reach.
struct ConePiece
{
    Vector3d a, b;
    double ra, rb;
    Vector3d low, high;
};

/// Signed distance (mm) to the lumen surface of a cone piece: distance to the nearest axis point minus the
/// radius there (exact perpendicular cross-sections; ends capped by spheres).
double coneDistance(const ConePiece& piece, const Vector3d& p)
{
    const Vector3d axis = piece.b - piece.a;
    const double t = std::clamp((p - piece.a).dot(axis) / axis.squaredNorm(), 0.0, 1.0);
    return (p - (piece.a + t * axis)).norm() - (piece.ra + t * (piece.rb - piece.ra));
}

/// Approximate signed distance (mm) to a tissue shape: the normalised radius minus one, scaled by the
/// smallest semi-axis (exact for circles and spheres).
double shapeDistance(const TissueShape& shape, const Vector3d& p)
{
    const Vector3d q = (p - shape.centre).cwiseQuotient(shape.semiAxes);
    if (shape.type == TissueShape::Type::EllipticCylinder)
        return (std::sqrt(q.x() * q.x() + q.y() * q.y()) - 1.0) * std::min(shape.semiAxes.x(), shape.semiAxes.y());
    return (q.norm() - 1.0) * shape.semiAxes.minCoeff();
}

/// Fraction of a voxel inside a surface at signed distance d under a Gaussian blur of sigma (mm).
double occupancy(double d, double sigma)
{
    if (sigma <= 0.0)
        return d < 0.0 ? 1.0 : 0.0;
    const double x = d / sigma;
    if (x > 5.0)
        return 0.0;
    if (x < -5.0)
        return 1.0;
    return 0.5 * std::erfc(x * std::numbers::sqrt2 * 0.5);
}

std::uint64_t mixSeed(std::uint64_t seed, std::uint64_t slice)
{
    // splitmix64 of the pair: independent, reproducible streams per slice.
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + slice + 0x632BE59BD9B4E019ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

class SliceEvaluator
{
public:
    SliceEvaluator(const PhantomModel& model, const SliceStack& stack, double reachMm)
        : m_model(model), m_stack(stack), m_normal(stack.normal())
    {
        for (const VesselSegment& segment : model.segments)
            for (std::size_t s = 1; s < segment.points.size(); ++s)
            {
                ConePiece piece{segment.points[s - 1], segment.points[s], segment.radii[s - 1], segment.radii[s], {}, {}};
                const double grow = std::max(piece.ra, piece.rb) + reachMm;
                piece.low = piece.a.cwiseMin(piece.b).array() - grow;
                piece.high = piece.a.cwiseMax(piece.b).array() + grow;
                m_pieces.push_back(piece);
            }
    }

    std::size_t pixelCount() const { return std::size_t(m_stack.columns) * std::size_t(m_stack.rows); }

    /// Minimum signed distance to any vessel for every pixel of a slice; kFar beyond the reach.
    void vesselDistances(std::size_t slice, std::vector<float>& distance) const
    {
        distance.assign(pixelCount(), kFar);
        const Vector3d& origin = m_stack.positions[slice];
        const Vector3d stepX = m_stack.columnSpacing * m_stack.xDirection;
        const Vector3d stepY = m_stack.rowSpacing * m_stack.yDirection;
        for (const ConePiece& piece : m_pieces)
        {
            const Vector3d centre = 0.5 * (piece.low + piece.high);
            const Vector3d half = 0.5 * (piece.high - piece.low);
            if (std::abs((centre - origin).dot(m_normal)) > m_normal.cwiseAbs().dot(half))
                continue;
            double iLow = 1e300, iHigh = -1e300, jLow = 1e300, jHigh = -1e300;
            for (int corner = 0; corner < 8; ++corner)
            {
                const Vector3d p((corner & 1) ? piece.high.x() : piece.low.x(),
                                 (corner & 2) ? piece.high.y() : piece.low.y(),
                                 (corner & 4) ? piece.high.z() : piece.low.z());
                const double i = (p - origin).dot(m_stack.xDirection) / m_stack.columnSpacing;
                const double j = (p - origin).dot(m_stack.yDirection) / m_stack.rowSpacing;
                iLow = std::min(iLow, i), iHigh = std::max(iHigh, i), jLow = std::min(jLow, j), jHigh = std::max(jHigh, j);
            }
            const int i0 = std::max(0, int(std::floor(iLow))), i1 = std::min(m_stack.columns - 1, int(std::ceil(iHigh)));
            const int j0 = std::max(0, int(std::floor(jLow))), j1 = std::min(m_stack.rows - 1, int(std::ceil(jHigh)));
            for (int j = j0; j <= j1; ++j)
            {
                const Vector3d rowStart = origin + double(j) * stepY;
                float* out = distance.data() + std::size_t(j) * m_stack.columns;
                for (int i = i0; i <= i1; ++i)
                    out[i] = std::min(out[i], float(coneDistance(piece, rowStart + double(i) * stepX)));
            }
        }
    }

    /// Calls visit(pixelIndex, position) for every pixel of a slice.
    template <typename Visit>
    void forEachPixel(std::size_t slice, Visit&& visit) const
    {
        const Vector3d& origin = m_stack.positions[slice];
        const Vector3d stepX = m_stack.columnSpacing * m_stack.xDirection;
        const Vector3d stepY = m_stack.rowSpacing * m_stack.yDirection;
        std::size_t index = 0;
        for (int j = 0; j < m_stack.rows; ++j)
        {
            const Vector3d rowStart = origin + double(j) * stepY;
            for (int i = 0; i < m_stack.columns; ++i, ++index)
                visit(index, Vector3d(rowStart + double(i) * stepX));
        }
    }

    const PhantomModel& model() const { return m_model; }

private:
    const PhantomModel& m_model;
    const SliceStack& m_stack;
    Vector3d m_normal;
    std::vector<ConePiece> m_pieces;
};

void reportSlices(const Progress& progress, std::size_t done, std::size_t total, const char* stage)
{
    progress.report(double(done) / double(total), stage);
}

} // namespace

CtVolume renderPhantomCt(const PhantomModel& model, const SliceStack& stack, const PhantomOptions& options,
                         const Progress& progress)
{
    options.validate();
    const double sigma = options.effectiveBlurMm();
    const double reach = 5.0 * sigma + 0.5 * std::max(stack.columnSpacing, stack.rowSpacing);
    const SliceEvaluator evaluator(model, stack, reach);
    CtVolume volume(stack.nominalGeometry());
    const std::size_t slices = stack.positions.size();
    parallelFor(
        slices,
        [&](std::size_t k) {
            std::vector<float> value(evaluator.pixelCount(), float(hu::kAir));
            for (const TissueShape& shape : model.tissues)
                evaluator.forEachPixel(k, [&](std::size_t index, const Vector3d& p) {
                    const double occupied = occupancy(shapeDistance(shape, p), sigma);
                    if (occupied > 0.0)
                        value[index] += float((shape.hu - value[index]) * occupied);
                });
            std::vector<float> vessel;
            evaluator.vesselDistances(k, vessel);
            std::mt19937_64 random(mixSeed(options.seed, k));
            std::normal_distribution<float> noise(0.0f, float(options.noiseHu));
            std::int16_t* out = volume.data() + k * evaluator.pixelCount();
            for (std::size_t index = 0; index < value.size(); ++index)
            {
                double v = value[index];
                if (vessel[index] != kFar)
                    v += (model.bloodHu - v) * occupancy(vessel[index], sigma);
                if (options.noiseHu > 0.0)
                    v += noise(random);
                out[index] = std::int16_t(std::clamp(std::lround(v), long(hu::kMinimum), long(hu::kMaximum)));
            }
        },
        [&](std::size_t done) { reportSlices(progress, done, slices, "rendering phantom"); });
    return volume;
}

double vesselSurfaceDistance(const PhantomModel& model, const Vector3d& p)
{
    double nearest = std::numeric_limits<double>::infinity();
    for (const VesselSegment& segment : model.segments)
        for (std::size_t s = 1; s < segment.points.size(); ++s)
        {
            const ConePiece piece{segment.points[s - 1], segment.points[s], segment.radii[s - 1], segment.radii[s], {}, {}};
            nearest = std::min(nearest, coneDistance(piece, p));
        }
    return nearest;
}

LabelVolume renderPhantomLabels(const PhantomModel& model, const VolumeGeometry& geometry, const Progress& progress)
{
    const SliceStack stack = stackOf(geometry);
    const SliceEvaluator evaluator(model, stack, 0.0);
    LabelVolume labels(geometry);
    const std::size_t slices = stack.positions.size();
    parallelFor(
        slices,
        [&](std::size_t k) {
            std::uint8_t* out = labels.data() + k * evaluator.pixelCount();
            for (const TissueShape& shape : model.tissues)
                evaluator.forEachPixel(k, [&](std::size_t index, const Vector3d& p) {
                    if (shapeDistance(shape, p) < 0.0)
                        out[index] = shape.label;
                });
            std::vector<float> vessel;
            evaluator.vesselDistances(k, vessel);
            for (std::size_t index = 0; index < vessel.size(); ++index)
                if (vessel[index] < 0.0f)
                    out[index] = label::kVesselLumen;
        },
        [&](std::size_t done) { reportSlices(progress, done, slices, "rendering truth labels"); });
    return labels;
}

} // namespace vsim::dicom
