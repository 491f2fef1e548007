// The rows of the hostile HTTP table (hostile_http_test.cc) and the checks
// they make of a reply: a row is one request, the HTTP statuses it accepts
// and, optionally, a check of the reply's headers and body. The table is
// split by concern: the tile routes' rows are in hostile_tile_rows.cc, the
// elevation APIs' in hostile_elevation_rows.cc.

#ifndef LOCATOR_TESTS_SERVER_MAIN_HOSTILE_HOSTILE_HTTP_ROWS_H_
#define LOCATOR_TESTS_SERVER_MAIN_HOSTILE_HOSTILE_HTTP_ROWS_H_

#include <functional>
#include <string>
#include <vector>

#include "tests/server/main/hostile/hostile_calls.h"

namespace locator::test {

struct HttpRow {
  std::string label;
  std::string method, target, body;
  HttpHeaders headers;
  // Sent as is on a fresh connection instead, when not empty.
  std::string raw;
  std::vector<unsigned> statuses;
  // More checks of the reply; "" when it is right.
  std::function<std::string(const HttpReply&)> check = nullptr;
  // Whether an error reply must be an ApiError (Open Topo Data's have its
  // own shape, which `check` judges).
  bool api_error = true;
};

// Splits what RawExchange received into a reply; status 0 if it is none.
HttpReply ParseRawReply(const std::string& received);
// The reply's header `name` (lower case), or "" when it has none.
std::string Header(const HttpReply& reply, const std::string& name);

// The checks of a reply: each returns "" when the reply is right, else what
// is wrong with it.
std::string IsHtml(const HttpReply& reply);
std::string NoSecrets(const HttpReply& reply);
// /metrics below 1 MiB, in the Prometheus text format.
std::string SmallParsedMetrics(const HttpReply& reply);
std::string IsJson(const HttpReply& reply);
std::string IsPng(const HttpReply& reply);
// A quantized-mesh tile: its type, and at least an empty tile's bytes.
std::string IsQuantizedMesh(const HttpReply& reply);
std::function<std::string(const HttpReply&)> AllowsOrigin(
    const std::string& origin);
std::string NoCors(const HttpReply& reply);

// The terrain tile routes' rows (the PNG tiles and the Cesium terrain):
// hostile z/x/y, encodings, Accept, Accept-Encoding, Host and
// If-None-Match, on the hostile server's dataset "utm" (and "plain", which
// has no CRS).
std::vector<HttpRow> TileRows();

// The elevation APIs' rows: Open Topo Data and OGC API - EDR with hostile
// points, WKT, CRSs, polylines, bodies and sizes past the limits, on "utm"
// and "plain".
std::vector<HttpRow> ElevationRows();

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_MAIN_HOSTILE_HOSTILE_HTTP_ROWS_H_
