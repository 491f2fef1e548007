// The hostile-input property test (issue 26), part 3: every HTTP route with
// what a careless or hostile HTTP client sends: JSON numbers protobuf's
// mapping would never print (1e400, 4.9e-324 as text, numbers as strings,
// nesting 10^5 deep), the issue's own reproductions (a profile 1e160 long,
// samples past 32 bits), bodies at and past --http-max-body-bytes, other
// content types, absurd Content-Length, oversized headers and paths,
// garbage instead of HTTP, paths that climb out of the status page's
// files, and CORS preflights from origins that are not allowed. Each row
// names the HTTP statuses it accepts; an error must be an ApiError with a
// short message, or a status the HTTP server answers before any API call
// (400, 413, 414, 415, 431) — never a dropped connection. The server must
// pass the control query after every batch of rows, as in parts 1 and 2.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "tests/server/main/hostile/hostile_calls.h"
#include "tests/server/main/hostile/hostile_http_rows.h"
#include "tests/server/main/hostile/hostile_run.h"

namespace locator::test {
namespace {

constexpr char kLocate[] = "/v1/datasets/plain:locate";
constexpr char kProfile[] = "/v1/datasets/plain:profile";
constexpr char kGrid[] = "/v1/datasets/plain:grid";
constexpr size_t kDeepNesting = 100000;

std::vector<HttpRow> Rows() {
  const std::string ok = HostileServer::kCorsOrigin;
  const std::string locate_body = R"({"point":{"x":10.25,"y":20.5}})";
  std::string at_limit = locate_body;
  at_limit.resize(HostileLimits::kHttpBodyBytes, ' ');
  std::string past_limit = at_limit + " ";
  const std::string nested = "{\"point\":" + std::string(kDeepNesting, '[') +
                             std::string(kDeepNesting, ']') + "}";
  const std::string raw_post = "POST " + std::string(kLocate) +
                               " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: "
                               "application/json\r\nConnection: close\r\n";
  const HttpHeaders json = {{"Content-Type", "application/json"}};
  const std::vector<unsigned> bad = {400};
  const std::vector<unsigned> refused = {400, 413, 414, 431};
  std::vector<HttpRow> rows = {
      {"the status page", "GET", "/", "", {}, "", {200}, IsHtml},
      {"the web example", "GET", "/web/", "", {}, "", {200}, IsHtml},
      {"/metrics", "GET", "/metrics", "", {}, "", {200}, SmallParsedMetrics},
      {"/api/stats", "GET", "/api/stats", "", {}, "", {200}, IsJson},
      {"/api/edges",
       "GET",
       "/api/edges?dataset=utm",
       "",
       {},
       "",
       {200},
       IsJson},
      {"/api/history", "GET", "/api/history", "", {}, "", {200}, IsJson},
      {"an /api/ path nobody serves", "GET", "/api/nope", "", {}, "", {404}},
      {"/v1/datasets", "GET", "/v1/datasets", "", {}, "", {200}, IsJson},
      {"POST /v1/datasets", "POST", "/v1/datasets", "{}", json, "", {405}},
      // Within the header limit, echoed by the API's own errors.
      {"a 6 KiB API path",
       "GET",
       "/v1/" + std::string(6000, 'p'),
       "",
       {},
       "",
       {404}},
      {"a 6 KiB dataset of a method it is not",
       "GET",
       "/v1/datasets/" + std::string(6000, 'd') + ":locate",
       "",
       {},
       "",
       {405}},
      {":locate naming a 6 KiB dataset in its body", "POST", kLocate,
       R"({"point":{"x":1,"y":1},"dataset":")" + std::string(6000, 'd') +
           R"("})",
       json, "", bad},
      {":locate with a 6 KiB unknown field", "POST", kLocate,
       "{\"" + std::string(6000, 'f') + "\":1}", json, "", bad},
      {"DELETE :locate", "DELETE", kLocate, "", {}, "", {405}},
      {"a path climbing out",
       "GET",
       "/../../etc/passwd",
       "",
       {},
       "",
       {400, 404},
       NoSecrets},
      {"an encoded path climbing out",
       "GET",
       "/%2e%2e/%2e%2e/etc/passwd",
       "",
       {},
       "",
       {400, 404},
       NoSecrets},
      {"the web example climbing out",
       "GET",
       "/web/../../../etc/passwd",
       "",
       {},
       "",
       {301, 400, 404},
       NoSecrets},
      {"/api/stats of a dataset with NUL",
       "GET",
       "/api/stats?dataset=%00",
       "",
       {},
       "",
       {404}},
      {":locate as text/plain (a cross-origin form)",
       "POST",
       kLocate,
       locate_body,
       {{"Content-Type", "text/plain"}},
       "",
       {415}},
      {":locate without a content type",
       "POST",
       kLocate,
       locate_body,
       {},
       "",
       {415}},
      {":locate as JSON with a charset",
       "POST",
       kLocate,
       locate_body,
       {{"Content-Type", "application/json; charset=utf-8"}},
       "",
       {200}},
      {":locate at the body limit", "POST", kLocate, at_limit, json, "", {200}},
      {":locate past the body limit",
       "POST",
       kLocate,
       past_limit,
       json,
       "",
       {413}},
      {":locate x=1e400", "POST", kLocate, R"({"point":{"x":1e400,"y":0}})",
       json, "", bad},
      {":locate x=-1e400", "POST", kLocate, R"({"point":{"x":0,"y":-1e400}})",
       json, "", bad},
      {":locate NaN and Infinity as strings", "POST", kLocate,
       R"({"point":{"x":"NaN","y":"Infinity"}})", json, "", bad},
      {":locate -Infinity", "POST", kLocate,
       R"({"point":{"x":"-Infinity","y":1}})", json, "", bad},
      {":locate 4.9e-324 and -0",
       "POST",
       kLocate,
       R"({"point":{"x":4.9e-324,"y":-0}})",
       json,
       "",
       {200}},
      {":locate 1e160 as strings",
       "POST",
       kLocate,
       R"({"point":{"x":"1e160","y":"-1e160"}})",
       json,
       "",
       {200}},
      {":locate DBL_MAX",
       "POST",
       kLocate,
       R"({"point":{"x":1.7976931348623157e308,"y":-1.7976931348623157e308}})",
       json,
       "",
       {200}},
      {":locate nested 10^5 deep", "POST", kLocate, nested, json, "", bad},
      {":locate a crs of invalid UTF-8", "POST", kLocate,
       "{\"point\":{\"x\":1,\"y\":1},\"crs\":\"\xff\xfe\"}", json, "", bad},
      {":profile 1e160 long (issue 26, hole 1)",
       "POST",
       kProfile,
       R"({"vertices":[{"x":-1e160,"y":-1e160},{"x":1e160,"y":1e160}]})",
       json,
       "",
       {200, 400}},
      {":profile samples 2^32", "POST", kProfile,
       R"({"vertices":[{"x":1,"y":1},{"x":2,"y":2}],"samples":4294967296})",
       json, "", bad},
      {":profile samples 4e9 as a string (hole 2)",
       "POST",
       kProfile,
       R"({"vertices":[{"x":1,"y":1},{"x":2,"y":2}],"samples":"4000000000"})",
       json,
       "",
       {429}},
      {":profile samples 1e300", "POST", kProfile,
       R"({"vertices":[{"x":1,"y":1},{"x":2,"y":2}],"samples":1e300})", json,
       "", bad},
      {":grid width -1", "POST", kGrid,
       R"({"box":{"minX":0,"minY":0,"maxX":1,"maxY":1},"width":-1,"height":2})",
       json, "", bad},
      {":grid cell size 1e-300 (a 300-digit cell count)",
       "POST",
       kGrid,
       R"({"box":{"minX":0,"minY":0,"maxX":1,"maxY":1},"cellSize":1e-300})",
       json,
       "",
       {429}},
      {":grid 4096 x 4096, past every cell limit",
       "POST",
       kGrid,
       R"({"box":{"minX":0,"minY":0,"maxX":59,"maxY":59},"width":4096,"height":4096})",
       json,
       "",
       {429}},
      {"a preflight from the allowed origin",
       "OPTIONS",
       kLocate,
       "",
       {{"Origin", ok}, {"Access-Control-Request-Method", "POST"}},
       "",
       {204},
       AllowsOrigin(ok)},
      {"a preflight from a look-alike origin",
       "OPTIONS",
       kLocate,
       "",
       {{"Origin", ok + ".evil"}, {"Access-Control-Request-Method", "POST"}},
       "",
       {403},
       NoCors},
      {"a preflight from origin null",
       "OPTIONS",
       kLocate,
       "",
       {{"Origin", "null"}, {"Access-Control-Request-Method", "POST"}},
       "",
       {403},
       NoCors},
      {"a preflight from a 4 KiB origin",
       "OPTIONS",
       kLocate,
       "",
       {{"Origin", "https://" + std::string(4096, 'a')},
        {"Access-Control-Request-Method", "POST"}},
       "",
       {403},
       NoCors},
      {"a GET from an origin not allowed",
       "GET",
       "/api/stats",
       "",
       {{"Origin", "https://evil.example"}},
       "",
       {200},
       NoCors},
      {"an absurd Content-Length",
       "",
       "",
       "",
       {},
       raw_post + "Content-Length: 99999999999999999999\r\n\r\n{}",
       refused},
      {"a 100 KiB header",
       "",
       "",
       "",
       {},
       raw_post + "X-Big: " + std::string(100 << 10, 'b') +
           "\r\nContent-Length: 2\r\n\r\n{}",
       {400, 431}},
      {"a 100 KiB path",
       "",
       "",
       "",
       {},
       "GET /" + std::string(100 << 10, 'p') +
           " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n",
       {400, 404, 414, 431}},
      {"a TLS hello instead of HTTP",
       "",
       "",
       "",
       {},
       std::string("\x16\x03\x01\x02\x00\x01\x00\x01\xfc\x03\x03", 11) +
           std::string(500, '\x42'),
       bad},
      {"a chunk of 2^64 bytes",
       "",
       "",
       "",
       {},
       raw_post + "Transfer-Encoding: chunked\r\n\r\nffffffffffffffff\r\nx",
       refused},
  };
  const std::vector<HttpRow> tiles = TileRows();
  rows.insert(rows.end(), tiles.begin(), tiles.end());
  const std::vector<HttpRow> elevation = ElevationRows();
  rows.insert(rows.end(), elevation.begin(), elevation.end());
  return rows;
}

