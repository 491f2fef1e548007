#include "tests/server/http/status_e2e_support.h"

#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "tests/server/http/http_test_client.h"

namespace locator::test {
namespace {

constexpr auto kServingTimeout = std::chrono::seconds(60);
constexpr auto kPollInterval = std::chrono::milliseconds(20);

}  // namespace

Status LocatordWithHttp::Start(const std::string& dataset,
                               const std::vector<std::string>& flags,
                               std::unique_ptr<LocatordWithHttp>* server,
                               const std::string& data_token) {
  std::vector<std::string> args = {"--dataset",     dataset,
                                   "--listen",      "127.0.0.1:0",
                                   "--http-listen", "127.0.0.1:0"};
  args.insert(args.end(), flags.begin(), flags.end());
  std::unique_ptr<LocatordWithHttp> started(new LocatordWithHttp());
  started->data_token_ = data_token;
  Status status = ServerProcess::Spawn(LOCATORD_PATH, args, &started->process_);
  if (status.ok()) status = started->process_->WaitForListening();
  if (!status.ok()) return status;
  started->grpc_target_ = started->process_->target();
  status = started->process_->WaitForListening();
  if (!status.ok()) return status;
  started->http_port_ = started->process_->port();
  status = started->WaitUntilServes("");
  if (!status.ok()) return status;
  *server = std::move(started);
  return Status::OK();
}

Status LocatordWithHttp::WaitUntilServes(const std::string& dataset) {
  const std::string target = "/api/stats?dataset=" + dataset;
  const auto deadline = std::chrono::steady_clock::now() + kServingTimeout;
  for (;;) {
    HttpReply reply;
    HttpHeaders headers;
    if (!data_token_.empty()) {
      headers.emplace_back("Authorization", "Bearer " + data_token_);
    }
    if (SendHttp(http_port_, "GET", target, &reply, "", headers).ok() &&
        reply.status == 200) {
      return Status::OK();
    }
    if (process_->WaitForExit(std::chrono::milliseconds(0)) ||
        std::chrono::steady_clock::now() > deadline) {
      return Status::Unavailable("locatord did not serve '" + dataset +
                                 "'; stderr:\n" + process_->StderrText());
    }
    std::this_thread::sleep_for(kPollInterval);
  }
}

std::unique_ptr<v1::Locator::Stub> LocatordWithHttp::NewStub() const {
  return v1::Locator::NewStub(
      grpc::CreateChannel(grpc_target_, grpc::InsecureChannelCredentials()));
}

JsonValue GetJson(int port, const std::string& target) {
  HttpReply reply;
  const Status fetched = HttpGet(port, target, &reply);
  EXPECT_TRUE(fetched.ok()) << fetched.ToString();
  EXPECT_EQ(reply.headers["content-type"], "application/json");
  JsonValue json;
  const Status parsed = ParseJson(reply.body, &json);
  EXPECT_TRUE(parsed.ok()) << parsed.ToString() << "\n" << reply.body;
  return json;
}

}  // namespace locator::test
