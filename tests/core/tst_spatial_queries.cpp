// The spatial queries against brute force, on three seeds each: NearestPoint (tests/support: the nearest of a point
// set for the grown trees' truth; exact, queries inside and far outside the set's box) and squaredDistanceTransform
// (core; exact squared distances on an anisotropic grid).

#include "vsim/core/DistanceTransform.h"
#include "NearestPoint.h"

#include <QtTest>

#include <limits>
#include <random>

using namespace vsim;

class SpatialQueries : public QObject
{
    Q_OBJECT
private slots:
    void nearestPointIsExact()
    {
        for (unsigned seed : {1u, 2u, 3u})
        {
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> unit(-50.0, 50.0);
            std::vector<Eigen::Vector3d> points(2000);
            for (Eigen::Vector3d& p : points)
                p = {unit(random), unit(random), 0.2 * unit(random)}; // a flat cloud: sparse cells above and below
            const NearestPoint nearest(points, 3.0);
            for (int q = 0; q < 500; ++q)
            {
                const Eigen::Vector3d query = 1.5 * Eigen::Vector3d(unit(random), unit(random), unit(random));
                int truth = 0;
                for (std::size_t i = 1; i < points.size(); ++i)
                    if ((points[i] - query).squaredNorm() < (points[std::size_t(truth)] - query).squaredNorm())
                        truth = int(i);
                double distance = 0.0;
                QCOMPARE(nearest.nearest(query, &distance), truth);
                QCOMPARE(distance, (points[std::size_t(truth)] - query).norm());
                QCOMPARE(nearest.anyWithin(query, distance + 1e-9), true);
                QCOMPARE(nearest.anyWithin(query, 0.999 * distance), false);
            }
        }
        QCOMPARE(NearestPoint({}, 1.0).nearest(Eigen::Vector3d::Zero()), -1);
    }

    void distanceTransformIsExact()
    {
        const std::array<int, 3> dims{23, 17, 11};
        const std::array<double, 3> spacing{0.7, 0.9, 1.6};
        for (unsigned seed : {1u, 2u, 3u})
        {
            std::mt19937 random(seed);
            std::bernoulli_distribution site(0.01);
            std::vector<double> values(std::size_t(dims[0] * dims[1] * dims[2]), 1.0);
            std::vector<Eigen::Vector3d> sites;
            for (int k = 0; k < dims[2]; ++k)
                for (int j = 0; j < dims[1]; ++j)
                    for (int i = 0; i < dims[0]; ++i)
                        if (site(random))
                        {
                            values[std::size_t(i + dims[0] * (j + dims[1] * k))] = 0.0;
                            sites.emplace_back(i * spacing[0], j * spacing[1], k * spacing[2]);
                        }
            QVERIFY(!sites.empty());
            squaredDistanceTransform(values, dims, spacing);
            double worst = 0.0;
            for (int k = 0; k < dims[2]; ++k)
                for (int j = 0; j < dims[1]; ++j)
                    for (int i = 0; i < dims[0]; ++i)
                    {
                        const Eigen::Vector3d p(i * spacing[0], j * spacing[1], k * spacing[2]);
                        double truth = std::numeric_limits<double>::infinity();
                        for (const Eigen::Vector3d& s : sites)
                            truth = std::min(truth, (s - p).squaredNorm());
                        worst = std::max(worst, std::abs(values[std::size_t(i + dims[0] * (j + dims[1] * k))] - truth));
                    }
            QVERIFY(worst <= 1e-9);
        }
        std::vector<double> none(8, 1.0);
        squaredDistanceTransform(none, {2, 2, 2}, {1.0, 1.0, 1.0});
        QVERIFY(std::isinf(none.front()));
    }
};

QTEST_APPLESS_MAIN(SpatialQueries)
#include "tst_spatial_queries.moc"
