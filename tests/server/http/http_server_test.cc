#include "server/http/http_server.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <memory>
#include <string>
#include <vector>

#include "tests/server/http/http_test_client.h"

namespace locator {
namespace {

using test::HttpGet;
using test::HttpReply;
using test::HttpRequest;
using test::RawExchange;
using ::testing::HasSubstr;
using ::testing::StartsWith;

class HttpServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Echoes the path; "/missing" is 404.
    const Status started = HttpServer::Start(
        "127.0.0.1", 0,
        [this](std::string_view path) {
          ++handled_;
          if (path == "/missing") return HttpResponse{404, "text/plain", "no"};
          return HttpResponse{200, "text/x-echo", std::string(path)};
        },
        &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
  }

  std::atomic<int> handled_{0};
  std::unique_ptr<HttpServer> server_;
};

TEST_F(HttpServerTest, GetReachesTheHandlerWithoutTheQuery) {
  HttpReply reply;
  ASSERT_TRUE(HttpGet(server_->port(), "/a/b?x=1&y=2", &reply).ok());
  EXPECT_EQ(reply.status, 200u);
  EXPECT_EQ(reply.body, "/a/b");
  EXPECT_EQ(reply.headers["content-type"], "text/x-echo");
  EXPECT_EQ(reply.headers["cache-control"], "no-store");
  ASSERT_TRUE(HttpGet(server_->port(), "/missing", &reply).ok());
  EXPECT_EQ(reply.status, 404u);
}

TEST_F(HttpServerTest, HeadGetsHeadersOnly) {
  HttpReply reply;
  ASSERT_TRUE(HttpRequest(server_->port(), "HEAD", "/four", &reply).ok());
  EXPECT_EQ(reply.status, 200u);
  EXPECT_EQ(reply.headers["content-length"], "5");
  EXPECT_EQ(reply.body, "");
}

TEST_F(HttpServerTest, OtherMethodsAre405WithoutCallingTheHandler) {
  for (const char* method : {"POST", "PUT", "DELETE", "OPTIONS", "PATCH"}) {
    HttpReply reply;
    ASSERT_TRUE(HttpRequest(server_->port(), method, "/x", &reply).ok());
    EXPECT_EQ(reply.status, 405u) << method;
    EXPECT_EQ(reply.headers["allow"], "GET, HEAD");
  }
  EXPECT_EQ(handled_.load(), 0);
}

TEST_F(HttpServerTest, KeepAliveServesSeveralRequestsOnOneConnection) {
  std::string received;
  ASSERT_TRUE(RawExchange(server_->port(),
                          "GET /one HTTP/1.1\r\nHost: x\r\n\r\n"
                          "GET /two HTTP/1.1\r\nHost: x\r\n"
                          "Connection: close\r\n\r\n",
                          &received)
                  .ok());
  EXPECT_THAT(received, StartsWith("HTTP/1.1 200 OK"));
  const size_t second = received.find("HTTP/1.1 200 OK", 1);
  ASSERT_NE(second, std::string::npos) << received;
  EXPECT_THAT(received.substr(0, second), HasSubstr("\r\n\r\n/one"));
  EXPECT_THAT(received.substr(second), HasSubstr("\r\n\r\n/two"));
}

TEST_F(HttpServerTest, OversizedOrMalformedRequestsAreDropped) {
  const std::string huge_header =
      "GET / HTTP/1.1\r\nHost: x\r\nX-Big: " +
      std::string(HttpServer::kMaxHeaderBytes, 'a') + "\r\n\r\n";
  const std::string huge_body =
      "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: " +
      std::to_string(HttpServer::kMaxBodyBytes + 1) + "\r\n\r\n" +
      std::string(HttpServer::kMaxBodyBytes + 1, 'b');
  for (const std::string& request :
       {huge_header, huge_body, std::string("NOT HTTP AT ALL\r\n\r\n")}) {
    std::string received = "unset";
    ASSERT_TRUE(RawExchange(server_->port(), request, &received).ok());
    EXPECT_EQ(received, "") << request.substr(0, 40);
  }
  EXPECT_EQ(handled_.load(), 0);
  // The server still serves.
  HttpReply reply;
  ASSERT_TRUE(HttpGet(server_->port(), "/after", &reply).ok());
  EXPECT_EQ(reply.body, "/after");
}

TEST_F(HttpServerTest, IdleConnectionsDoNotHoldUpOthers) {
  // Connections that send nothing (or half a request) occupy no thread.
  boost::asio::io_context io;
  std::vector<boost::asio::ip::tcp::socket> idle;
  const boost::asio::ip::tcp::endpoint endpoint(
      boost::asio::ip::make_address("127.0.0.1"),
      static_cast<unsigned short>(server_->port()));
  for (int i = 0; i < 100; ++i) {
    idle.emplace_back(io).connect(endpoint);
    if (i % 2 == 0) {
      boost::asio::write(
          idle.back(),
          boost::asio::buffer(std::string_view("GET / HTTP/1.1\r\n")));
    }
  }
  for (int i = 0; i < 20; ++i) {
    HttpReply reply;
    ASSERT_TRUE(
        HttpGet(server_->port(), "/n" + std::to_string(i), &reply).ok());
    EXPECT_EQ(reply.body, "/n" + std::to_string(i));
  }
}

TEST(HttpServerStartTest, AnAddressInUseFails) {
  std::unique_ptr<HttpServer> first, second;
  const auto handler = [](std::string_view) { return HttpResponse{}; };
  ASSERT_TRUE(HttpServer::Start("127.0.0.1", 0, handler, &first).ok());
  const Status status =
      HttpServer::Start("127.0.0.1", first->port(), handler, &second);
  EXPECT_EQ(status.code(), Status::Code::kIOError);
  EXPECT_THAT(status.message(), HasSubstr("cannot listen on 127.0.0.1:"));
  EXPECT_EQ(second, nullptr);
  EXPECT_FALSE(
      HttpServer::Start("no.such.host.invalid", 0, handler, &second).ok());
}

}  // namespace
}  // namespace locator
