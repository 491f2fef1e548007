#include "tests/server/http/http_test_client.h"

#include <algorithm>
#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <cctype>
#include <chrono>

namespace locator::test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
using tcp = asio::ip::tcp;

// Long enough for a slow server (sanitizers, a loaded machine) to answer;
// only a server that never answers waits this long.
constexpr auto kTimeout = std::chrono::seconds(120);

// Connects `stream` from the loopback address `from` to 127.0.0.1:port.
Status Connect(int port, beast::tcp_stream* stream,
               std::string_view from = "127.0.0.1") {
  beast::error_code error;
  stream->expires_after(kTimeout);
  tcp::socket& socket = stream->socket();
  socket.open(tcp::v4(), error);
  if (!error) {
    socket.bind(tcp::endpoint(asio::ip::make_address(from), 0), error);
  }
  if (!error) {
    socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"),
                                 static_cast<unsigned short>(port)),
                   error);
  }
  if (error) return Status::IOError("connect: " + error.message());
  return Status::OK();
}

// Runs the asynchronous operation `start` begins on `stream` to its end,
// within kTimeout: the synchronous calls would ignore the stream's expiry
// and wait for ever for a server that never answers.
template <class Start>
beast::error_code Await(asio::io_context& io, beast::tcp_stream& stream,
                        Start start, size_t* transferred = nullptr) {
  beast::error_code result;
  stream.expires_after(kTimeout);
  start([&](beast::error_code error, size_t bytes) {
    result = error;
    if (transferred != nullptr) *transferred = bytes;
  });
  io.restart();
  io.run();
  return result;
}

std::string Lower(std::string_view text) {
  std::string lower(text);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return lower;
}

}  // namespace

Status SendHttp(int port, std::string_view method, std::string_view target,
                HttpReply* reply, std::string_view body,
                const HttpHeaders& headers) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  if (Status status = Connect(port, &stream); !status.ok()) return status;
  http::request<http::string_body> request(
      http::string_to_verb(beast::string_view(method.data(), method.size())),
      beast::string_view(target.data(), target.size()), 11);
  if (request.method() == http::verb::unknown) {
    request.method_string(beast::string_view(method.data(), method.size()));
  }
  request.set(http::field::host, "127.0.0.1");
  for (const auto& [name, value] : headers) request.set(name, value);
  request.body() = std::string(body);
  if (!body.empty() || request.method() == http::verb::post) {
    request.prepare_payload();
  }
  beast::error_code error;
  http::write(stream, request, error);
  if (error) return Status::IOError("write: " + error.message());
  beast::flat_buffer buffer;
  http::response_parser<http::string_body> parser;
  parser.body_limit(64 << 20);
  // A HEAD reply has no body whatever its Content-Length says.
  parser.skip(request.method() == http::verb::head);
  error = Await(io, stream, [&](auto handler) {
    http::async_read(stream, buffer, parser, handler);
  });
  if (error) return Status::IOError("read: " + error.message());
  const auto& response = parser.get();
  reply->status = response.result_int();
  reply->headers.clear();
  for (const auto& field : response) {
    reply->headers[Lower(std::string_view(field.name_string().data(),
                                          field.name_string().size()))] =
        std::string(field.value());
  }
  reply->body = response.body();
  return Status::OK();
}

Status RawExchange(int port, std::string_view raw, std::string* received,
                   std::string_view from) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  if (Status status = Connect(port, &stream, from); !status.ok()) {
    return status;
  }
  beast::error_code error;
  asio::write(stream.socket(), asio::buffer(raw.data(), raw.size()), error);
  // The server may close while we still write; what it sent still counts.
  received->clear();
  char chunk[4096];
  for (;;) {
    size_t got = 0;
    error = Await(
        io, stream,
        [&](auto handler) {
          stream.async_read_some(asio::buffer(chunk), handler);
        },
        &got);
    received->append(chunk, got);
    if (error == asio::error::eof || error == asio::error::connection_reset) {
      return Status::OK();
    }
    if (error) return Status::IOError("read: " + error.message());
  }
}

}  // namespace locator::test
