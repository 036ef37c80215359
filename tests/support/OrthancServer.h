#pragma once

// A real Orthanc (Debian package orthanc, /usr/sbin/Orthanc) for the PACS tests (issue 22): its own configuration,
// storage and index in a fresh folder, DICOM on a free loopback port, no HTTP server, our AE title VASCUSIM
// registered as a modality at the port `vascusimPort` (where a C-MOVE sends to). `strict` lets only registered modalities echo, store, find, get and move (an unknown
// AE is refused), so that a permissive server does not hide a fault. With OrthancTls, the DICOM port speaks DICOM TLS
// only (Orthanc 1.9 and later), requires a client certificate it trusts, and moves to VASCUSIM over TLS. The server
// stops with the object, also when a test fails.

#include "vsim/core/Error.h"
#include "vsim/dicom/PacsClient.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QThread>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace vsim::test {

/// A loopback TCP port that nothing listens on now: bound to port 0, read, released.
inline int freeLoopbackPort()
{
    const int socket = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = 0;
    socklen_t length = sizeof address;
    int port = 0;
    if (socket >= 0 && ::bind(socket, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
        ::getsockname(socket, reinterpret_cast<sockaddr*>(&address), &length) == 0)
        port = ntohs(address.sin_port);
    if (socket >= 0)
        ::close(socket);
    return port;
}

/// Certificates (PEM) for an Orthanc that speaks DICOM TLS, and the client's that VascuSim shows.
struct OrthancTls
{
    std::string serverCertificate, serverKey; ///< Orthanc's
    std::string clientCertificate, clientKey; ///< VascuSim's (Orthanc trusts it)
};

/// A self-signed certificate and its key from the openssl command (`name`.pem, `name`.key in `folder`); false when
/// openssl is not there or fails.
inline bool makeSelfSignedCertificate(const std::filesystem::path& folder, const std::string& name)
{
    QProcess openssl;
    openssl.setProcessChannelMode(QProcess::MergedChannels);
    openssl.start("openssl", {"req", "-x509", "-nodes", "-days", "2", "-newkey", "rsa:2048", "-subj",
                              QString::fromStdString("/CN=" + name), "-keyout",
                              QString::fromStdString((folder / (name + ".key")).string()), "-out",
                              QString::fromStdString((folder / (name + ".pem")).string())});
    return openssl.waitForFinished(60000) && openssl.exitStatus() == QProcess::NormalExit && openssl.exitCode() == 0;
}

class OrthancServer
{
public:
    static QString executable()
    {
        const QString inPath = QStandardPaths::findExecutable("Orthanc");
        return inPath.isEmpty() ? QStandardPaths::findExecutable("Orthanc", {"/usr/sbin"}) : inPath;
    }

    /// Why the PACS tests cannot run here ("" when they can): Orthanc or DCMTK's storescu missing.
    static QString unavailableReason()
    {
        if (executable().isEmpty())
            return "Orthanc is not installed (Debian package orthanc; scripts/install-deps.sh installs it)";
        if (QStandardPaths::findExecutable("storescu").isEmpty())
            return "storescu is not installed (Debian package dcmtk)";
        return {};
    }

    /// Starts the server in `folder` (emptied first); waits until it answers an echo (15 s at most). Throws
    /// vsim::Error when it does not start.
    OrthancServer(const std::filesystem::path& folder, bool strict, int vascusimPort = 11112,
                  std::optional<OrthancTls> tls = std::nullopt)
        : m_tls(std::move(tls)), m_folder(folder)
    {
        std::filesystem::remove_all(folder);
        std::filesystem::create_directories(folder);
        m_port = freeLoopbackPort();
        const QString root = QString::fromStdString(folder.string());
        QJsonObject config{{"Name", "vascusim-test"},
                           {"StorageDirectory", root + "/storage"},
                           {"IndexDirectory", root + "/index"},
                           {"HttpServerEnabled", false},
                           {"DicomServerEnabled", true},
                           {"DicomAet", "ORTHANC"},
                           {"DicomPort", m_port},
                           {"DicomCheckCalledAet", true},
                           {"DicomCheckModalityHost", false},
                           {"RemoteAccessAllowed", false},
                           {"MaximumStorageCacheSize", 0}, // MB: every transfer reads the storage (a test breaks it)
                           {"Plugins", QJsonArray()},
                           {"DicomModalities", QJsonObject{{"vascusim", QJsonArray{"VASCUSIM", "127.0.0.1", vascusimPort}}}}};
        if (m_tls)
        {
            config.insert("DicomTlsEnabled", true);
            config.insert("DicomTlsCertificate", QString::fromStdString(m_tls->serverCertificate));
            config.insert("DicomTlsPrivateKey", QString::fromStdString(m_tls->serverKey));
            config.insert("DicomTlsTrustedCertificates", QString::fromStdString(m_tls->clientCertificate));
            config.insert("DicomTlsRemoteCertificateRequired", true);
            config.insert("DicomModalities",
                          QJsonObject{{"vascusim", QJsonObject{{"AET", "VASCUSIM"}, {"Host", "127.0.0.1"},
                                                               {"Port", vascusimPort}, {"UseDicomTls", true}}}});
        }
        for (const char* operation : {"Echo", "Store", "Find", "Get", "Move"})
            config.insert(QString("DicomAlwaysAllow") + operation, !strict);
        const QString path = QString::fromStdString((folder / "orthanc.json").string());
        QFile file(path);
        file.open(QIODevice::WriteOnly);
        file.write(QJsonDocument(config).toJson());
        file.close();
        m_process = std::make_unique<QProcess>();
        // Orthanc's DCMTK without Nagle's algorithm too (dicom::prepareDicomNetworking: with it on either end each
        // small PDU waits for a delayed acknowledgement; a PACS in the field is configured by its own people).
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert("TCP_NODELAY", "1");
        m_process->setProcessEnvironment(environment);
        m_process->setProcessChannelMode(QProcess::MergedChannels);
        m_process->setStandardOutputFile(QString::fromStdString((folder / "orthanc.log").string()));
        m_process->start(executable(), {path});
        if (!m_process->waitForStarted(10000))
            throw Error("Orthanc did not start: " + m_process->errorString().toStdString());
        for (int attempt = 0; attempt < 150; ++attempt)
        {
            try
            {
                dicom::pacsEcho(node());
                return;
            }
            catch (const Error&)
            {
                if (m_process->state() == QProcess::NotRunning)
                    break;
                QThread::msleep(100);
            }
        }
        throw Error("Orthanc did not answer an echo on port " + std::to_string(m_port) + " (see " +
                    (folder / "orthanc.log").string() + ")");
    }

    ~OrthancServer()
    {
        if (m_process && m_process->state() != QProcess::NotRunning)
        {
            m_process->terminate();
            if (!m_process->waitForFinished(10000))
                m_process->kill(), m_process->waitForFinished(5000);
        }
    }

    OrthancServer(const OrthancServer&) = delete;
    OrthancServer& operator=(const OrthancServer&) = delete;

    int port() const { return m_port; }
    /// Where Orthanc keeps the files it stored (a test removes one to break a transfer).
    std::filesystem::path storageFolder() const { return m_folder / "storage"; }
    /// The node as VascuSim (AE title VASCUSIM) reaches it.
    dicom::PacsNode node() const
    {
        dicom::PacsNode node;
        node.calledAeTitle = "ORTHANC";
        node.host = "127.0.0.1";
        node.port = m_port;
        node.timeoutS = 10;
        if (m_tls)
            node.tls = {true, m_tls->serverCertificate, m_tls->clientCertificate, m_tls->clientKey};
        return node;
    }

    /// Uploads the files with DCMTK's storescu (another C-STORE implementation than ours) from AE title VASCUSIM;
    /// storescu's exit code (-1 when it crashed or hung for a minute).
    int uploadWithStorescu(const std::vector<std::filesystem::path>& files) const
    {
        const dicom::PacsNode target = node();
        QStringList arguments{"-aet", QString::fromStdString(target.callingAeTitle), "-aec",
                              QString::fromStdString(target.calledAeTitle), QString::fromStdString(target.host),
                              QString::number(target.port)};
        if (m_tls) // the key not encrypted: no password prompt
            arguments << "--enable-tls" << QString::fromStdString(m_tls->clientKey)
                      << QString::fromStdString(m_tls->clientCertificate) << "--add-cert-file"
                      << QString::fromStdString(m_tls->serverCertificate);
        for (const std::filesystem::path& file : files)
            arguments << QString::fromStdString(file.string());
        QProcess storescu;
        storescu.start("storescu", arguments);
        storescu.waitForFinished(60000);
        return storescu.exitStatus() == QProcess::NormalExit ? storescu.exitCode() : -1;
    }

private:
    std::optional<OrthancTls> m_tls;
    std::filesystem::path m_folder;
    int m_port = 0;
    std::unique_ptr<QProcess> m_process;
};

} // namespace vsim::test
