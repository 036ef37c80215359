// DICOM TLS for the PACS client (PS3.15 B.1; issue 22): one OpenSSL transport layer of DCMTK dcmtls, for our end of
// an association we open (a requestor) or of the move listener's (an acceptor), with the BCP 195 profile (TLS 1.2
// or later, its cipher suites) and the peer's certificate required and verified against the trusted ones.

#include "PacsAssociation.h"

#include "vsim/core/Error.h"

#include <dcmtk/dcmtls/tlslayer.h>

#include <filesystem>

namespace vsim::dicom::detail {
namespace {

void checkTls(const OFCondition& condition, const std::string& what)
{
    if (condition.bad())
        throw Error(Pattern{"DICOM TLS: %1: %2", {what, condition.text()}});
}

/// The PEM file `path` given for `what`; throws when it is not set or not there.
const char* pemFile(const std::string& path, const std::string& what)
{
    if (path.empty())
        throw Error(Pattern{"DICOM TLS needs %1 (a PEM file)", {what}});
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw Error(Pattern{"DICOM TLS: %1 is not a file: %2", {what, path}});
    return path.c_str();
}

} // namespace

std::unique_ptr<DcmTLSTransportLayer> makeTlsLayer(const PacsTls& tls, bool acceptor)
{
    auto layer = std::make_unique<DcmTLSTransportLayer>(acceptor ? NET_ACCEPTOR : NET_REQUESTOR, nullptr, OFTrue);
    checkTls(layer->setTLSProfile(TSP_Profile_BCP195), "the BCP 195 profile");
    checkTls(layer->activateCipherSuites(), "the cipher suites");
    checkTls(layer->addTrustedCertificateFile(pemFile(tls.trustedCertificates, "the trusted certificates"),
                                              DCF_Filetype_PEM),
             "cannot read the trusted certificates " + tls.trustedCertificates);
    if (acceptor || !tls.certificate.empty() || !tls.privateKey.empty())
    {
        const std::string whose = acceptor ? "our certificate and its private key (the move's listener shows them)"
                                           : "our certificate and its private key, both or neither";
        checkTls(layer->setPrivateKeyFile(pemFile(tls.privateKey, whose), DCF_Filetype_PEM),
                 "cannot read our private key " + tls.privateKey + " (it must not be encrypted)");
        checkTls(layer->setCertificateFile(pemFile(tls.certificate, whose), DCF_Filetype_PEM),
                 "cannot read our certificate " + tls.certificate);
        if (!layer->checkPrivateKeyMatchesCertificate())
            throw Error(Pattern{"DICOM TLS: the private key %1 is not that of the certificate %2",
                                {tls.privateKey, tls.certificate}});
    }
    layer->setCertificateVerification(DCV_requireCertificate);
    return layer;
}

} // namespace vsim::dicom::detail
