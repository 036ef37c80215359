#include "vsim/imaging/Centerlines.h"

#include "LabelGeometry.h"
#include "vsim/core/Localized.h"
#include "vsim/interop/ItkImage.h"

#include <Eigen/Dense>
#include <itkFastMarchingImageFilter.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vsim::imaging {
namespace {

using FloatImage = itk::Image<float, 3>;

/// Cubic B-spline basis values N_{i,3}(t) of every control point on a clamped knot vector.
Eigen::VectorXd cubicBasis(const std::vector<double>& knots, int controls, double t)
{
    const int degree = 3;
    // Degree-0 basis over the knot spans, then the Cox-de Boor recursion.
    const int spans = int(knots.size()) - 1;
    Eigen::VectorXd basis = Eigen::VectorXd::Zero(spans);
    for (int i = 0; i < spans; ++i)
        if ((t >= knots[std::size_t(i)] && t < knots[std::size_t(i + 1)]) ||
            (t == knots.back() && knots[std::size_t(i)] < knots[std::size_t(i + 1)] && knots[std::size_t(i + 1)] == knots.back()))
            basis[i] = 1.0;
    for (int p = 1; p <= degree; ++p)
    {
        Eigen::VectorXd next = Eigen::VectorXd::Zero(spans - p);
        for (int i = 0; i < spans - p; ++i)
        {
            const double left = knots[std::size_t(i + p)] - knots[std::size_t(i)];
            const double right = knots[std::size_t(i + p + 1)] - knots[std::size_t(i + 1)];
            if (left > 0)
                next[i] += (t - knots[std::size_t(i)]) / left * basis[i];
            if (right > 0)
                next[i] += (knots[std::size_t(i + p + 1)] - t) / right * basis[i + 1];
        }
        basis = next;
    }
    return basis.head(controls);
}

std::array<int, 3> nearestVoxel(const VolumeGeometry& geometry, const Eigen::Vector3d& patient)
{
    const Eigen::Vector3d index = geometry.patientToIndex(patient);
    std::array<int, 3> v{};
    for (int a = 0; a < 3; ++a)
        v[a] = std::clamp(int(std::lround(index[a])), 0, geometry.dims[a] - 1);
    return v;
}

} // namespace

std::vector<ParameterSpec> centerlineParameters()
{
    const std::string group = "Centerlines";
    return {
        {"speed_power", "Speed exponent", "", 2, 0.5, 8, group,
         "Fast-marching speed = (distance to the wall / its maximum)^exponent: higher hugs the medial axis."},
        {"bspline_knot_spacing_mm", "B-spline knot spacing", "mm", 4, 0.5, 50, group,
         "Knot spacing of the least-squares cubic B-spline that smooths each centerline (thesis ch. 4.1)."},
        {"sample_step_mm", "Sample step", "mm", 0.5, 0.05, 5, group, "Spacing of the resampled centerline points."},
    };
}

