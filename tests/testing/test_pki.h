// TestPki: a throwaway public key infrastructure for TLS tests, made at test
// time with the openssl command-line tool (OPENSSL_PATH) in a fresh
// directory under the test temp dir, removed again on destruction:
//
//   ca.crt/.key        a self-signed CA
//   server.crt/.key    signed by the CA, for DNS:localhost and IP:127.0.0.1
//   client.crt/.key    signed by the CA, for client authentication
//
// Keys are EC P-256 (instant to generate); certificates last two days.
//
// Owns the directory. Thread-safety: immutable after Create().

#ifndef LOCATOR_TESTS_TESTING_TEST_PKI_H_
#define LOCATOR_TESTS_TESTING_TEST_PKI_H_

#include <memory>
#include <string>
#include <vector>

#include "common/channel_options.h"
#include "locator/status.h"

namespace locator::test {

class TestPki {
 public:
  // Makes the files; Internal with openssl's stderr if a command fails.
  static Status Create(std::unique_ptr<TestPki>* pki);
  ~TestPki();
  TestPki(const TestPki&) = delete;
  TestPki& operator=(const TestPki&) = delete;

  // The path of `name` ("ca.crt", "server.key", ...) in the directory.
  std::string Path(const std::string& name) const;

  // locatord's flags for TLS, and with `mutual` also requiring client
  // certificates signed by the CA.
  std::vector<std::string> ServerFlags(bool mutual) const;
  // The credentials of a client that trusts the CA and, with
  // `client_cert`, presents the client certificate.
  ChannelSecurity ClientSecurity(bool client_cert) const;
  // The same as `locator` / `locator-load` flags, or with `prefix` as a
  // router's to its shards ("shard-": --shard-tls-ca, ...).
  std::vector<std::string> ClientFlags(bool client_cert,
                                       const std::string& prefix = "") const;

 private:
  explicit TestPki(std::string dir) : dir_(std::move(dir)) {}
  Status Openssl(const std::vector<std::string>& args) const;
  Status MakeCertificate(const std::string& name, const std::string& subject,
                         const std::string& extensions,
                         const std::string& serial) const;

  const std::string dir_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_TESTING_TEST_PKI_H_