TEST_F(HostileTest, HttpRoutes) {
  HostileRun run(server_, "HttpRoutes", seed());
  const std::vector<HttpRow> rows = Rows();
  for (size_t i = 0; i < rows.size() && !run.stopped(); ++i) {
    const HttpRow& row = rows[i];
    HttpReply reply;
    Outcome outcome;
    std::string problem;
    if (!row.raw.empty()) {
      std::string received;
      const Status exchanged =
          RawExchange(server_->http_port(), row.raw, &received);
      reply = ParseRawReply(received);
      if (reply.status == 0) {
        problem = outcome.transport_problem = "no HTTP answer (" +
                                              exchanged.ToString() + "): '" +
                                              Shorten(received, 80) + "'";
      }
    } else {
      outcome = CallHttp(server_->http_port(), row.method, row.target, row.body,
                         row.headers, nullptr, &reply);
      if (outcome.http_status == 0) problem = outcome.transport_problem;
      if (problem.empty() && row.api_error && reply.status >= 400 &&
          Header(reply, "content-type") == "application/json") {
        // An API error: short, readable, and mapped as its code says.
        Expectation any;
        any.Require(outcome.code, {""});
        problem = any.Judge(outcome);
      }
    }
    if (problem.empty() && std::find(row.statuses.begin(), row.statuses.end(),
                                     reply.status) == row.statuses.end()) {
      problem = "HTTP " + std::to_string(reply.status) + ": " +
                Shorten(reply.body, 200);
    }
    if (problem.empty() && row.check) problem = row.check(reply);
    run.Record(i, row.label, outcome, problem);
  }
}

}  // namespace
}  // namespace locator::test
