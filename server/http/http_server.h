// HttpServer: a small HTTP/1.1 server (Boost.Beast): every request, whatever
// its method, goes to one asynchronous handler, which answers it through
// the reply function it is given, from any thread.
//
// Owns an io_context, the listening socket, every connection and one thread
// that runs them all, asynchronously, so it never shares a thread with the
// gRPC server and a slow client holds nothing but its own connection.
//
// Limits (HttpLimits): at most max_connections open and
// max_connections_per_address from one client address (ConnectionTable:
// when all are open, the connection idle longest is shed for a new one);
// kMaxHeaderBytes per request header, max_body_bytes per request body,
// kIdleTimeout for a connection waiting for (or sending) a message.
//
// A request that cannot be served as sent still reaches the handler, with
// HttpRequest::problem set, so that every client gets an answer rather than
// a reset: a body over the limit (not read: the handler gets the header
// and an empty body), a header over the limit, a malformed request (an
// absurd Content-Length, a bad request line), and a connection refused by
// the limits above (an empty request, answered before anything is read; at
// most kMaxRefusing of these at once, further ones are closed). After such
// an answer the connection reads and drops what the client still sends (up
// to kMaxLingerBytes, for at most kLingerTimeout, so that the client gets to
// read the answer) and closes. "Expect: 100-continue" is answered before
// the body is read. HEAD reaches the handler as GET, and its answer goes
// out without the body. Keep-alive is honoured. After writing a body of at
// least kTrimAfterBytes the server returns freed memory to the system
// (ReturnFreedMemory): glibc would otherwise keep a large reply's pages.
//
// Thread-safety: the handler is called on the server's thread, one request
// at a time, and must return quickly; the reply function may be called from
// any thread, at most once per request, and may outlive the server: a reply
// after the server is destroyed is dropped. A reply function destroyed
// without being called closes the request's connection.

#ifndef LOCATOR_SERVER_HTTP_HTTP_SERVER_H_
#define LOCATOR_SERVER_HTTP_HTTP_SERVER_H_

#include <array>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

#include "common/mutex.h"
#include "locator/status.h"
#include "server/http/connection_table.h"

namespace locator {

struct HttpRequest {
  // As sent ("GET", "POST", "OPTIONS", ...), except that HEAD arrives as GET.
  std::string method;
  // The target up to '?', and what follows it (undecoded; "" if none).
  std::string path;
  std::string query;
  // Header fields as sent, names in lower case.
  std::vector<std::pair<std::string, std::string>> headers;
  std::string body;

  // What kept the request from being read whole (see above); the
  // connection closes after its answer.
  enum class Problem {
    kNone,
    kBodyTooLarge,    // the header is there, the body was not read
    kHeaderTooLarge,  // nothing else is there
    kMalformed,       // nothing else is there; problem_detail says what
    kAddressFull,     // refused: the client address has its share open
    kServerBusy,      // refused: every connection is busy
  };
  Problem problem = Problem::kNone;
  // For kMalformed, the parser's complaint; for the refusals, the client's
  // address.
  std::string problem_detail;

  // The value of header `name` (lower case), or nullopt.
  std::optional<std::string_view> Header(std::string_view name) const;
};

struct HttpResponse {
  unsigned status = 200;
  std::string content_type = "text/plain; charset=utf-8";
  std::string body;
  // More header fields (e.g. Allow, Access-Control-*).
  std::vector<std::pair<std::string, std::string>> headers = {};
};

// Answers one request; call once, from any thread (see above).
using HttpReply = std::function<void(HttpResponse response)>;
// Handles one request (see the thread-safety note above).
using HttpHandler = std::function<void(HttpRequest request, HttpReply reply)>;

struct HttpLimits {
  // Larger request bodies are not read (see above).
  size_t max_body_bytes = size_t{16} << 20;
  // Connections open at once, in all and from one client address.
  size_t max_connections = 512;
  size_t max_connections_per_address = 64;
};

class HttpServer {
 public:
  static constexpr size_t kMaxHeaderBytes = 8 * 1024;
  static constexpr std::chrono::seconds kIdleTimeout{30};
  static constexpr size_t kMaxLingerBytes = size_t{64} << 20;
  static constexpr std::chrono::seconds kLingerTimeout{5};
  static constexpr size_t kMaxRefusing = 64;
  static constexpr size_t kTrimAfterBytes = size_t{1} << 20;

  // Listens on host:port (port 0: the OS picks) and starts serving with
  // `handler` within `limits`. IOError naming the address if it cannot be
  // bound.
  static Status Start(const std::string& host, int port, HttpLimits limits,
                      HttpHandler handler, std::unique_ptr<HttpServer>* server);

  // Stops accepting, closes every connection and joins the thread.
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  // The port actually bound.
  int port() const { return port_; }

 private:
  class Connection;
  class ReplyTicket;

  // Lets reply functions on any thread post to the io_context while the
  // server lives, and makes them drop their work once it is closed.
  class ReplyGate {
   public:
    explicit ReplyGate(boost::asio::io_context* io_context)
        : io_context_(io_context) {}
    // Runs `work` on the server's thread, unless the gate is closed.
    void Post(std::function<void()> work) EXCLUDES(mu_);
    // After this, Post drops its work; called before the io_context stops.
    void Close() EXCLUDES(mu_);

   private:
    Mutex mu_;
    boost::asio::io_context* io_context_ GUARDED_BY(mu_);  // null: closed
  };

  HttpServer(HttpLimits limits, HttpHandler handler);
  Status Listen(const std::string& host, int port);
  void Accept();
  // Server's thread: opens a connection on `socket`, or answers it with
  // the refusal, as the connection table decides.
  void Open(boost::asio::ip::tcp::socket socket);
  // Server's thread: keeps `connection` until its reply; returns the reply
  // function that answers it.
  HttpReply AwaitReply(std::shared_ptr<Connection> connection);
  // Server's thread: answers, or closes, the connection awaiting reply `id`.
  void Answer(uint64_t id, HttpResponse response);
  void Abandon(uint64_t id);

  const HttpLimits limits_;
  const HttpHandler handler_;
  // The connections open now, and the refused ones still being answered;
  // only touched on the server's thread. Declared before io_context_:
  // connections still queued in it leave them while it is destroyed.
  ConnectionTable connections_;
  size_t refusing_ = 0;
  boost::asio::io_context io_context_;
  const std::shared_ptr<ReplyGate> reply_gate_;
  // Connections waiting for their handler's reply, by reply id; only
  // touched on the server's thread. After io_context_: their sockets are
  // closed before it is destroyed.
  std::unordered_map<uint64_t, std::shared_ptr<Connection>> awaiting_reply_;
  uint64_t next_reply_id_ = 0;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer accept_retry_;
  int port_ = 0;
  // Where lingering connections drop what they read (only on the thread).
  std::array<char, 16384> linger_buffer_;
  std::thread thread_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_HTTP_SERVER_H_
