#include "tests/server/http/json_value.h"
#include "tests/server/http/prometheus_text.h"
#include "tests/server/main/hostile/hostile_http_rows.h"

namespace locator::test {
namespace {

constexpr size_t kMaxMetricsBytes = size_t{1} << 20;

}  // namespace

HttpReply ParseRawReply(const std::string& received) {
  HttpReply reply;
  if (received.rfind("HTTP/1.1 ", 0) != 0 || received.size() < 12) return reply;
  reply.status = static_cast<unsigned>(std::stoi(received.substr(9, 3)));
  const size_t end = received.find("\r\n\r\n");
  if (end != std::string::npos) reply.body = received.substr(end + 4);
  return reply;
}

std::string Header(const HttpReply& reply, const std::string& name) {
  const auto it = reply.headers.find(name);
  return it == reply.headers.end() ? "" : it->second;
}

std::string IsHtml(const HttpReply& reply) {
  return Header(reply, "content-type").rfind("text/html", 0) == 0
             ? ""
             : "content type " + Header(reply, "content-type");
}

std::string NoSecrets(const HttpReply& reply) {
  return reply.body.find("root:") == std::string::npos &&
                 reply.body.find("the secret") == std::string::npos
             ? ""
             : "the reply holds a file's contents";
}

std::string SmallParsedMetrics(const HttpReply& reply) {
  if (reply.body.size() >= kMaxMetricsBytes) {
    return "/metrics is " + std::to_string(reply.body.size()) + " bytes";
  }
  PrometheusText parsed;
  const Status parses = ParsePrometheusText(reply.body, &parsed);
  return parses.ok() ? "" : parses.ToString();
}

std::string IsJson(const HttpReply& reply) {
  JsonValue json;
  return ParseJson(reply.body, &json).ok() ? "" : "not JSON";
}

std::string IsPng(const HttpReply& reply) {
  return Header(reply, "content-type") == "image/png" &&
                 reply.body.starts_with("\x89PNG\r\n\x1a\n")
             ? ""
             : "not a PNG: " + Header(reply, "content-type");
}

std::string IsQuantizedMesh(const HttpReply& reply) {
  constexpr size_t kEmptyTileBytes = 88 + 4 + 4 + 4 * 4;
  return Header(reply, "content-type") == "application/vnd.quantized-mesh" &&
                 reply.body.size() >= kEmptyTileBytes
             ? ""
             : "not a quantized-mesh tile: " + Header(reply, "content-type");
}

std::function<std::string(const HttpReply&)> AllowsOrigin(
    const std::string& origin) {
  return [origin](const HttpReply& reply) {
    const std::string allowed = Header(reply, "access-control-allow-origin");
    return allowed == origin ? ""
                             : "Access-Control-Allow-Origin '" + allowed +
                                   "', want '" + origin + "'";
  };
}

std::string NoCors(const HttpReply& reply) {
  return Header(reply, "access-control-allow-origin").empty()
             ? ""
             : "Access-Control-Allow-Origin for an origin not allowed";
}

}  // namespace locator::test
