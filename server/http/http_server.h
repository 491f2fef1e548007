// HttpServer: a small HTTP/1.1 server (Boost.Beast) for read-only endpoints:
// GET and HEAD only, one handler maps a path to a response.
//
// Owns an io_context, the listening socket, every connection and one thread
// that runs them all, asynchronously, so it never shares a thread with the
// gRPC server and a slow client holds nothing but its own connection.
// Limits: kMaxConnections at once (further ones are closed on accept),
// kMaxHeaderBytes per request header, kMaxBodyBytes per request body,
// kIdleTimeout for a connection waiting for (or sending) a message. Other
// methods get 405 with an Allow header; a malformed or oversized request
// closes the connection. Keep-alive is honoured.
//
// Thread-safety: the handler runs on the server's thread, one request at a
// time; it must be safe to call from there.

#ifndef LOCATOR_SERVER_HTTP_HTTP_SERVER_H_
#define LOCATOR_SERVER_HTTP_HTTP_SERVER_H_

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <thread>

#include "common/status.h"

namespace locator {

struct HttpResponse {
  unsigned status = 200;
  std::string content_type = "text/plain; charset=utf-8";
  std::string body;
};

// Maps a request path (the target without its query string) to a response.
using HttpHandler = std::function<HttpResponse(std::string_view path)>;

class HttpServer {
 public:
  static constexpr size_t kMaxConnections = 512;
  static constexpr size_t kMaxHeaderBytes = 8 * 1024;
  static constexpr size_t kMaxBodyBytes = 8 * 1024;
  static constexpr std::chrono::seconds kIdleTimeout{30};

  // Listens on host:port (port 0: the OS picks) and starts serving with
  // `handler`. IOError naming the address if it cannot be bound.
  static Status Start(const std::string& host, int port, HttpHandler handler,
                      std::unique_ptr<HttpServer>* server);

  // Stops accepting, closes every connection and joins the thread.
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  // The port actually bound.
  int port() const { return port_; }

 private:
  class Connection;

  explicit HttpServer(HttpHandler handler);
  Status Listen(const std::string& host, int port);
  void Accept();

  const HttpHandler handler_;
  // Connections open now; only touched on the server's thread. Declared
  // before io_context_: connections still queued in it decrement it while
  // it is destroyed.
  size_t open_connections_ = 0;
  boost::asio::io_context io_context_;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::steady_timer accept_retry_;
  int port_ = 0;
  std::thread thread_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_HTTP_SERVER_H_
