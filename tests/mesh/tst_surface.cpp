// The lumen surface of a segmented phantom against the analytic vessel surface: mean distance <= 0.5 mm;
// decimation to a vertex budget reports its shape error; the surface is closed and outward.

#include "SegmentedPhantom.h"
#include "vsim/dicom/PhantomRender.h"
#include "vsim/imaging/VesselSegmentation.h"
#include "vsim/mesh/VesselSurface.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <filesystem>

using namespace vsim;
using namespace vsim::dicom;

class Surface : public QObject
{
    Q_OBJECT

    PhantomModel m_model;
    LabelVolume m_label;

    double meanDistanceToTruth(const TriangleMesh& surface, double* largest)
    {
        double sum = 0;
        *largest = 0;
        for (const Eigen::Vector3d& point : surface.points)
        {
            const double d = std::abs(vesselSurfaceDistance(m_model, point));
            sum += d;
            *largest = std::max(*largest, d);
        }
        return sum / double(surface.points.size());
    }

private slots:
    void initTestCase()
    {
        test::SegmentedPhantom phantom =
            test::segmentPhantom(PhantomKind::Bifurcation, {192, 192, 120}, {1.0, 1.0, 1.0}, 5);
        m_model = std::move(phantom.model);
        m_label = std::move(phantom.label);
    }

    void surfaceMatchesTheModel()
    {
        const mesh::VesselSurface result = mesh::extractVesselSurface(m_label, 1, ParameterSet(mesh::surfaceParameters()));
        double largest = 0;
        const double mean = meanDistanceToTruth(result.surface, &largest);
        qInfo("bifurcation surface: %zu vertices, mean distance to the model %.3f mm, largest %.3f mm",
              result.surface.points.size(), mean, largest);
        QVERIFY(mean <= 0.5);
        QVERIFY(result.surface.signedVolume() > 0.0);
        result.surface.validate();
    }

    void decimationReportsItsError()
    {
        ParameterSet parameters(mesh::surfaceParameters());
        parameters.set("target_vertices", 2000);
        const mesh::VesselSurface result = mesh::extractVesselSurface(m_label, 1, parameters);
        double largest = 0;
        const double mean = meanDistanceToTruth(result.surface, &largest);
        qInfo("decimated %zu -> %zu vertices: shape error mean %.3f mm, Hausdorff %.3f mm; to the model %.3f mm",
              result.fullVertices, result.surface.points.size(), result.meanErrorMm, result.hausdorffMm, mean);
        QVERIFY(std::abs(double(result.surface.points.size()) - 2000.0) < 200.0);
        QVERIFY(result.meanErrorMm > 0.0 && result.meanErrorMm < 0.5);
        QVERIFY(result.hausdorffMm >= result.meanErrorMm);
        QVERIFY(mean <= 0.6);
        const QTemporaryDir folder;
        const auto stl = std::filesystem::path(folder.path().toStdString()) / "lumen.stl";
        mesh::writeStl(result.surface, stl);
        QCOMPARE(std::filesystem::file_size(stl), std::uintmax_t(84 + 50 * result.surface.triangles.size()));
    }

    void emptyLabelIsRefused()
    {
        const LabelVolume empty(m_label.geometry());
        QVERIFY_THROWS_EXCEPTION(Error, mesh::extractVesselSurface(empty, 1, ParameterSet(mesh::surfaceParameters())));
    }
};

QTEST_GUILESS_MAIN(Surface)
#include "tst_surface.moc"
