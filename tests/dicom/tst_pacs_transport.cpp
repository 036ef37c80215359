// The PACS client's transport against a real Orthanc (issue 22; tests/support/OrthancServer.h, PacsTestSupport.h):
// DICOM TLS (echo, find, get, move and store over TLS, storescu uploading over TLS; the PACS's certificate not
// trusted, ours not trusted there, plain DICOM on its TLS port, a key that is not the certificate's, a missing file;
// the CLI's TLS options and their misuse), and a study holding an MR image besides its CT retrieved whole, then
// broken (a file removed from the PACS's storage: a partial transfer that leaves nothing). Skips, saying so, where
// Orthanc or openssl is not installed (scripts/install-deps.sh installs them).

#include "DicomFixtures.h"
#include "PacsTestSupport.h"
#include "vsim/core/DicomUid.h"
#include "vsim/dicom/PacsClient.h"

#include <QtTest>

using namespace vsim;
using test::CliResult;
using test::errorOf;
using test::runCli;
using test::startOrthanc;

class TestPacsTransport : public QObject
{
    Q_OBJECT
private slots:
    void init()
    {
        if (const QString reason = test::OrthancServer::unavailableReason(); !reason.isEmpty())
            QSKIP(qPrintable(reason));
    }

    /// DICOM TLS against an Orthanc that speaks only TLS on its DICOM port and trusts only our certificate.
    void tlsNode()
    {
        const std::filesystem::path certificates = test::freshFolder("pacs", "tls-certificates");
        for (const char* name : {"orthanc", "vascusim", "stranger"})
            if (!test::makeSelfSignedCertificate(certificates, name))
                QSKIP("the openssl command is not there or failed (Debian package openssl)");
        const auto pem = [&](const char* name, const char* extension) {
            return (certificates / (std::string(name) + extension)).string();
        };
        const test::OrthancTls tls{pem("orthanc", ".pem"), pem("orthanc", ".key"), pem("vascusim", ".pem"),
                                   pem("vascusim", ".key")};
        const int listenPort = test::freeLoopbackPort();
        std::unique_ptr<test::OrthancServer> orthanc;
        try
        {
            orthanc = std::make_unique<test::OrthancServer>(std::filesystem::path(test::outputFolder("pacs").toStdString()) /
                                                                "orthanc-tls",
                                                            false, listenPort, tls);
        }
        catch (const Error& error)
        {
            QFAIL(error.what());
        }
        const dicom::PacsNode node = orthanc->node();
        QVERIFY(dicom::describe(node).find("(TLS)") != std::string::npos);
        dicom::CtSeriesDescription description;
        description.patientId = "PACS-TLS-1";
        const test::PhantomSeries series = test::writePhantomSeries(dicom::PhantomKind::Stenosis, test::smallPhantomOptions(),
                                                                    test::freshFolder("pacs", "tls-series"), description);
        QCOMPARE(orthanc->uploadWithStorescu(series.written.files), 0); // storescu over TLS
        const std::string uid = series.written.studyInstanceUid;
        QCOMPARE(dicom::findStudies(node, {}).size(), std::size_t(1));
        const std::filesystem::path got = test::freshFolder("pacs", "tls-get");
        QCOMPARE(dicom::retrieveStudy(node, uid, got).size(), series.written.files.size());
        const std::filesystem::path moved = test::freshFolder("pacs", "tls-move");
        QCOMPARE(dicom::moveStudy(node, uid, moved, listenPort).size(), series.written.files.size());
        QCOMPARE(dicom::storeFiles(node, {series.written.files.front()}).size(), std::size_t(1));

        dicom::PacsNode plain = node;
        plain.tls = {};
        plain.timeoutS = 3;
        const QString plainFailed = errorOf([&] { dicom::pacsEcho(plain); });
        QVERIFY2(!plainFailed.isEmpty(), "plain DICOM on the TLS port must fail");
        qInfo("plain DICOM on the TLS port: %s", qPrintable(plainFailed));
        dicom::PacsNode untrustedServer = node;
        untrustedServer.tls.trustedCertificates = pem("stranger", ".pem");
        const QString notTrusted = errorOf([&] { dicom::pacsEcho(untrustedServer); });
        QVERIFY2(notTrusted.contains("TLS") && notTrusted.contains("stranger.pem"), qPrintable(notTrusted));
        dicom::PacsNode untrustedClient = node;
        untrustedClient.tls.certificate = pem("stranger", ".pem");
        untrustedClient.tls.privateKey = pem("stranger", ".key");
        const QString refused = errorOf([&] { dicom::pacsEcho(untrustedClient); });
        QVERIFY2(!refused.isEmpty(), "a client certificate the PACS does not trust must fail");
        qInfo("our certificate not trusted there: %s", qPrintable(refused));
        dicom::PacsNode mismatched = node;
        mismatched.tls.privateKey = pem("stranger", ".key");
        QVERIFY(errorOf([&] { dicom::pacsEcho(mismatched); }).contains("is not that of the certificate"));
        dicom::PacsNode missing = node;
        missing.tls.trustedCertificates = (certificates / "none.pem").string();
        QVERIFY(errorOf([&] { dicom::pacsEcho(missing); }).contains("not a file"));

        // The CLI: the node's TLS options, and their misuse.
        const QStringList where{"--aet", "ORTHANC", "--host", "127.0.0.1", "--port", QString::number(node.port), "--tls",
                                "--tls-trusted", QString::fromStdString(pem("orthanc", ".pem")), "--tls-cert",
                                QString::fromStdString(pem("vascusim", ".pem")), "--tls-key",
                                QString::fromStdString(pem("vascusim", ".key"))};
        CliResult echo = runCli(QStringList{"pacs", "echo"} + where);
        QVERIFY2(echo.code == 0 && echo.output.contains("(TLS)"), qPrintable(echo.output));
        CliResult withoutTls = runCli({"pacs", "echo", "--aet", "ORTHANC", "--host", "127.0.0.1", "--port",
                                       QString::number(node.port), "--tls-trusted", QString::fromStdString(pem("orthanc", ".pem"))});
        QVERIFY2(withoutTls.code == 2 && withoutTls.output.contains("go with --tls"), qPrintable(withoutTls.output));
    }