std::vector<Eigen::Vector3d> smoothWithBSpline(const std::vector<Eigen::Vector3d>& points, double knotSpacingMm,
                                               double stepMm)
{
    if (points.size() < 5)
        return points;
    std::vector<double> t{0.0};
    for (std::size_t p = 1; p < points.size(); ++p)
        t.push_back(t.back() + (points[p] - points[p - 1]).norm());
    const double length = t.back();
    const int controls = std::clamp(int(std::lround(length / knotSpacingMm)) + 3, 4, int(points.size()) - 1);
    std::vector<double> knots(4, 0.0);
    for (int k = 1; k <= controls - 4; ++k)
        knots.push_back(length * k / (controls - 3));
    knots.insert(knots.end(), 4, length);

    // Least squares with the end control points pinned to the end points (a clamped curve passes through them).
    const int free = controls - 2, samples = int(points.size());
    Eigen::MatrixXd a(samples, free);
    Eigen::MatrixXd rhs(samples, 3);
    for (int s = 0; s < samples; ++s)
    {
        const Eigen::VectorXd basis = cubicBasis(knots, controls, t[std::size_t(s)]);
        a.row(s) = basis.segment(1, free).transpose();
        rhs.row(s) = (points[std::size_t(s)] - basis[0] * points.front() - basis[controls - 1] * points.back()).transpose();
    }
    // A small penalty on the second differences of the control points keeps knot spans without samples
    // determined (a singular normal matrix would let their control points fly off).
    Eigen::MatrixXd normal = a.transpose() * a;
    const double ridge = 1e-3 * normal.diagonal().mean();
    for (int c = 0; c + 2 < free; ++c)
    {
        const int index[3] = {c, c + 1, c + 2};
        const double weight[3] = {1.0, -2.0, 1.0};
        for (int x = 0; x < 3; ++x)
            for (int y = 0; y < 3; ++y)
                normal(index[x], index[y]) += ridge * weight[x] * weight[y];
    }
    const Eigen::MatrixXd inner = normal.ldlt().solve(a.transpose() * rhs);
    std::vector<Eigen::Vector3d> control{points.front()};
    for (int c = 0; c < free; ++c)
        control.push_back(inner.row(c).transpose());
    control.push_back(points.back());

    const int steps = std::max(1, int(std::ceil(length / stepMm)));
    std::vector<Eigen::Vector3d> smooth;
    for (int s = 0; s <= steps; ++s)
    {
        if (s == steps) // the clamped curve ends at the last control point (and t = length may round past it)
        {
            smooth.push_back(control.back());
            break;
        }
        const Eigen::VectorXd basis = cubicBasis(knots, controls, length * s / steps);
        Eigen::Vector3d point = Eigen::Vector3d::Zero();
        for (int c = 0; c < controls; ++c)
            point += basis[c] * control[std::size_t(c)];
        smooth.push_back(point);
    }
    return smooth;
}

