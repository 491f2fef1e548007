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
#include <thread>
#include <vector>

#include "common/mutex.h"
#include "tests/server/http/http_test_client.h"

namespace locator {
namespace {

using test::HttpGet;
using test::HttpReply;
using test::RawExchange;
using test::SendHttp;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr size_t kMaxBody = 8 * 1024;

class HttpServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Echoes "METHOD PATH?QUERY BODY"; "/missing" is 404, a body over the
    // limit 413, "/later" is answered from another thread, "/held" is kept
    // unanswered in held_ and "/dropped" is never answered.
    const Status started = HttpServer::Start(
        "127.0.0.1", 0, kMaxBody,
        [this](HttpRequest request, locator::HttpReply reply) {
          ++handled_;
          if (request.body_too_large) {
            reply(HttpResponse{413, "text/plain", "too large"});
            return;
          }
          if (request.path == "/held") {
            MutexLock lock(&held_mu_);
            held_.push_back(std::move(reply));
            held_arrived_.Signal();
            return;
          }
          if (request.path == "/dropped") return;
          if (request.path == "/missing") {
            reply(HttpResponse{404, "text/plain", "no"});
            return;
          }
          HttpResponse echo{200, "text/x-echo",
                            request.method + " " + request.path + "?" +
                                request.query + " " + request.body};
          echo.headers.emplace_back(
              "X-Seen", std::string(request.Header("x-test").value_or("")));
          if (request.path == "/later") {
            std::thread([reply, echo] { reply(echo); }).detach();
            return;
          }
          reply(std::move(echo));
        },
        &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
  }

