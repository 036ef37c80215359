// The SPH solver's flow validation cases (issue 18), each run on the run driver with its stated tolerances:
// sph-hydrostatic (water at rest in a tank: the pressure at depth within 2 %), sph-poiseuille (plane Poiseuille
// flow 20 particles across: RMS velocity error within 1 % of the peak, density within 1 %) and sph-womersley
// (pulsatile pipe flow at alpha 4 and 8: the centerline's amplitude and phase within 5 %), sph-mass (an inlet, an
// outlet and absorbing walls: inflow - outflow - absorbed = the mass change to rounding).

#include "vsim/sim/sph/SphValidation.h"

#include <QtTest>

using namespace vsim;
using namespace vsim::sim::sph;

class SphFlowValidation : public QObject
{
    Q_OBJECT
private slots:
    void flowCases_data()
    {
        QTest::addColumn<QString>("name");
        for (const char* name : {"sph-hydrostatic", "sph-poiseuille", "sph-womersley", "sph-mass", "sph-stenosis"})
            QTest::newRow(name) << QString(name);
    }

    void flowCases()
    {
        QFETCH(QString, name);
        const ValidationResult result = runSphValidation(name.toStdString());
        qInfo("%s (%.1f s)", result.description.c_str(), result.seconds);
        for (const ValidationFigure& figure : result.figures)
            qInfo("%s = %.4g (expected %.3g +- %.3g)", figure.name.c_str(), figure.measured, figure.expected,
                  figure.tolerance);
        QVERIFY(result.passed());
    }
};

QTEST_APPLESS_MAIN(SphFlowValidation)
#include "tst_sph_flow_validation.moc"