SkeletonGraph extractCenterlines(const LabelVolume& label, std::uint8_t value, const SkeletonGraph& skeleton,
                                 const ParameterSet& p, const std::optional<std::pair<int, int>>& fromTo,
                                 const Progress& progress)
{
    if (skeleton.nodes.empty() || skeleton.edges.empty())
        throw Error("the skeleton is empty: run the skeleton step first");
    const LabelVolume binary = cropLabel(label, value, 2).binary;
    const VolumeGeometry& geometry = binary.geometry();
    const RealVolume distance = insideDistanceMm(binary, 1);
    progress.report(0.2, localized("vsim::Progress", "fast marching"));

    // Speed: fastest on the medial axis, ((d + h/2) / (peak + h/2))^power with d the distance of a voxel's centre to
    // the wall's voxels and h the finest spacing (the wall itself lies half a voxel out: a vessel two voxels across
    // has d = 0 in all of its voxels, and must still be much faster than around it). A crawl, far slower than any
    // lumen voxel, in the voxels touching the lumen, so that lumen voxels joined only across an edge or a corner
    // (26-connected) stay reachable by the 6-connected front; none farther out.
    const double halfVoxel = 0.5 * geometry.spacing.minCoeff();
    auto wallDistance = [&](int i, int j, int k) { return std::max(0.0, double(distance.at(i, j, k))) + halfVoxel; };
    const double peak = *std::max_element(distance.data(), distance.data() + distance.size()) + halfVoxel;
    RealVolume speed = RealVolume::uninitialized(geometry);
    const double power = p.get("speed_power");
    constexpr float kCrawl = 1e-5f;
    const auto& d = geometry.dims;
    for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j)
            for (int i = 0; i < d[0]; ++i)
            {
                float value = 0.0f;
                if (binary.at(i, j, k))
                    value = float(std::pow(wallDistance(i, j, k) / peak, power));
                else
                    for (int n = 0; n < 27 && value == 0.0f; ++n)
                    {
                        const int ii = i + n % 3 - 1, jj = j + (n / 3) % 3 - 1, kk = k + n / 9 - 1;
                        if (geometry.contains(ii, jj, kk) && binary.at(ii, jj, kk))
                            value = kCrawl;
                    }
                speed.at(i, j, k) = value;
            }

    // The root: the endpoint of largest radius (the aortic inlet, the hepatic artery's origin).
    std::vector<int> ends = skeleton.endpoints();
    if (ends.empty())
        ends = {0};
    auto radiusAtNode = [&](int node) {
        const auto v = nearestVoxel(geometry, skeleton.nodes[std::size_t(node)].position);
        return double(distance.at(v[0], v[1], v[2]));
    };
    const int root = fromTo ? fromTo->first
                            : *std::max_element(ends.begin(), ends.end(),
                                                [&](int a, int b) { return radiusAtNode(a) < radiusAtNode(b); });

    using Marching = itk::FastMarchingImageFilter<FloatImage, FloatImage>;
    auto marching = Marching::New();
    auto trial = Marching::NodeContainer::New();
    Marching::NodeType seed;
    const auto rootVoxel = nearestVoxel(geometry, skeleton.nodes[std::size_t(root)].position);
    seed.SetIndex({{rootVoxel[0], rootVoxel[1], rootVoxel[2]}});
    seed.SetValue(0.0);
    trial->InsertElement(0, seed);
    marching->SetTrialPoints(trial);
    marching->SetInput(interop::toItk(speed)); // zero speed outside the lumen: those voxels are never reached
    marching->Update();
    const RealVolume arrival = interop::fromItk<float>(marching->GetOutput());
    progress.report(0.6, localized("vsim::Progress", "minimal paths"));

    auto timeAt = [&](const std::array<int, 3>& v) { return double(arrival.at(v[0], v[1], v[2])); };
    constexpr double kUnreached = 1e30;
    /// Steepest descent of the arrival time from `start` until the time drops to `stopTime` or below.
    auto descend = [&](std::array<int, 3> current, double stopTime) {
        std::vector<std::array<int, 3>> path{current};
        for (std::size_t guard = 0; guard < arrival.size() && timeAt(current) > stopTime; ++guard)
        {
            std::array<int, 3> best = current;
            for (int dk = -1; dk <= 1; ++dk)
                for (int dj = -1; dj <= 1; ++dj)
                    for (int di = -1; di <= 1; ++di)
                    {
                        const std::array<int, 3> next{current[0] + di, current[1] + dj, current[2] + dk};
                        if (geometry.contains(next[0], next[1], next[2]) && timeAt(next) < timeAt(best))
                            best = next;
                    }
            if (best == current)
                break; // a local minimum: the root's basin
            current = best;
            path.push_back(current);
        }
        return path;
    };

    SkeletonGraph result;
    result.nodes = skeleton.nodes;
    const double knotSpacing = p.get("bspline_knot_spacing_mm"), step = p.get("sample_step_mm");
    std::vector<std::pair<int, int>> wanted;
    if (fromTo)
        wanted.push_back(*fromTo);
    else
        for (const SkeletonGraph::Edge& edge : skeleton.edges)
            wanted.push_back({edge.from, edge.to});
    for (const auto& [from, to] : wanted)
    {
        const auto voxelFrom = nearestVoxel(geometry, skeleton.nodes[std::size_t(from)].position);
        const auto voxelTo = nearestVoxel(geometry, skeleton.nodes[std::size_t(to)].position);
        if (timeAt(voxelFrom) >= kUnreached || timeAt(voxelTo) >= kUnreached)
            throw Error(Pattern{"the vessel label is disconnected: skeleton nodes %1 and %2 cannot be reached from "
                                "the root through the lumen; segment one vessel tree from a seed, or join the parts "
                                "with the brush",
                                {std::to_string(from), std::to_string(to)}});
        // Descend from the node farther from the root down to the nearer one.
        const bool toIsChild = timeAt(voxelTo) >= timeAt(voxelFrom);
        std::vector<std::array<int, 3>> voxels = descend(toIsChild ? voxelTo : voxelFrom,
                                                         timeAt(toIsChild ? voxelFrom : voxelTo));
        if (voxels.back() != (toIsChild ? voxelFrom : voxelTo))
            voxels.push_back(toIsChild ? voxelFrom : voxelTo);
        // Thinning stops short of a vessel end (a rounded cap; a two-voxel tip that steps diagonally loses
        // millimetres): at an endpoint, carry on up the arrival time while the lumen keeps at least 90 % of the end's
        // radius (a cap's centre is where the full radius ends), measured to the wall half a voxel beyond the wall
        // voxels (a two-voxel tip is all wall voxels).
        const int child = toIsChild ? to : from;
        if (skeleton.degree(child) == 1 && !fromTo)
        {
            const double endRadius = wallDistance(voxels.front()[0], voxels.front()[1], voxels.front()[2]);
            std::vector<std::array<int, 3>> extension;
            std::array<int, 3> current = voxels.front();
            for (int guard = 0; guard < 1000; ++guard)
            {
                std::array<int, 3> best = current;
                for (int n = 0; n < 27; ++n)
                {
                    const std::array<int, 3> next{current[0] + n % 3 - 1, current[1] + (n / 3) % 3 - 1, current[2] + n / 9 - 1};
                    if (geometry.contains(next[0], next[1], next[2]) && binary.at(next[0], next[1], next[2]) &&
                        wallDistance(next[0], next[1], next[2]) >= 0.9 * endRadius && timeAt(next) < kUnreached &&
                        timeAt(next) > timeAt(best))
                        best = next;
                }
                if (best == current)
                    break;
                current = best;
                extension.push_back(current);
            }
            voxels.insert(voxels.begin(), extension.rbegin(), extension.rend());
        }
        if (toIsChild)
            std::reverse(voxels.begin(), voxels.end()); // from -> to
        // Sub-voxel: each path voxel moves to the centroid of its 3 x 3 x 3 neighbourhood weighted by the
        // distance to the wall to the 4th power, which pulls it onto the medial axis between voxel centres.
        std::vector<Eigen::Vector3d> raw;
        for (const auto& v : voxels)
        {
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            double weights = 0;
            for (int n = 0; n < 27; ++n)
            {
                const std::array<int, 3> u{v[0] + n % 3 - 1, v[1] + (n / 3) % 3 - 1, v[2] + n / 9 - 1};
                if (!geometry.contains(u[0], u[1], u[2]) || !binary.at(u[0], u[1], u[2]))
                    continue;
                const double w = std::pow(std::max(0.0f, distance.at(u[0], u[1], u[2])), 4.0);
                sum += w * geometry.indexToPatient(Eigen::Vector3d(u[0], u[1], u[2]));
                weights += w;
            }
            raw.push_back(weights > 0 ? Eigen::Vector3d(sum / weights)
                                      : geometry.indexToPatient(Eigen::Vector3d(v[0], v[1], v[2])));
        }
        SkeletonGraph::Edge edge;
        edge.from = from;
        edge.to = to;
        edge.points = smoothWithBSpline(raw, knotSpacing, step);
        for (const Eigen::Vector3d& point : edge.points)
        {
            const auto v = nearestVoxel(geometry, point);
            const Eigen::Vector3d labelIndex = label.geometry().patientToIndex(point);
            edge.voxels.push_back({int(std::lround(labelIndex[0])), int(std::lround(labelIndex[1])), int(std::lround(labelIndex[2]))});
            edge.radii.push_back(std::max(double(distance.at(v[0], v[1], v[2])), 0.5 * geometry.spacing.minCoeff()));
        }
        result.edges.push_back(std::move(edge));
    }
    progress.report(1.0, localized("vsim::Progress", "centerlines"));
    return result;
}

} // namespace vsim::imaging
