// The drug network's analytic cases (NetworkValidation.h): Hagen-Poiseuille limit 1e-12, conical closed form
// against numeric integration 1e-9, Kirchhoff conservation 1e-12, bifurcation and confluence networks 1e-9, the
// catheter's annulus 1e-12, blood and injection mixed at a confluence 1e-9, the two-phase split shift 1e-9.

#include "vsim/core/Error.h"
#include "vsim/sim/network/NetworkValidation.h"

#include <QtTest>

using namespace vsim;
using namespace vsim::sim::network;

class NetworkValidation : public QObject
{
    Q_OBJECT
private slots:
    void cases_data()
    {
        QTest::addColumn<QString>("name");
        for (const std::string& name : networkValidationCases())
            QTest::newRow(name.c_str()) << QString::fromStdString(name);
    }

    void cases()
    {
        QFETCH(QString, name);
        const ValidationResult result = runNetworkValidation(name.toStdString());
        for (const ValidationFigure& figure : result.figures)
        {
            qInfo("%s: %.3g (tolerance %.0e)", figure.name.c_str(), figure.measured - figure.expected, figure.tolerance);
            QVERIFY2(figure.passed(), figure.name.c_str());
        }
        QVERIFY(result.passed());
    }

    void unknownCase()
    {
        bool thrown = false;
        try
        {
            runNetworkValidation("network-nothing");
        }
        catch (const vsim::Error& error)
        {
            thrown = std::string(error.what()).find("network-cylinder") != std::string::npos;
        }
        QVERIFY(thrown);
    }
};

QTEST_APPLESS_MAIN(NetworkValidation)
#include "tst_network_validation.moc"
