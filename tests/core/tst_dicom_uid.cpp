// New DICOM UIDs (vsim/core/DicomUid.h) against PS3.5 section 9: at most 64 characters, digits and dots, no
// component with a leading zero; the 2.25 form is a version-4 UUID as a decimal integer (PS3.5 B.2, RFC 4122);
// a configured root prefixes every UID; bad roots are refused. Uniqueness over 20,000 UIDs in each form.

#include "vsim/core/DicomUid.h"
#include "vsim/core/Error.h"

#include <QtTest>

#include <set>
#include <string>

namespace {

bool validUid(const std::string& uid)
{
    if (uid.empty() || uid.size() > 64)
        return false;
    std::size_t start = 0;
    while (start <= uid.size())
    {
        const std::size_t dot = std::min(uid.find('.', start), uid.size());
        const std::string component = uid.substr(start, dot - start);
        if (component.empty() || component.find_first_not_of("0123456789") != std::string::npos ||
            (component.size() > 1 && component[0] == '0'))
            return false;
        start = dot + 1;
    }
    return true;
}

/// The 128-bit integer of a 2.25 UID's last component, as (high, low) 64-bit halves.
std::pair<unsigned long long, unsigned long long> uuidOf(const std::string& uid)
{
    unsigned __int128 value = 0;
    for (char digit : uid.substr(5))
        value = value * 10 + unsigned(digit - '0');
    return {static_cast<unsigned long long>(value >> 64), static_cast<unsigned long long>(value)};
}

} // namespace

class TestDicomUid : public QObject
{
    Q_OBJECT

private slots:
    void cleanup() { vsim::setDicomUidRoot(""); }

    void uuidFormIsValidVersionFourAndUnique()
    {
        QCOMPARE(vsim::dicomUidRoot(), std::string());
        std::set<std::string> seen;
        for (int i = 0; i < 20000; ++i)
        {
            const std::string uid = vsim::newDicomUid();
            QVERIFY2(uid.rfind("2.25.", 0) == 0 && validUid(uid), uid.c_str());
            const auto [high, low] = uuidOf(uid);
            QCOMPARE((high >> 12) & 0xF, 4ULL);  // the version nibble (RFC 4122 4.1.3)
            QCOMPARE((low >> 62) & 0x3, 2ULL);   // the variant bits 10 (RFC 4122 4.1.1)
            QVERIFY(seen.insert(uid).second);
        }
    }

    void configuredRootPrefixesEveryUid()
    {
        const std::string root = "1.2.826.0.1.3680043.10.1234";
        vsim::setDicomUidRoot(root);
        QCOMPARE(vsim::dicomUidRoot(), root);
        std::set<std::string> seen;
        for (int i = 0; i < 20000; ++i)
        {
            const std::string uid = vsim::newDicomUid();
            QVERIFY2(uid.rfind(root + ".", 0) == 0 && validUid(uid), uid.c_str());
            QVERIFY(seen.insert(uid).second);
        }
        vsim::setDicomUidRoot("");
        QVERIFY(vsim::newDicomUid().rfind("2.25.", 0) == 0);
    }

    void badRootsAreRefusedAndLeaveTheRoot()
    {
        vsim::setDicomUidRoot("1.2.3");
        for (const char* bad : {"1..2", ".1.2", "1.2.", "1.02.3", "1.2a.3", "1.2.3.4.5.6.7.8.9.10.11.12.13.14.15.16", "abc"})
        {
            QVERIFY_THROWS_EXCEPTION(vsim::Error, vsim::setDicomUidRoot(bad));
            QCOMPARE(vsim::dicomUidRoot(), std::string("1.2.3"));
        }
        vsim::setDicomUidRoot("1.0.3"); // a lone 0 is a valid component
        QVERIFY(validUid(vsim::newDicomUid()));
    }
};

QTEST_APPLESS_MAIN(TestDicomUid)
#include "tst_dicom_uid.moc"
