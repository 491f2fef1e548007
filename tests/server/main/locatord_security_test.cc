// locatord's access control, redaction and TLS, end to end: bearer tokens
// per RPC scope, the health service left open, GetStats without paths, TLS
// and mutual TLS with certificates made at test time by openssl, and the
// startup errors for unusable token and certificate files.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "tests/server/main/e2e_support.h"
#include "tests/testing/test_pki.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr auto kExitTimeout = std::chrono::seconds(30);
constexpr char kDataToken[] = "data-7f3a9c";
constexpr char kAdminToken[] = "admin-52be0d";

std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "locatord_security_" +
                           std::to_string(getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}

ChannelSecurity WithToken(const std::string& token) {
  ChannelSecurity security;
  security.bearer_token = token;
  return security;
}

// Locate with `authorization` as the raw metadata value (none if empty),
// over a plaintext channel without a token of its own.
grpc::Status LocateWithHeader(const ServerProcess& server,
                              const std::string& authorization) {
  auto stub = NewStub(server, ChannelSecurity());
  grpc::ClientContext context;
  if (!authorization.empty())
    context.AddMetadata("authorization", authorization);
  v1::LocateResponse response;
  return stub->Locate(&context, LocateRequestFor({0.5, 0.5}), &response);
}

// Each RPC once, on `stub`; their codes in the order Locate, LocateBatch,
// LocateStream, GetStats, Retune.
std::vector<grpc::StatusCode> EveryRpc(v1::Locator::Stub& stub) {
  std::vector<grpc::StatusCode> codes;
  v1::LocateResponse located;
  codes.push_back(LocateOne(stub, {0.5, 0.5}, &located).error_code());
  {
    grpc::ClientContext context;
    v1::LocateBatchResponse response;
    const std::vector<Point2> points = {{0.5, 0.5}, {0.25, 0.75}};
    codes.push_back(
        stub.LocateBatch(&context, BatchRequestFor(points), &response)
            .error_code());
  }
  {
    grpc::ClientContext context;
    auto stream = stub.LocateStream(&context);
    stream->Write(LocateRequestFor({0.5, 0.5}));
    stream->WritesDone();
    while (stream->Read(&located)) {
    }
    codes.push_back(stream->Finish().error_code());
  }
  {
    grpc::ClientContext context;
    v1::GetStatsResponse response;
    codes.push_back(stub.GetStats(&context, {}, &response).error_code());
  }
  {
    grpc::ClientContext context;
    v1::RetuneResponse response;
    codes.push_back(stub.Retune(&context, {}, &response).error_code());
  }
  return codes;
}

// Starts locatord with `flags`: it must exit 2 (a flag error, before it
// listens) saying `message`.
void ExpectStartupFailure(const std::vector<std::string>& flags,
                          const std::string& message) {
  std::vector<std::string> args = {"--dataset", "uniform:100:1", "--listen",
                                   "127.0.0.1:0"};
  args.insert(args.end(), flags.begin(), flags.end());
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(ServerProcess::Spawn(LOCATORD_PATH, args, &server).ok());
  EXPECT_EQ(server->WaitForExit(kExitTimeout), 2) << message;
  EXPECT_THAT(server->StderrText(), HasSubstr(message));
}

using Codes = std::vector<grpc::StatusCode>;
constexpr grpc::StatusCode kOk = grpc::StatusCode::OK;
constexpr grpc::StatusCode kUnauthenticated = grpc::StatusCode::UNAUTHENTICATED;
constexpr grpc::StatusCode kDenied = grpc::StatusCode::PERMISSION_DENIED;

class LocatordTokensTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const Status started = StartLocatord(
        "uniform:2000:1",
        {"--token-file",
         WriteFile("data_token", std::string(kDataToken) + "\n"),
         "--admin-token-file", WriteFile("admin_token", kAdminToken)},
        &server_, WithToken(kDataToken));
    ASSERT_TRUE(started.ok()) << started.ToString();
  }
  static void TearDownTestSuite() { server_.reset(); }

  static std::unique_ptr<ServerProcess> server_;
};

std::unique_ptr<ServerProcess> LocatordTokensTest::server_;

TEST_F(LocatordTokensTest, EveryRpcNeedsAToken) {
  auto stub = NewStub(*server_, ChannelSecurity());
  EXPECT_EQ(EveryRpc(*stub), Codes(5, kUnauthenticated));
}