    /// A study with an MR image besides its CT comes whole (the other objects of a study do not fail its retrieve).
    /// Then a partial transfer: one stored file removed from the PACS's storage, the PACS sends the others and fails
    /// that one; the C-GET and the C-MOVE both fail, naming the failure, and leave no file.
    void partialTransferLeavesNothing()
    {
        QString failure;
        const int listenPort = test::freeLoopbackPort();
        const std::unique_ptr<test::OrthancServer> orthanc = startOrthanc("orthanc-partial", false, failure, listenPort);
        QVERIFY2(orthanc, qPrintable(failure));
        const dicom::PacsNode node = orthanc->node();
        dicom::CtSeriesDescription description;
        description.patientId = "PACS-PARTIAL-1";
        const test::PhantomSeries series = test::writePhantomSeries(dicom::PhantomKind::Stenosis, test::smallPhantomOptions(),
                                                                    test::freshFolder("pacs", "partial-series"), description);
        // One slice made an MR image of the same study (DCMTK's dcmodify: class, modality, new series and instance).
        const std::filesystem::path mr = test::freshFolder("pacs", "partial-mr") / "mr.dcm";
        std::filesystem::copy_file(series.written.files.front(), mr);
        QProcess dcmodify;
        dcmodify.start("dcmodify", {"-nb", "-gin", "-m", "(0008,0016)=1.2.840.10008.5.1.4.1.1.4", "-m", "(0008,0060)=MR", "-m",
                                    QString::fromStdString("(0020,000e)=" + newDicomUid()), QString::fromStdString(mr.string())});
        QVERIFY(dcmodify.waitForFinished(30000) && dcmodify.exitCode() == 0);
        std::vector<std::filesystem::path> upload = series.written.files;
        upload.push_back(mr);
        QCOMPARE(orthanc->uploadWithStorescu(upload), 0);
        const std::string uid = series.written.studyInstanceUid;
        QCOMPARE(dicom::findSeries(node, uid).size(), std::size_t(2));
        const std::filesystem::path whole = test::freshFolder("pacs", "partial-whole");
        QCOMPARE(dicom::retrieveStudy(node, uid, whole).size(), upload.size());
        const std::filesystem::path wholeMoved = test::freshFolder("pacs", "partial-whole-move");
        QCOMPARE(dicom::moveStudy(node, uid, wholeMoved, listenPort).size(), upload.size());

        std::vector<std::filesystem::path> stored;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(orthanc->storageFolder()))
            if (entry.is_regular_file())
                stored.push_back(entry.path());
        QVERIFY(stored.size() >= upload.size());
        std::filesystem::remove(stored.front());
        const std::filesystem::path got = test::freshFolder("pacs", "partial-get");
        const QString getFailed = errorOf([&] { dicom::retrieveStudy(node, uid, got); });
        QVERIFY2(getFailed.contains("failed") && std::filesystem::is_empty(got), qPrintable(getFailed));
        const std::filesystem::path moved = test::freshFolder("pacs", "partial-move");
        const QString moveFailed = errorOf([&] { dicom::moveStudy(node, uid, moved, listenPort); });
        QVERIFY2(moveFailed.contains("failed") && std::filesystem::is_empty(moved), qPrintable(moveFailed));
        qInfo("partial C-GET: %s; partial C-MOVE: %s", qPrintable(getFailed), qPrintable(moveFailed));
    }
};

QTEST_GUILESS_MAIN(TestPacsTransport)
#include "tst_pacs_transport.moc"
