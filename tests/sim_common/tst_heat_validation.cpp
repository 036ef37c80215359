// The template solver's validation (HeatValidation.h): heat diffusion on the run driver against the exact decay of
// the slowest mode, its error and its second-order convergence.

#include "vsim/core/Error.h"
#include "vsim/sim/heat/HeatValidation.h"

#include <QtTest>

using namespace vsim;

class HeatValidation : public QObject
{
    Q_OBJECT
private slots:
    void everyCasePasses()
    {
        for (const std::string& name : sim::heat::heatValidationCases())
        {
            const ValidationResult result = sim::heat::runHeatValidation(name);
            for (const ValidationFigure& figure : result.figures)
                qInfo("%s: %s = %.6g (expected %.6g +- %.3g %s)", name.c_str(), figure.name.c_str(), figure.measured,
                      figure.expected, figure.tolerance, figure.unit.c_str());
            QVERIFY2(result.passed(), name.c_str());
        }
    }

    void unknownCaseIsRefused()
    {
        QVERIFY_THROWS_EXCEPTION(Error, sim::heat::runHeatValidation("heat-nothing"));
    }
};

QTEST_GUILESS_MAIN(HeatValidation)
#include "tst_heat_validation.moc"