  std::atomic<int> handled_{0};
  Mutex held_mu_;
  // Before server_: these reply functions outlive the server.
  std::vector<locator::HttpReply> held_ GUARDED_BY(held_mu_);
  CondVar held_arrived_;
  std::unique_ptr<HttpServer> server_;
};

TEST_F(HttpServerTest, GetReachesTheHandlerWithItsQuery) {
  HttpReply reply;
  ASSERT_TRUE(HttpGet(server_->port(), "/a/b?x=1&y=2", &reply).ok());
  EXPECT_EQ(reply.status, 200u);
  EXPECT_EQ(reply.body, "GET /a/b?x=1&y=2 ");
  EXPECT_EQ(reply.headers["content-type"], "text/x-echo");
  EXPECT_EQ(reply.headers["cache-control"], "no-store");
  ASSERT_TRUE(HttpGet(server_->port(), "/missing", &reply).ok());
  EXPECT_EQ(reply.status, 404u);
}

TEST_F(HttpServerTest, HeadGetsHeadersOnly) {
  HttpReply reply;
  ASSERT_TRUE(SendHttp(server_->port(), "HEAD", "/four", &reply).ok());
  EXPECT_EQ(reply.status, 200u);
  EXPECT_EQ(reply.headers["content-length"], "11");  // "GET /four? "
  EXPECT_EQ(reply.body, "");
}

TEST_F(HttpServerTest, EveryMethodReachesTheHandlerWithBodyAndHeaders) {
  for (const char* method : {"POST", "PUT", "DELETE", "OPTIONS", "PATCH"}) {
    HttpReply reply;
    ASSERT_TRUE(SendHttp(server_->port(), method, "/x", &reply, "{\"a\":1}",
                         {{"X-Test", "yes"}})
                    .ok());
    EXPECT_EQ(reply.status, 200u) << method;
    EXPECT_EQ(reply.body, std::string(method) + " /x? {\"a\":1}");
    EXPECT_EQ(reply.headers["x-seen"], "yes");
  }
  EXPECT_EQ(handled_.load(), 5);
}

TEST_F(HttpServerTest, RepliesMayComeFromAnotherThread) {
  for (int i = 0; i < 3; ++i) {
    HttpReply reply;
    ASSERT_TRUE(SendHttp(server_->port(), "POST", "/later", &reply, "b").ok());
    EXPECT_EQ(reply.body, "POST /later? b");
  }
}

TEST_F(HttpServerTest, AReplyDroppedUnansweredClosesTheConnection) {
  std::string received;
  ASSERT_TRUE(RawExchange(server_->port(),
                          "GET /dropped HTTP/1.1\r\nHost: x\r\n\r\n", &received)
                  .ok());
  EXPECT_EQ(received, "");
}

TEST_F(HttpServerTest, AReplyMayOutliveTheServer) {
  // A client whose request is held, on a thread of its own: it sees the
  // connection close when the server goes.
  std::thread client([port = server_->port()] {
    std::string received;
    EXPECT_TRUE(
        RawExchange(port, "GET /held HTTP/1.1\r\nHost: x\r\n\r\n", &received)
            .ok());
    EXPECT_EQ(received, "");
  });
  {
    MutexLock lock(&held_mu_);
    while (held_.empty()) held_arrived_.Wait(&held_mu_);
  }
  server_.reset();
  client.join();
  // Answered after the server is gone: dropped. The reply functions are
  // destroyed after the server, too (held_ outlives server_).
  MutexLock lock(&held_mu_);
  held_.front()(HttpResponse{200, "text/plain", "late"});
}

TEST_F(HttpServerTest, ABodyOverTheLimitIsNotReadButAnswered) {
  // With a Content-Length over the limit the body is never read: the
  // handler answers from the header, and the connection drops the body
  // and closes.
  HttpReply reply;
  ASSERT_TRUE(SendHttp(server_->port(), "POST", "/big", &reply,
                       std::string(kMaxBody + 1, 'b'))
                  .ok());
  EXPECT_EQ(reply.status, 413u);
  EXPECT_EQ(reply.headers["connection"], "close");
  // At the limit it is read.
  ASSERT_TRUE(SendHttp(server_->port(), "POST", "/fits", &reply,
                       std::string(kMaxBody, 'b'))
                  .ok());
  EXPECT_EQ(reply.status, 200u);
  EXPECT_EQ(reply.body.size(), std::string("POST /fits? ").size() + kMaxBody);
  // A chunked body that grows over the limit.
  std::string received;
  ASSERT_TRUE(RawExchange(server_->port(),
                          "POST /chunked HTTP/1.1\r\nHost: x\r\n"
                          "Transfer-Encoding: chunked\r\n\r\n"
                          "2001\r\n" +
                              std::string(0x2001, 'c') + "\r\n0\r\n\r\n",
                          &received)
                  .ok());
  EXPECT_THAT(received, StartsWith("HTTP/1.1 413"));
}

TEST_F(HttpServerTest, ExpectContinueIsAnsweredBeforeTheBody) {
  std::string received;
  // The body follows the header at once here, as from a client that does
  // not wait; the interim answer still comes before the final one.
  ASSERT_TRUE(RawExchange(server_->port(),
                          "POST /e HTTP/1.1\r\nHost: x\r\n"
                          "Expect: 100-continue\r\nContent-Length: 2\r\n"
                          "Connection: close\r\n\r\nok",
                          &received)
                  .ok());
  EXPECT_THAT(received, StartsWith("HTTP/1.1 100 Continue\r\n\r\n"
                                   "HTTP/1.1 200 OK"));
  EXPECT_THAT(received, HasSubstr("POST /e? ok"));
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
  EXPECT_THAT(received.substr(0, second), HasSubstr("\r\n\r\nGET /one? "));
  EXPECT_THAT(received.substr(second), HasSubstr("\r\n\r\nGET /two? "));
}

TEST_F(HttpServerTest, OversizedHeadersOrMalformedRequestsAreDropped) {
  const std::string huge_header =
      "GET / HTTP/1.1\r\nHost: x\r\nX-Big: " +
      std::string(HttpServer::kMaxHeaderBytes, 'a') + "\r\n\r\n";
  for (const std::string& request :
       {huge_header, std::string("NOT HTTP AT ALL\r\n\r\n")}) {
    std::string received = "unset";
    ASSERT_TRUE(RawExchange(server_->port(), request, &received).ok());
    EXPECT_EQ(received, "") << request.substr(0, 40);
  }
  EXPECT_EQ(handled_.load(), 0);
  // The server still serves.
  HttpReply reply;
  ASSERT_TRUE(HttpGet(server_->port(), "/after", &reply).ok());
  EXPECT_EQ(reply.body, "GET /after? ");
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
    EXPECT_EQ(reply.body, "GET /n" + std::to_string(i) + "? ");
  }
}

TEST(HttpServerStartTest, AnAddressInUseFails) {
  std::unique_ptr<HttpServer> first, second;
  const auto handler = [](HttpRequest, locator::HttpReply reply) {
    reply(HttpResponse{});
  };
  ASSERT_TRUE(
      HttpServer::Start("127.0.0.1", 0, kMaxBody, handler, &first).ok());
  const Status status =
      HttpServer::Start("127.0.0.1", first->port(), kMaxBody, handler, &second);
  EXPECT_EQ(status.code(), Status::Code::kIOError);
  EXPECT_THAT(status.message(), HasSubstr("cannot listen on 127.0.0.1:"));
  EXPECT_EQ(second, nullptr);
  EXPECT_FALSE(
      HttpServer::Start("no.such.host.invalid", 0, kMaxBody, handler, &second)
          .ok());
}

}  // namespace
}  // namespace locator
