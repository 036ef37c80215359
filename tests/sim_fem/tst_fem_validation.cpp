// The wall solver against analytic solutions (FemValidation.h states each truth and tolerance): patch test exact
// to 1e-8, no force under a 90-degree rigid rotation, cantilever tip within 3 % of Timoshenko, Lame cylinder
// (nu = 0.45) radial displacement within 2 % and hoop stress within 5 %, monotone energy decay with damping.

#include "vsim/core/Error.h"
#include "vsim/sim/fem/FemValidation.h"

#include <QtTest>

using namespace vsim;
using namespace vsim::sim::fem;

class FemValidation : public QObject
{
    Q_OBJECT

private slots:
    void analyticCases_data()
    {
        QTest::addColumn<QString>("name");
        for (const std::string& name : femValidationCases())
            QTest::newRow(name.c_str()) << QString::fromStdString(name);
    }

    void analyticCases()
    {
        QFETCH(QString, name);
        const ValidationResult result = runFemValidation(name.toStdString());
        qInfo("%s (%.2f s): %s", result.name.c_str(), result.seconds, result.description.c_str());
        for (const ValidationFigure& figure : result.figures)
            qInfo("  %s: %.6g %s (expected %.6g +- %.3g) %s", figure.name.c_str(), figure.measured, figure.unit.c_str(),
                  figure.expected, figure.tolerance, figure.passed() ? "ok" : "OUT OF TOLERANCE");
        QVERIFY(result.passed());
    }

    void unknownCaseIsRefused()
    {
        QVERIFY_THROWS_EXCEPTION(vsim::Error, runFemValidation("fem-nothing"));
    }
};

QTEST_GUILESS_MAIN(FemValidation)
#include "tst_fem_validation.moc"
