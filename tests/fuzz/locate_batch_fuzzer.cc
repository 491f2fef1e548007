// Fuzzes the LocateBatch request path: bytes -> a locator.v1
// LocateBatchRequest -> the service's validation (BatchLocator::Validate and
// its status mapping) -> Engine::LocateBatch on a small fixed triangulation
// -> the service's column writer.
//
// The first input byte picks how the rest becomes a request (bit 0: wire
// format; clear: a structured decode that mixes arbitrary bit patterns, special
// doubles such as NaN, +-inf, denormals and +-1e308, vertices, edge midpoints,
// points on edges and on their extensions, and vertices nudged by a few ulps),
// which strategy answers (bits 1-2, kStrategies) and whether it re-tunes first
// (bit 7).
//
// Aborts unless an invalid request fails exactly as documented (ragged
// columns and non-finite points InvalidArgument naming the lengths or the
// first bad point's index, too many points ResourceExhausted), and every
// answer to a valid one agrees with CGAL's own locate(), carries the dataset's
// interpolated value inside the hull, and appears unchanged in the response
// columns.

#include <fuzzer/FuzzedDataProvider.h>
#include <grpcpp/grpcpp.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/status_mapping.h"
#include "locator/engine.h"
#include "locator/v1/locator.pb.h"
#include "server/app/batch_locator.h"
#include "server/app/proto_convert.h"
#include "server/core/cgal/triangulation.h"

