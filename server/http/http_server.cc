#include "server/http/http_server.h"

#include <atomic>
#include <boost/asio/post.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <cctype>
#include <optional>
#include <utility>

#include "common/freed_memory.h"

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

// Whether `error` is the parser's complaint about what the client sent (as
// opposed to the client closing or the connection failing).
bool IsParseError(const beast::error_code& error) {
  return error.category() ==
             http::make_error_code(http::error::bad_method).category() &&
         error != http::error::end_of_stream &&
         error != http::error::partial_message;
}

// The client's address, IPv4-mapped IPv6 addresses as IPv4 ("" if the
// socket has none: it is already closed).
std::string ClientAddress(const tcp::socket& socket) {
  beast::error_code error;
  asio::ip::address address = socket.remote_endpoint(error).address();
  if (error) return "";
  if (address.is_v6() && address.to_v6().is_v4_mapped()) {
    address = asio::ip::make_address_v4(asio::ip::v4_mapped, address.to_v6());
  }
  return address.to_string();
}

}  // namespace

// One client connection: reads a request, hands it to the handler, writes
// its reply, and repeats while the client keeps the connection alive. Owned
// by the completion handlers in flight (shared_from_this) or, while the
// handler works, by the server's awaiting_reply_, so it lives exactly as
// long as it has work pending and never outlives the server. It is in the
// server's connection table from Read() on (a refused one never is) and
// idle there while it waits for a request header. Its members are only
// touched on the server's thread.
class HttpServer::Connection final
    : public std::enable_shared_from_this<Connection>,
      public ConnectionTable::Member {
 public:
  Connection(HttpServer* server, tcp::socket socket, std::string address)
      : server_(server),
        stream_(std::move(socket)),
        address_(std::move(address)) {}
  ~Connection() {
    server_->connections_.Close(this);
    if (refused_) --server_->refusing_;
  }

  const std::string& address() const { return address_; }

  void Read() {
    parser_.emplace();
    parser_->header_limit(kMaxHeaderBytes);
    parser_->body_limit(server_->limits_.max_body_bytes);
    stream_.expires_after(kIdleTimeout);
    server_->connections_.SetIdle(this, true);
    http::async_read_header(
        stream_, buffer_, *parser_,
        [self = shared_from_this()](beast::error_code error, size_t) {
          self->server_->connections_.SetIdle(self.get(), false);
          // A Content-Length over the body limit fails here, with the
          // header read. Closed, timed out or shed: drop the connection
          // (the destructor closes the socket).
          if (error == http::error::body_limit) {
            self->Dispatch(HttpRequest::Problem::kBodyTooLarge);
          } else if (error == http::error::header_limit) {
            self->DispatchProblem(HttpRequest::Problem::kHeaderTooLarge, "");
          } else if (IsParseError(error)) {
            self->DispatchProblem(HttpRequest::Problem::kMalformed,
                                  error.message());
          } else if (!error) {
            self->ReadBody();
          }
        });
  }

  // Answers a connection the table refused with `problem`, without reading
  // anything.
  void Refuse(HttpRequest::Problem problem) {
    refused_ = true;
    ++server_->refusing_;
    DispatchProblem(problem, address_);
  }

  // ConnectionTable::Member: the pending read ends (operation_aborted).
  void Shed() override { stream_.close(); }

 private:
  void ReadBody() {
    const auto read = [this] {
      http::async_read(
          stream_, buffer_, *parser_,
          [self = shared_from_this()](beast::error_code error, size_t) {
            // A chunked body grew over the limit, or a chunk is malformed.
            if (error == http::error::body_limit) {
              self->Dispatch(HttpRequest::Problem::kBodyTooLarge);
            } else if (IsParseError(error)) {
              self->DispatchProblem(HttpRequest::Problem::kMalformed,
                                    error.message());
            } else if (!error) {
              self->Dispatch(HttpRequest::Problem::kNone);
            }
          });
    };
    const auto& header = parser_->get();
    if (beast::iequals(header[http::field::expect], "100-continue")) {
      auto proceed = std::make_shared<http::response<http::empty_body>>(
          http::status::continue_, header.version());
      http::async_write(stream_, *proceed,
                        [self = shared_from_this(), proceed, read](
                            beast::error_code error, size_t) {
                          if (!error) read();
                        });
      return;
    }
    read();
  }

  // Hands the request read so far to the handler.
  void Dispatch(HttpRequest::Problem problem) {
    const bool body_too_large = problem == HttpRequest::Problem::kBodyTooLarge;
    const http::request<http::string_body>& message = parser_->get();
    HttpRequest request;
    request.method = message.method() == http::verb::head
                         ? "GET"
                         : std::string(message.method_string());
    const std::string_view target(message.target().data(),
                                  message.target().size());
    const size_t question = target.find('?');
    request.path = std::string(target.substr(0, question));
    if (question != std::string_view::npos) {
      request.query = std::string(target.substr(question + 1));
    }
    for (const auto& field : message) {
      std::string name(field.name_string());
      for (char& c : name) c = static_cast<char>(std::tolower(c));
      request.headers.emplace_back(std::move(name), std::string(field.value()));
    }
    request.problem = problem;
    if (!body_too_large) request.body = std::move(parser_->get().body());
    // An unread body leaves the stream mid-message: close after replying.
    keep_alive_ = message.keep_alive() && !body_too_large;
    linger_ = body_too_large;
    head_ = message.method() == http::verb::head;
    version_ = message.version();
    server_->handler_(std::move(request),
                      server_->AwaitReply(shared_from_this()));
  }

  // Hands a request that could not be read to the handler: it holds
  // nothing but the problem. The stream is at an unknown place in what
  // the client sends, so the connection closes after the answer.
  void DispatchProblem(HttpRequest::Problem problem, std::string detail) {
    HttpRequest request;
    request.problem = problem;
    request.problem_detail = std::move(detail);
    keep_alive_ = false;
    linger_ = true;
    head_ = false;
    version_ = 11;
    server_->handler_(std::move(request),
                      server_->AwaitReply(shared_from_this()));
  }

 public:
  // Sends the reply to the request last dispatched.
  void Write(HttpResponse reply) {
    response_ = {};
    response_.version(version_);
    response_.keep_alive(keep_alive_);
    response_.result(reply.status);
    response_.set(http::field::server, "locatord");
    response_.set(http::field::cache_control, "no-store");
    response_.set(http::field::content_type, reply.content_type);
    for (const auto& [name, value] : reply.headers) response_.set(name, value);
    response_.body() = std::move(reply.body);
    response_.prepare_payload();
    // HEAD: the GET's headers, Content-Length included, and no body.
    if (head_) response_.body().clear();
    stream_.expires_after(kIdleTimeout);
    http::async_write(
        stream_, response_,
        [self = shared_from_this()](beast::error_code error, size_t) {
          // A large body would otherwise stay allocated while the
          // connection waits for its next request.
          const size_t written = self->response_.body().size();
          self->response_ = {};
          if (written >= kTrimAfterBytes) ReturnFreedMemory();
          if (error) return;
          if (!self->keep_alive_) {
            beast::error_code ignored;
            self->stream_.socket().shutdown(tcp::socket::shutdown_send,
                                            ignored);
            if (self->linger_) self->Linger();
            return;
          }
          self->Read();
        });
  }

 private:
  // Reads and drops what the client still sends of a body that was not
  // read, until it closes, kMaxLingerBytes or kLingerTimeout: closing with
  // unread data would reset the connection, and the client could lose the
  // answer.
  void Linger() {
    stream_.expires_after(kLingerTimeout);
    stream_.async_read_some(
        asio::buffer(server_->linger_buffer_),
        [self = shared_from_this()](beast::error_code error, size_t got) {
          self->lingered_ += got;
          if (!error && self->lingered_ < kMaxLingerBytes) self->Linger();
        });
  }

  HttpServer* const server_;
  beast::tcp_stream stream_;
  const std::string address_;
  bool refused_ = false;  // counted in the server's refusing_
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  http::response<http::string_body> response_;  // kept alive while written
  // Of the request last dispatched: how to answer it.
  bool keep_alive_ = false;
  bool head_ = false;
  unsigned version_ = 11;
  bool linger_ = false;  // its body was not read
  size_t lingered_ = 0;
};