TEST_F(LocatordTokensTest, DataTokenServesDataRpcsButNotAdminOnes) {
  auto stub = NewStub(*server_, WithToken(kDataToken));
  EXPECT_EQ(EveryRpc(*stub), Codes({kOk, kOk, kOk, kOk, kDenied}));
}

TEST_F(LocatordTokensTest, AdminTokenServesEveryRpc) {
  auto stub = NewStub(*server_, WithToken(kAdminToken));
  EXPECT_EQ(EveryRpc(*stub), Codes(5, kOk));
}

TEST_F(LocatordTokensTest, WrongTokenIsDeniedAndMalformedUnauthenticated) {
  auto stub = NewStub(*server_, WithToken("data-7f3a9d"));
  EXPECT_EQ(EveryRpc(*stub), Codes(5, kDenied));
  const grpc::Status wrong =
      LocateWithHeader(*server_, "Bearer " + std::string(kAdminToken) + "x");
  EXPECT_EQ(wrong.error_code(), kDenied);
  EXPECT_THAT(wrong.error_message(), Not(HasSubstr(kAdminToken)));
  for (const std::string& header :
       {std::string(kDataToken), "Basic " + std::string(kDataToken),
        std::string("Bearer")}) {
    const grpc::Status malformed = LocateWithHeader(*server_, header);
    EXPECT_EQ(malformed.error_code(), kUnauthenticated) << header;
    EXPECT_THAT(malformed.error_message(), HasSubstr("Bearer <token>"));
  }
  EXPECT_TRUE(
      LocateWithHeader(*server_, "bearer " + std::string(kDataToken)).ok());
}

TEST_F(LocatordTokensTest, HealthNeedsNoToken) {
  server_->set_client_security(ChannelSecurity());
  HealthStatus health = HealthStatus::kUnknown;
  const grpc::Status probe = server_->CheckHealth(&health);
  server_->set_client_security(WithToken(kDataToken));
  ASSERT_TRUE(probe.ok()) << probe.error_message();
  EXPECT_EQ(health, HealthStatus::kServing);
}

TEST(LocatordAccessTest, AdminTokenAloneGuardsOnlyAdminRpcs) {
  std::unique_ptr<ServerProcess> server;
  const Status started = StartLocatord(
      "uniform:2000:1",
      {"--admin-token-file", WriteFile("admin_only", kAdminToken)}, &server);
  ASSERT_TRUE(started.ok()) << started.ToString();
  auto anonymous = NewStub(*server);
  EXPECT_EQ(EveryRpc(*anonymous),
            Codes({kOk, kOk, kOk, kOk, kUnauthenticated}));
  auto admin = NewStub(*server, WithToken(kAdminToken));
  EXPECT_EQ(EveryRpc(*admin), Codes(5, kOk));
}

TEST(LocatordAccessTest, RedactedStatsNameNoPath) {
  const TestDatasetFile dataset;
  std::unique_ptr<ServerProcess> plain, redacted;
  ASSERT_TRUE(StartLocatord(dataset.path(), {}, &plain).ok());
  ASSERT_TRUE(StartLocatord(dataset.path(), {"--redact"}, &redacted).ok());
  const v1::GetStatsResponse shown = GetStats(*NewStub(*plain));
  const v1::GetStatsResponse hidden = GetStats(*NewStub(*redacted));
  EXPECT_EQ(shown.dataset().source(), dataset.path());
  EXPECT_EQ(hidden.dataset().source(), "");
  const std::string file_name =
      dataset.path().substr(dataset.path().rfind('/') + 1);
  EXPECT_THAT(hidden.SerializeAsString(), Not(HasSubstr(file_name)));
  EXPECT_THAT(hidden.SerializeAsString(), Not(HasSubstr(::testing::TempDir())));
  // Everything else is still there.
  EXPECT_EQ(hidden.dataset().input_points(), shown.dataset().input_points());
}

TEST(LocatordAccessTest, UnusableTokenFilesFailStartupNamingTheFile) {
  const std::string empty = WriteFile("empty_token", "\n");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--token-file", "/no/such/token"},
       "--token-file '/no/such/token': cannot open"},
      {{"--admin-token-file", empty},
       "--admin-token-file '" + empty + "': the token is empty"},
  };
  for (const auto& [flags, message] : cases) {
    ExpectStartupFailure(flags, message);
  }
}

class LocatordTlsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const Status made = TestPki::Create(&pki_);
    ASSERT_TRUE(made.ok()) << made.ToString();
  }
  static void TearDownTestSuite() { pki_.reset(); }

  // Starts locatord with TLS (mutual: client certificates required).
  static std::unique_ptr<ServerProcess> StartTls(bool mutual) {
    std::unique_ptr<ServerProcess> server;
    const Status started =
        StartLocatord("uniform:2000:1", pki_->ServerFlags(mutual), &server,
                      pki_->ClientSecurity(/*client_cert=*/mutual));
    EXPECT_TRUE(started.ok()) << started.ToString();
    return server;
  }

  static grpc::Status Locate(const ServerProcess& server,
                             const ChannelSecurity& security) {
    auto stub = NewStub(server, security);
    grpc::ClientContext context;
    SetDeadlineFromNow(&context, std::chrono::seconds(10));
    v1::LocateResponse response;
    return stub->Locate(&context, LocateRequestFor({0.5, 0.5}), &response);
  }

  static std::unique_ptr<TestPki> pki_;
};

std::unique_ptr<TestPki> LocatordTlsTest::pki_;

TEST_F(LocatordTlsTest, TlsClientIsServedAndPlaintextClientIsNot) {
  const std::unique_ptr<ServerProcess> server = StartTls(/*mutual=*/false);
  ASSERT_NE(server, nullptr);
  const grpc::Status tls = Locate(*server, pki_->ClientSecurity(false));
  EXPECT_TRUE(tls.ok()) << tls.error_message();
  EXPECT_EQ(Locate(*server, ChannelSecurity()).error_code(),
            grpc::StatusCode::UNAVAILABLE);
  // The certificate is for localhost and 127.0.0.1, not for this name.
  ChannelSecurity wrong_name = pki_->ClientSecurity(false);
  wrong_name.server_name = "not-the-server.example";
  EXPECT_EQ(Locate(*server, wrong_name).error_code(),
            grpc::StatusCode::UNAVAILABLE);
}

TEST_F(LocatordTlsTest, MutualTlsNeedsTheClientCertificate) {
  const std::unique_ptr<ServerProcess> server = StartTls(/*mutual=*/true);
  ASSERT_NE(server, nullptr);
  const grpc::Status with_cert = Locate(*server, pki_->ClientSecurity(true));
  EXPECT_TRUE(with_cert.ok()) << with_cert.error_message();
  EXPECT_EQ(Locate(*server, pki_->ClientSecurity(false)).error_code(),
            grpc::StatusCode::UNAVAILABLE);
}

TEST_F(LocatordTlsTest, TlsAndTokenTogether) {
  std::vector<std::string> flags = pki_->ServerFlags(/*mutual=*/false);
  flags.insert(flags.end(),
               {"--token-file", WriteFile("tls_token", kDataToken)});
  ChannelSecurity security = pki_->ClientSecurity(false);
  security.bearer_token = kDataToken;
  std::unique_ptr<ServerProcess> server;
  const Status started =
      StartLocatord("uniform:2000:1", flags, &server, security);
  ASSERT_TRUE(started.ok()) << started.ToString();
  EXPECT_TRUE(Locate(*server, security).ok());
  EXPECT_EQ(Locate(*server, pki_->ClientSecurity(false)).error_code(),
            kUnauthenticated);
}

TEST_F(LocatordTlsTest, UnusableCertificateFilesFailStartupNamingTheFile) {
  const std::string garbage = WriteFile("garbage.crt", "-----BEGIN junk\n");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--tls-cert", garbage, "--tls-key", pki_->Path("server.key")},
       "--tls-cert '" + garbage + "': no PEM certificate could be read"},
      {{"--tls-cert", pki_->Path("server.crt"), "--tls-key", "/no/such.key"},
       "--tls-key '/no/such.key': cannot open"},
      {{"--tls-cert", pki_->Path("server.crt"), "--tls-key",
        pki_->Path("client.key")},
       "is not the private key"},
  };
  for (const auto& [flags, message] : cases) {
    ExpectStartupFailure(flags, message);
  }
}

}  // namespace
}  // namespace locator::test