namespace locator {
namespace {

constexpr size_t kMaxBatchPoints = 64;
constexpr std::array<const char*, 4> kStrategies = {
    "walk", "jump-and-walk", "adaptive-paper", "self-tuning"};

double Value(const Point2& p) { return 2 * p.x + 3 * p.y + 1; }

// A 5x5 integer grid (its Delaunay triangulation is full of cocircular
// ties), off-grid points with dyadic coordinates so that edge midpoints and
// points at k/256 along an edge are exact, and one repeated point. Every
// point carries Value(p), so interpolated values are checkable.
Dataset FixedDataset() {
  Dataset ds;
  for (int x = 0; x <= 4; ++x) {
    for (int y = 0; y <= 4; ++y) ds.points.push_back({double(x), double(y)});
  }
  for (Point2 p : {Point2{1.5, 0.25}, Point2{3.25, 2.75}, Point2{-0.5, 2},
                   Point2{2, 5.125}, Point2{0.75, 3.5}, Point2{2, 2}}) {
    ds.points.push_back(p);
  }
  for (const Point2& p : ds.points) ds.values.push_back(Value(p));
  ds.source = "fuzz-fixed";
  return ds;
}

struct Fixture {
  Dataset dataset;
  std::unique_ptr<Triangulation> reference;
  std::vector<std::unique_ptr<Engine>> engines;  // one per kStrategies entry
  std::vector<std::pair<Point2, Point2>> edges;  // every finite edge
  BatchLocator service{1, kMaxBatchPoints};
};

void Fail(const std::string& what) {
  std::fprintf(stderr, "locate_batch_fuzzer: %s\n", what.c_str());
  std::abort();
}

void Require(const Status& status, const char* what) {
  if (!status.ok()) Fail(std::string(what) + ": " + status.ToString());
}

Fixture* MakeFixture() {
  auto* f = new Fixture;
  f->dataset = FixedDataset();
  StatusOr<std::unique_ptr<Triangulation>> reference =
      Triangulation::Build(f->dataset);
  Require(reference.status(), "reference");
  f->reference = *std::move(reference);
  for (const char* strategy : kStrategies) {
    EngineOptions options;
    options.strategy = strategy;
    // Small enough that the fuzzer's traffic re-tunes them often.
    options.tuning.grid_size = 8;
    options.tuning.warmup_queries = 200;
    options.tuning.retune_every = 256;
    StatusOr<std::unique_ptr<Engine>> engine =
        Engine::Create(f->dataset, options);
    Require(engine.status(), strategy);
    f->engines.push_back(*std::move(engine));
  }
  const auto& dt = f->reference->cgal();
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const auto& [face, i] = *e;
    f->edges.emplace_back(
        Triangulation::FromCgal(face->vertex(dt.ccw(i))->point()),
        Triangulation::FromCgal(face->vertex(dt.cw(i))->point()));
  }
  return f;
}

template <typename T>
const T& Pick(FuzzedDataProvider& in, const std::vector<T>& from) {
  return from[in.ConsumeIntegralInRange<size_t>(0, from.size() - 1)];
}

double RawDouble(FuzzedDataProvider& in) {
  const uint64_t bits = in.ConsumeIntegral<uint64_t>();
  double d;
  std::memcpy(&d, &bits, sizeof(d));
  return d;
}

double SpecialDouble(FuzzedDataProvider& in) {
  using L = std::numeric_limits<double>;
  constexpr double kSpecial[] = {L::quiet_NaN(),
                                 -L::quiet_NaN(),
                                 L::signaling_NaN(),
                                 L::infinity(),
                                 -L::infinity(),
                                 0.0,
                                 -0.0,
                                 L::denorm_min(),
                                 -L::denorm_min(),
                                 1e-310,
                                 L::min(),
                                 -L::min(),
                                 L::epsilon(),
                                 1 - L::epsilon() / 2,
                                 0.5,
                                 4,
                                 -4,
                                 1e-300,
                                 1e300,
                                 1e308,
                                 -1e308,
                                 L::max(),
                                 L::lowest()};
  return in.PickValueInArray(kSpecial);
}

// One coordinate: special, or a coordinate some dataset point has (so that
// the point lies on a grid or hull line).
double SpecialOrVertexCoordinate(FuzzedDataProvider& in, const Fixture& f) {
  if (in.ConsumeBool()) return SpecialDouble(in);
  const Point2& p = Pick(in, f.dataset.points);
  return in.ConsumeBool() ? p.x : p.y;
}

Point2 Along(const std::pair<Point2, Point2>& edge, double t) {
  const auto& [a, b] = edge;
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

Point2 ConsumePoint(FuzzedDataProvider& in, const Fixture& f) {
  switch (in.ConsumeIntegralInRange(0, 6)) {
    case 0:
      return {RawDouble(in), RawDouble(in)};
    case 1:
      return {SpecialOrVertexCoordinate(in, f),
              SpecialOrVertexCoordinate(in, f)};
    case 2:
      return Pick(in, f.dataset.points);
    case 3:
      return Along(Pick(in, f.edges), 0.5);
    case 4:  // on the edge, ends included
      return Along(Pick(in, f.edges),
                   in.ConsumeIntegralInRange(0, 256) / 256.0);
    case 5:  // on the edge's line, mostly beyond its ends
      return Along(Pick(in, f.edges),
                   in.ConsumeIntegralInRange(-64, 80) / 16.0);
    default: {  // a vertex nudged by a few ulps
      Point2 p = Pick(in, f.dataset.points);
      for (double* c : {&p.x, &p.y}) {
        for (int ulps = in.ConsumeIntegralInRange(-3, 3); ulps != 0;
             ulps += ulps > 0 ? -1 : 1) {
          *c = std::nextafter(*c, ulps > 0 ? 1e9 : -1e9);
        }
      }
      return p;
    }
  }
}

void ConsumeRequest(FuzzedDataProvider& in, const Fixture& f,
                    v1::LocateBatchRequest* request) {
  request->set_include_vertex_ids(in.ConsumeBool());
  request->set_include_barycentric(in.ConsumeBool());
  request->set_include_values(in.ConsumeBool());
  const size_t points =
      in.ConsumeIntegralInRange<size_t>(0, kMaxBatchPoints + 4);
  for (size_t i = 0; i < points; ++i) {
    const Point2 p = ConsumePoint(in, f);
    request->add_xs(p.x);
    request->add_ys(p.y);
  }
  switch (in.ConsumeIntegralInRange(0, 15)) {  // now and then, ragged columns
    case 0:
      request->add_xs(ConsumePoint(in, f).x);
      break;
    case 1:
      request->add_ys(ConsumePoint(in, f).y);
      break;
  }
}

void CheckRejected(const Status& status, Status::Code code,
                   const std::string& must_mention) {
  const grpc::Status wire = ToGrpcStatus(status);
  const bool invalid = code == Status::Code::kInvalidArgument;
  if (status.code() != code ||
      wire.error_code() != (invalid ? grpc::StatusCode::INVALID_ARGUMENT
                                    : grpc::StatusCode::RESOURCE_EXHAUSTED) ||
      wire.error_message().find(must_mention) == std::string::npos) {
    Fail("rejected as '" + status.ToString() + "', want code " +
         std::string(StatusCodeName(code)) + " mentioning '" + must_mention +
         "'");
  }
}

// Checks how an invalid request was rejected; false if it is valid.
bool CheckInvalid(const v1::LocateBatchRequest& request, const Status& status,
                  const Engine& engine, std::span<const Point2> points) {
  const int xs = request.xs_size();
  const int ys = request.ys_size();
  if (xs != ys) {
    CheckRejected(status, Status::Code::kInvalidArgument,
                  "xs has " + std::to_string(xs) + " values but ys has " +
                      std::to_string(ys));
    return true;
  }
  if (static_cast<size_t>(xs) > kMaxBatchPoints) {
    CheckRejected(status, Status::Code::kResourceExhausted,
                  std::to_string(kMaxBatchPoints));
    return true;
  }
  for (size_t i = 0; i < points.size(); ++i) {
    if (IsFinite(points[i])) continue;
    const std::string index = "point " + std::to_string(i) + " ";
    CheckRejected(status, Status::Code::kInvalidArgument, index);
    // The engine's own check, which the service relies on, agrees.
    std::vector<LocateResult> results;
    CheckRejected(engine.LocateBatch(points, &results),
                  Status::Code::kInvalidArgument, index);
    return true;
  }
  return false;
}

void CheckAnswer(const Fixture& f, const Point2& q, const LocateResult& got) {
  const LocateResult want = f.reference->ReferenceLocate(q);
  char where[96];
  std::snprintf(where, sizeof(where), "(%.17g, %.17g)", q.x, q.y);
  if (!f.reference->Agrees(q, got, want)) {
    Fail(std::string("disagrees with CGAL at ") + where + ": " +
         std::string(LocationTypeName(got.type)) + " triangle " +
         std::to_string(got.triangle_id) + ", CGAL says " +
         std::string(LocationTypeName(want.type)) + " triangle " +
         std::to_string(want.triangle_id));
  }
  const bool inside = got.type != LocationType::kOutsideConvexHull;
  if (got.has_value != inside) Fail(std::string("has_value wrong at ") + where);
  if (inside && std::abs(got.value - Value(q)) > 1e-9) {
    Fail(std::string("interpolated value wrong at ") + where);
  }
}

// The batch columns hold what the unary conversion of each answer holds.
void CheckColumns(const v1::LocateBatchRequest& request,
                  std::span<const LocateResult> results) {
  v1::LocateBatchResponse batch;
  const BatchAnswerColumns columns =
      SizeBatchAnswerColumns(request, results.size(), &batch);
  WriteBatchAnswers(results, 0, columns);
  for (size_t i = 0; i < results.size(); ++i) {
    v1::LocateResponse unary;
    ToLocateResponse(results[i], &unary);
    const int row = static_cast<int>(i);
    bool same = batch.types(row) == unary.type() &&
                batch.triangle_ids(row) == unary.triangle_id() &&
                batch.costs(row) == unary.cost().total();
    for (int c = 0; c < 3 && request.include_vertex_ids(); ++c) {
      same = same && batch.vertex_ids(3 * row + c) == unary.vertex_ids(c);
    }
    if (request.include_values() && unary.has_value()) {
      same = same && batch.values(row) == unary.value();
    }
    if (!same) Fail("batch row " + std::to_string(i) + " != unary answer");
  }
}

void FuzzOneInput(const uint8_t* data, size_t size) {
  static Fixture* const fixture = MakeFixture();
  const Fixture& f = *fixture;

  FuzzedDataProvider in(data, size);
  const uint8_t mode = in.ConsumeIntegral<uint8_t>();
  v1::LocateBatchRequest request;
  if (mode & 1) {
    const std::string wire = in.ConsumeRemainingBytesAsString();
    if (!request.ParseFromString(wire)) return;
  } else {
    ConsumeRequest(in, f, &request);
  }
  Engine& engine = *fixture->engines[(mode >> 1) % kStrategies.size()];
  if (mode & 0x80) engine.Retune();

  // As BatchLocator::Run: validate the whole request, then read the
  // points out of the columns.
  const Status valid = f.service.Validate(request);
  const size_t n =
      static_cast<size_t>(std::min(request.xs_size(), request.ys_size()));
  std::vector<Point2> points;
  for (size_t i = 0; i < n; ++i) {
    points.push_back(
        {request.xs(static_cast<int>(i)), request.ys(static_cast<int>(i))});
  }
  if (CheckInvalid(request, valid, engine, points)) return;
  Require(valid, "valid request rejected");

  std::vector<LocateResult> results;
  Require(engine.LocateBatch(points, &results), "valid batch failed");
  if (results.size() != n) Fail("answer count differs from point count");
  for (size_t i = 0; i < n; ++i) CheckAnswer(f, points[i], results[i]);
  CheckColumns(request, results);
}

}  // namespace
}  // namespace locator

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  locator::FuzzOneInput(data, size);
  return 0;
}