// The state behind one reply function: answers its connection once, or
// abandons it if destroyed unanswered. Any thread.
class HttpServer::ReplyTicket {
 public:
  ReplyTicket(HttpServer* server, uint64_t id)
      : server_(server), gate_(server->reply_gate_), id_(id) {}
  ~ReplyTicket() {
    if (!answered_.load()) {
      gate_->Post([server = server_, id = id_] { server->Abandon(id); });
    }
  }
  ReplyTicket(const ReplyTicket&) = delete;
  ReplyTicket& operator=(const ReplyTicket&) = delete;

  // Sends `response`, unless already answered.
  void Answer(HttpResponse response) {
    if (answered_.exchange(true)) return;
    gate_->Post(
        [server = server_, id = id_, response = std::move(response)]() mutable {
          server->Answer(id, std::move(response));
        });
  }

 private:
  HttpServer* const server_;  // only dereferenced on the server's thread
  const std::shared_ptr<ReplyGate> gate_;
  const uint64_t id_;
  std::atomic<bool> answered_{false};
};

void HttpServer::ReplyGate::Post(std::function<void()> work) {
  MutexLock lock(&mu_);
  if (io_context_ != nullptr) asio::post(*io_context_, std::move(work));
}

void HttpServer::ReplyGate::Close() {
  MutexLock lock(&mu_);
  io_context_ = nullptr;
}

