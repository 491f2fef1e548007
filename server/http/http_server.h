// HttpServer: a small HTTP/1.1 server (Boost.Beast): every request, whatever
// its method, goes to one asynchronous handler, which answers it through
// the reply function it is given, from any thread.
//
// Owns an io_context, the listening socket, every connection and one thread
// that runs them all, asynchronously, so it never shares a thread with the
// gRPC server and a slow client holds nothing but its own connection.
// Limits: kMaxConnections at once (further ones are closed on accept),
// kMaxHeaderBytes per request header, HttpOptions::max_body_bytes per
// request body, kIdleTimeout for a connection waiting for (or sending) a
// message. A body over the limit is not read: the handler gets the request
// with body_too_large set and an empty body, and after its answer the
// connection reads and drops what the client still sends (up to
// kMaxLingerBytes, for at most kLingerTimeout, so that the client gets to
// read the answer) and closes. "Expect: 100-continue" is answered before the
// body is read. HEAD reaches the handler as GET, and its answer goes out
// without the body. A malformed request closes the connection. Keep-alive is
// honoured.
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
#include "common/status.h"

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
  // The body was over the limit and was not read.
  bool body_too_large = false;

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

struct HttpOptions {
  // Larger request bodies are not read (see above).
  size_t max_body_bytes = size_t{16} << 20;
  // Origins allowed to call the server from web pages (CORS; see
  // CorsPolicy); empty: CORS off.
  std::vector<std::string> cors_origins;
};

class HttpServer {
 public:
  static constexpr size_t kMaxConnections = 512;
  static constexpr size_t kMaxHeaderBytes = 8 * 1024;
  static constexpr std::chrono::seconds kIdleTimeout{30};
  static constexpr size_t kMaxLingerBytes = size_t{64} << 20;
  static constexpr std::chrono::seconds kLingerTimeout{5};

  // Listens on host:port (port 0: the OS picks) and starts serving with
  // `handler`, reading bodies up to `max_body_bytes`. IOError naming the
  // address if it cannot be bound.
  static Status Start(const std::string& host, int port, size_t max_body_bytes,
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

  HttpServer(size_t max_body_bytes, HttpHandler handler);
  Status Listen(const std::string& host, int port);
  void Accept();
  // Server's thread: keeps `connection` until its reply; returns the reply
  // function that answers it.
  HttpReply AwaitReply(std::shared_ptr<Connection> connection);
  // Server's thread: answers, or closes, the connection awaiting reply `id`.
  void Answer(uint64_t id, HttpResponse response);
  void Abandon(uint64_t id);

  const size_t max_body_bytes_;
  const HttpHandler handler_;
  // Connections open now; only touched on the server's thread. Declared
  // before io_context_: connections still queued in it decrement it while
  // it is destroyed.
  size_t open_connections_ = 0;
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
