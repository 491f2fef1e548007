#include "server/http/http_server.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <sys/time.h>

#include <atomic>
#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/write.hpp>
#include <deque>
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
constexpr HttpLimits kLimits{.max_body_bytes = kMaxBody,
                             .max_connections = 512,
                             .max_connections_per_address = 512};

// The HTTP status a handler answers a problem with, as locatord's does.
unsigned ProblemStatus(HttpRequest::Problem problem) {
  switch (problem) {
    case HttpRequest::Problem::kNone:
      return 200;
    case HttpRequest::Problem::kBodyTooLarge:
      return 413;
    case HttpRequest::Problem::kHeaderTooLarge:
      return 431;
    case HttpRequest::Problem::kMalformed:
      return 400;
    default:
      return 503;
  }
}

class HttpServerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Echoes "METHOD PATH?QUERY BODY"; "/missing" is 404, a problem is
    // answered with ProblemStatus, "/later" is answered from another
    // thread, "/held" is kept unanswered in held_ and "/dropped" is never
    // answered.
    const Status started = HttpServer::Start(
        "127.0.0.1", 0, kLimits,
        [this](HttpRequest request, locator::HttpReply reply) {
          ++handled_;
          if (request.problem != HttpRequest::Problem::kNone) {
            reply(HttpResponse{ProblemStatus(request.problem), "text/plain",
                               request.problem_detail});
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

TEST_F(HttpServerTest,
       OversizedHeadersOrMalformedRequestsAreAnsweredAndClosed) {
  // Whatever the client sends after the header is dropped: the answer still
  // arrives whole (no reset), and the connection closes after it.
  const std::string huge_header =
      "GET / HTTP/1.1\r\nHost: x\r\nX-Big: " + std::string(100 * 1024, 'a') +
      "\r\n\r\n";
  const struct {
    std::string request;
    std::string answer;
  } cases[] = {
      {huge_header, "HTTP/1.1 431 "},
      {"NOT HTTP AT ALL\r\n\r\n", "HTTP/1.1 400 "},
      {"POST / HTTP/1.1\r\nHost: x\r\n"
       "Content-Length: 99999999999999999999\r\n\r\nabc",
       "HTTP/1.1 400 "},
      {"POST / HTTP/1.1\r\nHost: x\r\nTransfer-Encoding: chunked\r\n\r\n"
       "zz\r\nabc\r\n0\r\n\r\n",
       "HTTP/1.1 400 "},
  };
  for (const auto& [request, answer] : cases) {
    std::string received;
    ASSERT_TRUE(RawExchange(server_->port(), request, &received).ok());
    EXPECT_THAT(received, StartsWith(answer)) << request.substr(0, 60);
    EXPECT_THAT(received, HasSubstr("Connection: close\r\n"));
  }
  EXPECT_EQ(handled_.load(), 4);
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

// A server of 4 connections, 3 per client address, whose handler holds
// "/held" unanswered (a busy connection) and answers everything else with
// the problem's status or 200.
class HttpServerLimitsTest : public ::testing::Test {
 protected:
  static constexpr HttpLimits kSmall{.max_body_bytes = kMaxBody,
                                     .max_connections = 4,
                                     .max_connections_per_address = 3};

  void SetUp() override {
    ASSERT_TRUE(HttpServer::Start(
                    "127.0.0.1", 0, kSmall,
                    [this](HttpRequest request, locator::HttpReply reply) {
                      if (request.path == "/held") {
                        MutexLock lock(&mu_);
                        held_.push_back(std::move(reply));
                        held_changed_.Signal();
                        return;
                      }
                      reply(HttpResponse{ProblemStatus(request.problem),
                                         "text/plain", request.problem_detail});
                    },
                    &server_)
                    .ok());
  }

  // A connection from `from` that has sent nothing; it reads with a
  // timeout, so that a test expecting it closed cannot hang.
  boost::asio::ip::tcp::socket& OpenIdle(const char* from) {
    auto& socket = idle_.emplace_back(io_);
    socket.open(boost::asio::ip::tcp::v4());
    socket.bind({boost::asio::ip::make_address(from), 0});
    socket.connect({boost::asio::ip::make_address("127.0.0.1"),
                    static_cast<unsigned short>(server_->port())});
    const timeval timeout{.tv_sec = 10, .tv_usec = 0};
    setsockopt(socket.native_handle(), SOL_SOCKET, SO_RCVTIMEO, &timeout,
               sizeof(timeout));
    return socket;
  }

  // Whether the server closed `socket` (it reads end of file).
  static bool ClosedByServer(boost::asio::ip::tcp::socket& socket) {
    char byte;
    boost::system::error_code error;
    socket.read_some(boost::asio::buffer(&byte, 1), error);
    return error == boost::asio::error::eof;
  }

  void WaitUntilHeld(size_t count) {
    MutexLock lock(&mu_);
    while (held_.size() < count) held_changed_.Wait(&mu_);
  }

  // A whole exchange from `from`: all the server sent.
  std::string Get(const char* from, const char* path = "/x") {
    std::string received;
    EXPECT_TRUE(RawExchange(server_->port(),
                            std::string("GET ") + path +
                                " HTTP/1.1\r\nHost: x\r\n"
                                "Connection: close\r\n\r\n",
                            &received, from)
                    .ok());
    return received;
  }

  Mutex mu_;
  std::vector<locator::HttpReply> held_ GUARDED_BY(mu_);
  CondVar held_changed_;
  boost::asio::io_context io_;
  std::deque<boost::asio::ip::tcp::socket> idle_;
  std::unique_ptr<HttpServer> server_;
};

TEST_F(HttpServerLimitsTest, OneAddressGetsItsShareAnd503Beyond) {
  for (int i = 0; i < 3; ++i) OpenIdle("127.0.0.1");
  // The fourth from the same address is refused with an answer, not a
  // reset; another address is still served.
  const std::string refused = Get("127.0.0.1");
  EXPECT_THAT(refused, StartsWith("HTTP/1.1 503 "));
  EXPECT_THAT(refused, HasSubstr("Connection: close\r\n"));
  EXPECT_THAT(refused, HasSubstr("127.0.0.1"));  // the client's address
  EXPECT_THAT(Get("127.0.0.2"), StartsWith("HTTP/1.1 200 "));
  // Its idle connections were not shed for it.
  for (auto& socket : idle_) EXPECT_TRUE(socket.is_open());
}

TEST_F(HttpServerLimitsTest, AtTheLimitTheLongestIdleConnectionIsShed) {
  OpenIdle("127.0.0.2");
  OpenIdle("127.0.0.3");
  OpenIdle("127.0.0.3");
  OpenIdle("127.0.0.4");
  // All 4 are open and idle: a new client is served, and the connection
  // idle longest (the first) made room.
  EXPECT_THAT(Get("127.0.0.1"), StartsWith("HTTP/1.1 200 "));
  EXPECT_TRUE(ClosedByServer(idle_[0]));
}

TEST_F(HttpServerLimitsTest, WhenEveryConnectionIsBusyANewOneGets503) {
  std::vector<std::thread> clients;
  for (const char* from :
       {"127.0.0.2", "127.0.0.3", "127.0.0.4", "127.0.0.5"}) {
    clients.emplace_back([this, from] {
      EXPECT_THAT(Get(from, "/held"), StartsWith("HTTP/1.1 200 "));
    });
  }
  WaitUntilHeld(4);
  EXPECT_THAT(Get("127.0.0.1"), StartsWith("HTTP/1.1 503 "));
  {
    MutexLock lock(&mu_);
    for (locator::HttpReply& reply : held_) reply(HttpResponse{});
  }
  for (std::thread& client : clients) client.join();
  EXPECT_THAT(Get("127.0.0.1"), StartsWith("HTTP/1.1 200 "));
}

TEST(HttpServerStartTest, AnAddressInUseFails) {
  std::unique_ptr<HttpServer> first, second;
  const auto handler = [](HttpRequest, locator::HttpReply reply) {
    reply(HttpResponse{});
  };
  ASSERT_TRUE(HttpServer::Start("127.0.0.1", 0, kLimits, handler, &first).ok());
  const Status status =
      HttpServer::Start("127.0.0.1", first->port(), kLimits, handler, &second);
  EXPECT_EQ(status.code(), Status::Code::kIOError);
  EXPECT_THAT(status.message(), HasSubstr("cannot listen on 127.0.0.1:"));
  EXPECT_EQ(second, nullptr);
  EXPECT_FALSE(
      HttpServer::Start("no.such.host.invalid", 0, kLimits, handler, &second)
          .ok());
}

}  // namespace
}  // namespace locator