HttpReply HttpServer::AwaitReply(std::shared_ptr<Connection> connection) {
  const uint64_t id = next_reply_id_++;
  awaiting_reply_.emplace(id, std::move(connection));
  auto ticket = std::make_shared<ReplyTicket>(this, id);
  return
      [ticket](HttpResponse response) { ticket->Answer(std::move(response)); };
}

void HttpServer::Answer(uint64_t id, HttpResponse response) {
  const auto found = awaiting_reply_.find(id);
  if (found == awaiting_reply_.end()) return;
  const std::shared_ptr<Connection> connection = std::move(found->second);
  awaiting_reply_.erase(found);
  connection->Write(std::move(response));
}

void HttpServer::Abandon(uint64_t id) { awaiting_reply_.erase(id); }

std::optional<std::string_view> HttpRequest::Header(
    std::string_view name) const {
  for (const auto& [key, value] : headers) {
    if (key == name) return std::string_view(value);
  }
  return std::nullopt;
}

HttpServer::HttpServer(HttpLimits limits, HttpHandler handler)
    : limits_(limits),
      handler_(std::move(handler)),
      connections_(limits.max_connections, limits.max_connections_per_address),
      reply_gate_(std::make_shared<ReplyGate>(&io_context_)),
      acceptor_(io_context_),
      accept_retry_(io_context_) {}

Status HttpServer::Start(const std::string& host, int port, HttpLimits limits,
                         HttpHandler handler,
                         std::unique_ptr<HttpServer>* server) {
  std::unique_ptr<HttpServer> created(
      new HttpServer(limits, std::move(handler)));
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
  reply_gate_->Close();
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
    Open(std::move(socket));
    Accept();
  });
}

void HttpServer::Open(tcp::socket socket) {
  std::string address = ClientAddress(socket);
  if (address.empty()) return;  // gone already
  auto connection =
      std::make_shared<Connection>(this, std::move(socket), std::move(address));
  const ConnectionTable::Refusal refusal =
      connections_.Open(connection.get(), connection->address());
  if (refusal == ConnectionTable::Refusal::kNone) {
    connection->Read();
    return;
  }
  // Beyond kMaxRefusing the socket closes as `connection` goes.
  if (refusing_ < kMaxRefusing) {
    connection->Refuse(refusal == ConnectionTable::Refusal::kAddressFull
                           ? HttpRequest::Problem::kAddressFull
                           : HttpRequest::Problem::kServerBusy);
  }
}

}  // namespace locator
