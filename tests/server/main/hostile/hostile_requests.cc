// The point-location requests: Locate, LocateBatch and LocateStream.

#include "tests/server/main/hostile/hostile_requests.h"

#include "tests/server/main/hostile/hostile_request_parts.h"

namespace locator::test {
namespace {

using Code = grpc::StatusCode;

// Batch sizes, the cheap ones first (a case's other fields draw only
// those): none, ragged columns, past the point limit, at it, past the
// message size limit.
enum BatchSize : size_t {
  kEmpty,
  kMoreXs,
  kMoreYs,
  kPastPointLimit,
  kAtPointLimit,
  kPastMessageLimit,  // --max-message-bytes; over HTTP --http-max-body-bytes
  kBatchSizes
};
constexpr size_t kCheapBatchSizes = kAtPointLimit;

// Stream sizes: a long stream; a message past the message size limit.
enum StreamSize : size_t { kLong, kHugeMessage, kStreamSizes };

const std::vector<std::string> kLimitNames = {"limit", "larger than max",
                                              "body"};

std::vector<size_t> Counts(
    std::initializer_list<std::pair<HostileField, size_t>> fields) {
  std::vector<size_t> counts(kFieldCount, 0);
  for (const auto& [field, count] : fields) counts[field] = count;
  return counts;
}

}  // namespace

std::vector<size_t> LocateFieldCounts(const HostileServer& server) {
  return Counts({{kFieldX, HostileCoordinates().size()},
                 {kFieldY, HostileCoordinates().size()},
                 {kFieldCrs, server.request_crs().size()},
                 {kFieldDataset, HostileDatasetNames().size()},
                 {kFieldInterpolation, kHostileInterpolations}});
}

HostileCase<v1::LocateRequest> DrawLocate(CaseDraw& draw,
                                          const HostileServer& server,
                                          Transport transport) {
  HostileCase<v1::LocateRequest> c;
  const Target target = DrawTarget(draw, server, true, transport, &c.expect);
  c.oracle = target.oracle;
  c.summary = target.summary;
  v1::LocateRequest& request = c.request;
  request.set_dataset(target.dataset);
  request.set_interpolation(
      DrawInterpolation(draw, target, &c.expect, &c.summary));
  Point2 p = BenignPoint(draw, target);
  const std::string hostile = DrawHostilePoint(draw, &p);
  ExpectPoint(p, target, kPointNames, &c.expect);
  request.mutable_point()->set_x(p.x);
  request.mutable_point()->set_y(p.y);
  if (target.crs != nullptr) {
    request.set_crs(target.crs->text);
    request.set_vertices_in_request_crs(draw.Chance(0.5));
  }
  c.points = {target.points_known ? std::optional<Point2>(p) : std::nullopt};
  c.summary += " point " + PointText(p);
  return c;
}

std::vector<size_t> BatchFieldCounts(const HostileServer& server) {
  std::vector<size_t> counts = LocateFieldCounts(server);
  counts[kFieldSize] = kBatchSizes;
  return counts;
}

HostileCase<v1::LocateBatchRequest> DrawBatch(CaseDraw& draw,
                                              const HostileServer& server,
                                              Transport transport) {
  HostileCase<v1::LocateBatchRequest> c;
  const size_t size =
      draw.Hostile(kFieldSize, kCheapBatchSizes).value_or(kBatchSizes);
  if (size == kPastMessageLimit) {
    // Refused before the server reads it: nothing else counts.
    c.expect.Require(Code::RESOURCE_EXHAUSTED, kLimitNames)
        .AllowHttpStatus(413);
    // A point is 16 bytes packed, at least 8 ("0.5,0.5,") as JSON.
    const size_t n =
        (transport == Transport::kGrpc ? HostileLimits::kMessageBytes / 16
                                       : HostileLimits::kHttpBodyBytes / 8) +
        1000;
    c.request.mutable_xs()->Resize(static_cast<int>(n), 0.5);
    c.request.mutable_ys()->Resize(static_cast<int>(n), 0.5);
    c.summary = std::to_string(n) + " points, past the message or body limit";
    return c;
  }
  const Target target = DrawTarget(draw, server, true, transport, &c.expect);
  c.oracle = target.oracle;
  c.summary = target.summary;
  v1::LocateBatchRequest& request = c.request;
  request.set_dataset(target.dataset);
  request.set_interpolation(
      DrawInterpolation(draw, target, &c.expect, &c.summary));
  size_t n = 1 + draw.Below(40);
  if (size == kEmpty) n = 0;
  if (size == kAtPointLimit) n = HostileLimits::kBatchPoints;
  if (size == kPastPointLimit) n = HostileLimits::kBatchPoints + 1;
  std::vector<Point2> points(n);
  for (Point2& p : points) p = BenignPoint(draw, target);
  if (n > 0) {
    // The hostile coordinates go to one point, anywhere in the batch.
    Point2& p = points[draw.Below(n)];
    c.summary += " point " + DrawHostilePoint(draw, &p);
    ExpectPoint(p, target, {"point", "xs", "ys"}, &c.expect);
  }
  for (const Point2& p : points) {
    request.add_xs(p.x);
    request.add_ys(p.y);
    c.points.push_back(target.points_known ? std::optional<Point2>(p)
                                           : std::nullopt);
  }
  c.summary += " " + std::to_string(n) + " points";
  if (target.oracle != nullptr && n > HostileLimits::kBatchPoints) {
    c.expect.Require(Code::RESOURCE_EXHAUSTED, {"limit", "batch"});
  }
  if (target.oracle != nullptr && (size == kMoreXs || size == kMoreYs)) {
    (size == kMoreXs ? request.add_xs(1) : request.add_ys(1));
    c.summary += size == kMoreXs ? ", one more x" : ", one more y";
    c.expect.Require(Code::INVALID_ARGUMENT, {"xs", "ys"});
  }
  if (target.crs != nullptr) request.set_crs(target.crs->text);
  request.set_include_vertex_ids(draw.Chance(0.85));
  request.set_include_barycentric(draw.Chance(0.85));
  request.set_include_values(draw.Chance(0.85));
  return c;
}

std::vector<size_t> StreamFieldCounts(const HostileServer& server) {
  std::vector<size_t> counts = LocateFieldCounts(server);
  counts[kFieldSize] = kStreamSizes;
  return counts;
}

std::vector<HostileCase<v1::LocateRequest>> DrawStream(
    uint64_t seed, size_t index, Focus focus, const HostileServer& server) {
  // The other messages: benign, but for a few hostile fields (none in a
  // long stream, which would rarely get far otherwise).
  const bool size_focus = focus.field == kFieldSize;
  const bool long_stream = size_focus && focus.value == kLong;
  const double others_rate = long_stream ? 0 : 0.02;
  CaseDraw shape(seed, index, focus);
  const size_t n = long_stream ? kLongStream : 1 + shape.Below(6);
  const size_t focus_at = shape.Below(n);
  std::vector<HostileCase<v1::LocateRequest>> messages;
  for (size_t k = 0; k < n; ++k) {
    const bool focused = k == focus_at && !size_focus;
    CaseDraw draw(seed ^ (k + 1), index, focused ? focus : Focus{-1, 0},
                  others_rate);
    messages.push_back(DrawLocate(draw, server, Transport::kGrpc));
  }
  if (size_focus && focus.value == kHugeMessage) {
    HostileCase<v1::LocateRequest>& huge = messages[focus_at];
    huge.request.set_crs(std::string(HostileLimits::kMessageBytes, 'A'));
    huge.expect = Expectation();
    huge.expect.Require(Code::RESOURCE_EXHAUSTED, kLimitNames);
    huge.summary += " with a crs past the message size limit";
  }
  return messages;
}

}  // namespace locator::test
