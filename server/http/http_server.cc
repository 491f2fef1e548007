#include "server/http/http_server.h"

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <optional>
#include <utility>

namespace locator {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

// After a failed accept (e.g. out of file descriptors), wait this long
// before the next: retrying at once would spin the thread.
constexpr auto kAcceptRetryDelay = std::chrono::milliseconds(100);

// "[::1]" -> "::1": --listen style hosts may bracket IPv6 addresses.
std::string Unbracketed(const std::string& host) {
  if (host.size() >= 2 && host.front() == '[' && host.back() == ']') {
    return host.substr(1, host.size() - 2);
  }
  return host;
}

}  // namespace

// One client connection: reads a request, writes the response, and repeats
// while the client keeps the connection alive. Owned by the completion
// handlers in flight (shared_from_this), so it lives exactly as long as it
// has work queued.
class HttpServer::Connection : public std::enable_shared_from_this<Connection> {
 public:
  Connection(HttpServer* server, tcp::socket socket)
      : server_(server), stream_(std::move(socket)) {
    ++server_->open_connections_;
  }
  ~Connection() { --server_->open_connections_; }

  void Read() {
    parser_.emplace();
    parser_->header_limit(kMaxHeaderBytes);
    parser_->body_limit(kMaxBodyBytes);
    stream_.expires_after(kIdleTimeout);
    http::async_read(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code error, size_t) {
          // Closed, timed out, malformed or over a limit: drop the
          // connection (the destructor closes the socket).
          if (!error) self->Write(self->parser_->release());
        });
  }

 private:
  void Write(const http::request<http::string_body>& request) {
    response_ = Respond(request);
    stream_.expires_after(kIdleTimeout);
    http::async_write(
        stream_, response_,
        [self = shared_from_this()](beast::error_code error, size_t) {
          if (error) return;
          if (!self->response_.keep_alive()) {
            beast::error_code ignored;
            self->stream_.socket().shutdown(tcp::socket::shutdown_send,
                                            ignored);
            return;
          }
          self->Read();
        });
  }

  http::response<http::string_body> Respond(
      const http::request<http::string_body>& request) const {
    http::response<http::string_body> response;
    response.version(request.version());
    response.keep_alive(request.keep_alive());
    response.set(http::field::server, "locatord");
    response.set(http::field::cache_control, "no-store");
    const bool head = request.method() == http::verb::head;
    if (request.method() == http::verb::get || head) {
      const std::string_view target(request.target().data(),
                                    request.target().size());
      HttpResponse reply =
          server_->handler_(target.substr(0, target.find('?')));
      response.result(reply.status);
      response.set(http::field::content_type, reply.content_type);
      response.body() = std::move(reply.body);
    } else {
      response.result(http::status::method_not_allowed);
      response.set(http::field::allow, "GET, HEAD");
      response.set(http::field::content_type, "text/plain; charset=utf-8");
      response.body() = "method not allowed\n";
    }
    response.prepare_payload();
    // HEAD: the GET's headers, Content-Length included, and no body.
    if (head) response.body().clear();
    return response;
  }

  HttpServer* const server_;
  beast::tcp_stream stream_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  http::response<http::string_body> response_;  // kept alive while written
};

HttpServer::HttpServer(HttpHandler handler)
    : handler_(std::move(handler)),
      acceptor_(io_context_),
      accept_retry_(io_context_) {}

Status HttpServer::Start(const std::string& host, int port, HttpHandler handler,
                         std::unique_ptr<HttpServer>* server) {
  std::unique_ptr<HttpServer> created(new HttpServer(std::move(handler)));
  if (Status status = created->Listen(host, port); !status.ok()) {
    return status;
  }
  created->Accept();
  created->thread_ =
      std::thread([raw = created.get()] { raw->io_context_.run(); });
  *server = std::move(created);
  return Status::OK();
}

Status HttpServer::Listen(const std::string& host, int port) {
  const auto failure = [&](const beast::error_code& error) {
    return Status::IOError("cannot listen on " + host + ":" +
                           std::to_string(port) + ": " + error.message());
  };
  beast::error_code error;
  tcp::resolver resolver(io_context_);
  const auto endpoints = resolver.resolve(
      Unbracketed(host), std::to_string(port),
      tcp::resolver::passive | tcp::resolver::numeric_service, error);
  if (error) return failure(error);
  const tcp::endpoint endpoint = endpoints.begin()->endpoint();
  acceptor_.open(endpoint.protocol(), error);
  if (!error) {
    acceptor_.set_option(asio::socket_base::reuse_address(true), error);
  }
  if (!error) acceptor_.bind(endpoint, error);
  if (!error)
    acceptor_.listen(asio::socket_base::max_listen_connections, error);
  if (error) return failure(error);
  port_ = acceptor_.local_endpoint().port();
  return Status::OK();
}

HttpServer::~HttpServer() {
  io_context_.stop();
  if (thread_.joinable()) thread_.join();
}

void HttpServer::Accept() {
  acceptor_.async_accept([this](beast::error_code error, tcp::socket socket) {
    if (error == asio::error::operation_aborted) return;  // stopping
    if (error) {
      accept_retry_.expires_after(kAcceptRetryDelay);
      accept_retry_.async_wait([this](beast::error_code wait_error) {
        if (!wait_error) Accept();
      });
      return;
    }
    // Over the limit the socket is closed as it goes out of scope.
    if (open_connections_ < kMaxConnections) {
      std::make_shared<Connection>(this, std::move(socket))->Read();
    }
    Accept();
  });
}

}  // namespace locator
