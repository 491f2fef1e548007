// The security flags' files: tokens and PEM certificates are read once at
// startup; every problem fails naming the flag and the file.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "common/credential_files.h"
#include "server/config/server_config.h"
#include "tests/testing/test_pki.h"

namespace locator {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "security_config_" +
                           std::to_string(getpid()) + "_" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

Status Parse(std::vector<std::string> args, ServerConfig* config) {
  args.insert(args.begin(), "locatord");
  std::vector<const char*> argv;
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  std::string help;
  return ParseServerConfig(static_cast<int>(argv.size()), argv.data(), config,
                           &help);
}

TEST(TokenFileTest, OneTrailingNewlineIsTrimmed) {
  for (const char* text : {"s3cret\n", "s3cret\r\n", "s3cret"}) {
    std::string token;
    ASSERT_TRUE(
        ReadTokenFile("token-file", WriteFile("token", text), &token).ok());
    EXPECT_EQ(token, "s3cret");
  }
}

TEST(TokenFileTest, UnusableFilesFailNamingFlagAndFile) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "empty"},
      {"\n", "the token is empty"},
      {"two words\n", "printable ASCII without spaces"},
      {"line\nline\n", "printable ASCII without spaces"},
      {std::string(kMaxCredentialFileBytes + 1, 'x'), "larger than 1 MiB"},
  };
  for (const auto& [text, problem] : cases) {
    const std::string path = WriteFile("bad_token", text);
    std::string token;
    const Status status = ReadTokenFile("token-file", path, &token);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
    EXPECT_THAT(status.message(), HasSubstr("--token-file '" + path + "'"));
    EXPECT_THAT(status.message(), HasSubstr(problem));
    EXPECT_THAT(status.message(), Not(HasSubstr("word"))) << "leaks the token";
  }
  std::string token;
  EXPECT_THAT(ReadTokenFile("token-file", "/no/such/file", &token).message(),
              HasSubstr("'/no/such/file': cannot open"));
}

TEST(TokenFileTest, DataAndAdminTokensMustDiffer) {
  const std::string same = WriteFile("same", "t0ken\n");
  ServerConfig config;
  const Status status =
      Parse({"--token-file", same, "--admin-token-file", same}, &config);
  EXPECT_THAT(status.message(), HasSubstr("the same token"));
  ASSERT_TRUE(Parse({"--token-file", same, "--admin-token-file",
                     WriteFile("other", "0ther\n")},
                    &config)
                  .ok());
  EXPECT_EQ(config.access.data_token, "t0ken");
  EXPECT_EQ(config.access.admin_token, "0ther");
}

class TlsFlagsTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const Status made = test::TestPki::Create(&pki_);
    ASSERT_TRUE(made.ok()) << made.ToString();
  }
  static void TearDownTestSuite() { pki_.reset(); }

  static std::unique_ptr<test::TestPki> pki_;
};

std::unique_ptr<test::TestPki> TlsFlagsTest::pki_;

TEST_F(TlsFlagsTest, GoodFilesAreRead) {
  ServerConfig config;
  const Status status = Parse(pki_->ServerFlags(/*mutual=*/true), &config);
  ASSERT_TRUE(status.ok()) << status.ToString();
  const TlsConfig& tls = config.serving.transport.tls;
  EXPECT_TRUE(tls.enabled());
  EXPECT_THAT(tls.cert_chain_pem, HasSubstr("BEGIN CERTIFICATE"));
  EXPECT_THAT(tls.private_key_pem, HasSubstr("PRIVATE KEY"));
  EXPECT_THAT(tls.client_ca_pem, HasSubstr("BEGIN CERTIFICATE"));
}

TEST_F(TlsFlagsTest, BadFilesFailNamingTheFile) {
  const std::string garbage = WriteFile("garbage.pem", "not a certificate\n");
  const std::string cert = pki_->Path("server.crt");
  const std::string key = pki_->Path("server.key");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--tls-cert", garbage, "--tls-key", key},
       "--tls-cert '" + garbage + "': no PEM certificate"},
      {{"--tls-cert", cert, "--tls-key", garbage},
       "--tls-key '" + garbage + "': no unencrypted PEM private key"},
      {{"--tls-cert", key, "--tls-key", key}, "--tls-cert '" + key + "'"},
      {{"--tls-cert", cert, "--tls-key", pki_->Path("client.key")},
       "is not the private key of the first certificate in --tls-cert '" +
           cert + "'"},
      {{"--tls-cert", cert, "--tls-key", "/no/such.key"},
       "--tls-key '/no/such.key': cannot open"},
      {{"--tls-cert", cert, "--tls-key", key, "--tls-client-ca", garbage},
       "--tls-client-ca '" + garbage + "'"},
      {{"--tls-key", key}, "give both or neither"},
  };
  for (const auto& [args, message] : cases) {
    ServerConfig config;
    const Status status = Parse(args, &config);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << message;
    EXPECT_THAT(status.message(), HasSubstr(message));
  }
}

}  // namespace
}  // namespace locator
