#include "tests/testing/test_pki.h"

#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "tests/testing/run_binary.h"

namespace locator::test {
namespace {

// The extensions each certificate gets; the server's names cover both ways
// a test may dial it.
constexpr char kConfig[] = R"(
[req]
distinguished_name = dn
prompt = no
[dn]
CN = unused
[ca]
basicConstraints = critical,CA:TRUE
keyUsage = critical,keyCertSign,cRLSign
subjectKeyIdentifier = hash
[server]
basicConstraints = CA:FALSE
keyUsage = critical,digitalSignature,keyEncipherment
extendedKeyUsage = serverAuth
subjectAltName = DNS:localhost,IP:127.0.0.1
authorityKeyIdentifier = keyid
[client]
basicConstraints = CA:FALSE
keyUsage = critical,digitalSignature
extendedKeyUsage = clientAuth
authorityKeyIdentifier = keyid
)";

}  // namespace

Status TestPki::Create(std::unique_ptr<TestPki>* pki) {
  std::string dir = ::testing::TempDir() + "locator_pki_XXXXXX";
  if (mkdtemp(dir.data()) == nullptr) {
    return Status::IOError("mkdtemp " + dir);
  }
  std::unique_ptr<TestPki> made(new TestPki(dir));
  std::ofstream(made->Path("openssl.cnf")) << kConfig;
  Status status = made->Openssl(
      {"req", "-x509", "-config", made->Path("openssl.cnf"), "-extensions",
       "ca", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1",
       "-nodes", "-keyout", made->Path("ca.key"), "-out", made->Path("ca.crt"),
       "-days", "2", "-subj", "/CN=locator-test-ca"});
  if (status.ok()) {
    status = made->MakeCertificate("server", "/CN=localhost", "server", "2");
  }
  if (status.ok()) {
    status = made->MakeCertificate("client", "/CN=locator-test-client",
                                   "client", "3");
  }
  if (status.ok()) *pki = std::move(made);
  return status;
}

TestPki::~TestPki() {
  std::error_code ignored;
  std::filesystem::remove_all(dir_, ignored);
}

std::string TestPki::Path(const std::string& name) const {
  return dir_ + "/" + name;
}

Status TestPki::Openssl(const std::vector<std::string>& args) const {
  const BinaryResult result = RunBinary(OPENSSL_PATH, args);
  if (result.exit_code == 0) return Status::OK();
  return Status::Internal("openssl " + args.front() + " failed (exit " +
                          std::to_string(result.exit_code) +
                          "): " + result.err);
}

Status TestPki::MakeCertificate(const std::string& name,
                                const std::string& subject,
                                const std::string& extensions,
                                const std::string& serial) const {
  const std::string key = Path(name + ".key");
  const std::string request = Path(name + ".csr");
  Status status =
      Openssl({"req", "-new", "-config", Path("openssl.cnf"), "-newkey", "ec",
               "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes", "-keyout",
               key, "-out", request, "-subj", subject});
  if (!status.ok()) return status;
  return Openssl({"x509", "-req", "-in", request, "-CA", Path("ca.crt"),
                  "-CAkey", Path("ca.key"), "-set_serial", serial, "-days", "2",
                  "-extfile", Path("openssl.cnf"), "-extensions", extensions,
                  "-out", Path(name + ".crt")});
}

std::vector<std::string> TestPki::ServerFlags(bool mutual) const {
  std::vector<std::string> flags = {"--tls-cert", Path("server.crt"),
                                    "--tls-key", Path("server.key")};
  if (mutual) {
    flags.insert(flags.end(), {"--tls-client-ca", Path("ca.crt")});
  }
  return flags;
}

std::vector<std::string> TestPki::ClientFlags(bool client_cert,
                                              const std::string& prefix) const {
  const std::string tls = "--" + prefix + "tls";
  std::vector<std::string> flags = {tls + "-ca", Path("ca.crt")};
  if (client_cert) {
    flags.insert(flags.end(), {tls + "-cert", Path("client.crt"), tls + "-key",
                               Path("client.key")});
  }
  return flags;
}

ChannelSecurity TestPki::ClientSecurity(bool client_cert) const {
  // Through the clients' own flag reading, as `locator --tls-ca ...` does.
  ChannelSecurityFlags flags;
  flags.tls_ca = Path("ca.crt");
  if (client_cert) {
    flags.tls_cert = Path("client.crt");
    flags.tls_key = Path("client.key");
  }
  ChannelSecurity security;
  const Status loaded = LoadChannelSecurity(flags, &security);
  EXPECT_TRUE(loaded.ok()) << loaded.ToString();
  return security;
}

}  // namespace locator::test
