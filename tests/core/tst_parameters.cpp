// ParameterSet: declared once, validated with messages that name the key, the value and the range.
#include "vsim/core/Error.h"
#include "vsim/core/Parameters.h"

#include <QtTest>

using vsim::ParameterSet;
using vsim::ParameterSpec;

namespace {

ParameterSet wallParameters()
{
    return ParameterSet({
        {"young_modulus", "Young's modulus", "MPa", 4.23, 0.01, 100.0, "material", "thesis patient 1"},
        {"poisson_ratio", "Poisson ratio", "", 0.23, 0.0, 0.499, "material", ""},
        {"max_iterations", "CG iterations", "", 100, 1, 10000, "solver", "", ParameterSpec::Kind::Integer},
    });
}

} // namespace

class TestParameters : public QObject
{
    Q_OBJECT
private slots:
    void defaultsAreTheDeclaredValues()
    {
        const ParameterSet parameters = wallParameters();
        QCOMPARE(parameters.get("young_modulus"), 4.23);
        QCOMPARE(parameters.get("max_iterations"), 100.0);
        QCOMPARE(parameters.values().size(), std::size_t(3));
    }

    void setFromTextParsesKeyEqualsValue()
    {
        ParameterSet parameters = wallParameters();
        parameters.setFromText(" poisson_ratio = 0.45 ");
        QCOMPARE(parameters.get("poisson_ratio"), 0.45);
    }

    void outOfRangeMessageNamesKeyValueAndRange()
    {
        ParameterSet parameters = wallParameters();
        try
        {
            parameters.set("poisson_ratio", 0.5);
            QFAIL("0.5 is outside [0, 0.499] and must be refused");
        }
        catch (const vsim::Error& error)
        {
            const QString message = QString::fromStdString(error.message());
            QVERIFY2(message.contains("poisson_ratio") && message.contains("0.5") && message.contains("0.499"),
                     qPrintable(message));
            QCOMPARE(QString::fromStdString(error.contextValue("key")), QString("poisson_ratio"));
        }
        QCOMPARE(parameters.get("poisson_ratio"), 0.23); // unchanged after a refused value
    }

    void integerParameterRefusesFractions()
    {
        ParameterSet parameters = wallParameters();
        QVERIFY_THROWS_EXCEPTION(vsim::Error, parameters.set("max_iterations", 10.5));
        parameters.set("max_iterations", 250);
        QCOMPARE(parameters.get("max_iterations"), 250.0);
    }

    void unknownKeyListsTheKnownOnes()
    {
        ParameterSet parameters = wallParameters();
        try
        {
            parameters.setFromText("youngs=3");
            QFAIL("unknown key must be refused");
        }
        catch (const vsim::Error& error)
        {
            QVERIFY(QString::fromStdString(error.contextValue("known parameters")).contains("young_modulus"));
        }
    }

    void malformedTextAndNonFiniteValuesAreRefused()
    {
        ParameterSet parameters = wallParameters();
        QVERIFY_THROWS_EXCEPTION(vsim::Error, parameters.setFromText("young_modulus"));
        QVERIFY_THROWS_EXCEPTION(vsim::Error, parameters.setFromText("young_modulus=4.2MPa"));
        QVERIFY_THROWS_EXCEPTION(vsim::Error, parameters.set("young_modulus", std::nan("")));
    }

    void inconsistentDeclarationsAreRefused()
    {
        QVERIFY_THROWS_EXCEPTION(vsim::Error, ParameterSet({{"a", "A", "", 5, 0, 1, "", ""}}));
        QVERIFY_THROWS_EXCEPTION(vsim::Error,
                                 ParameterSet({{"a", "A", "", 0, 0, 1, "", ""}, {"a", "A", "", 0, 0, 1, "", ""}}));
    }
};

QTEST_APPLESS_MAIN(TestParameters)
#include "tst_parameters.moc"
