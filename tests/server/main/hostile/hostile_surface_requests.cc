// The surface requests: Profile and Grid.

#include <cmath>
#include <limits>

#include "tests/server/main/hostile/hostile_request_parts.h"
#include "tests/server/main/hostile/hostile_requests.h"

namespace locator::test {
namespace {

using Code = grpc::StatusCode;

const std::vector<std::string> kLineNames = {"vertices", "vertex", "line"};
const std::vector<std::string> kCrossingNames = {"cross", "edges"};
const std::vector<std::string> kBoxNames = {"box", "min_x", "min_y"};
const std::vector<std::string> kCellSizeNames = {"cell_size", "cell size"};
const std::vector<std::string> kCellsNames = {"cells"};
const std::vector<std::string> kShapeNames = {"width", "height", "cell_size"};

// Line shapes, the cheap ones first: no vertex, one, 1000 vertices a short
// step apart, a zigzag crossing far more edges than the limit, more
// vertices than the crossing limit (each enters a triangle).
enum LineSize : size_t {
  kNoVertex,
  kOneVertex,
  kManyVertices,
  kPastCrossings,
  kPastVertices,
  kLineSizes
};
constexpr size_t kCheapLineSizes = kManyVertices;
constexpr int kManyLineVertices = 1000;
constexpr int kZigzagPasses = 200;

// Samples past every limit, at the server's limit, just past it and far
// past it (issue 26, hole 2).
constexpr uint32_t kHostileSamples[] = {
    4'000'000'000u, std::numeric_limits<uint32_t>::max(),
    HostileLimits::kProfileSamples, HostileLimits::kProfileSamples + 1,
    10'000'000};

// Grid shapes, the cheap ones first.
enum GridShape : size_t {
  kZeroWidth,
  kZeroHeight,
  kOneCell,
  kSizeAndCellSize,
  kNeither,
  kNoBox,
  kEmptyBox,
  kInvertedBox,
  kAtHttpCells,
  kPastHttpCells,
  kPastCells,
  kPastCellsThin,
  kHugeShape,
  kAtCells,
  kAtCellsThin,
  kGridShapes
};
constexpr size_t kCheapGridShapes = kAtCells;

// The hostile cell sizes: the hostile coordinates, then a 300th and a 100th
// of the box's width (past the cell limit; within it).
constexpr size_t kRelativeCellSizes = 2;

// Adds what a grid of `cells` cells allows over `transport`.
void ExpectCells(long double cells, Transport transport, Expectation* expect) {
  const uint64_t limit = transport == Transport::kHttp
                             ? HostileLimits::kHttpGridCells
                             : HostileLimits::kGridCells;
  if (cells > limit) expect->Require(Code::RESOURCE_EXHAUSTED, kCellsNames);
}

}  // namespace

std::vector<size_t> ProfileFieldCounts(const HostileServer& server) {
  std::vector<size_t> counts = LocateFieldCounts(server);
  counts[kFieldSize] = kLineSizes;
  counts[kFieldSamples] = std::size(kHostileSamples);
  return counts;
}

HostileCase<v1::ProfileRequest> DrawProfile(CaseDraw& draw,
                                            const HostileServer& server,
                                            Transport transport) {
  HostileCase<v1::ProfileRequest> c;
  const Target target = DrawTarget(draw, server, true, transport, &c.expect);
  c.oracle = target.oracle;
  c.summary = target.summary;
  v1::ProfileRequest& request = c.request;
  request.set_dataset(target.dataset);
  request.set_interpolation(
      DrawInterpolation(draw, target, &c.expect, &c.summary));
  const size_t size =
      draw.Hostile(kFieldSize, kCheapLineSizes).value_or(kLineSizes);
  std::vector<Point2> line;
  const BoundingBox& f = target.frame;
  if (size == kManyVertices) {
    Point2 p = BenignPoint(draw, target);
    const double step = 0.002 * (f.width() + f.height());
    for (int k = 0; k < kManyLineVertices; ++k) {
      line.push_back(p);
      p.x += draw.Uniform(-step, step);
      p.y += draw.Uniform(-step, step);
    }
  } else if (size == kPastVertices) {
    for (uint64_t k = 0; k <= HostileLimits::kProfileCrossings; ++k) {
      line.push_back(BenignPoint(draw, target));
    }
  } else if (size == kPastCrossings) {
    for (int pass = 0; pass < kZigzagPasses; ++pass) {
      const double y =
          f.min_y + (0.05 + 0.9 * pass / kZigzagPasses) * f.height();
      const double west = f.min_x + 0.02 * f.width();
      const double east = f.max_x - 0.02 * f.width();
      line.push_back({pass % 2 == 0 ? west : east, y});
      line.push_back({pass % 2 == 0 ? east : west, y});
    }
  } else {
    const size_t n = size == kNoVertex    ? 0
                     : size == kOneVertex ? 1
                                          : 2 + draw.Below(5);
    for (size_t k = 0; k < n; ++k) line.push_back(BenignPoint(draw, target));
  }
  if (!line.empty()) {
    const size_t k = draw.Below(line.size());
    const std::string hostile = DrawHostilePoint(draw, &line[k]);
    if (!hostile.empty()) {
      c.summary += " vertex " + std::to_string(k) + " " + hostile;
    }
    ExpectPoint(line[k], target, kLineNames, &c.expect);
    if (target.oracle != nullptr && !hostile.empty() && IsFinite(line[k])) {
      // Arithmetic on it may overflow: answered or refused.
      c.expect.Allow(Code::INVALID_ARGUMENT, kLineNames);
    }
  }
  for (const Point2& p : line) {
    v1::Point* vertex = request.add_vertices();
    vertex->set_x(p.x);
    vertex->set_y(p.y);
  }
  c.summary += " " + std::to_string(line.size()) + " vertices";
  // The cheap ones only, but for the focus.
  if (const auto i = draw.Hostile(kFieldSamples, 0)) {
    request.set_samples(kHostileSamples[*i]);
  } else {
    request.set_samples(static_cast<uint32_t>(draw.Below(12)));
  }
  c.summary += " samples " + std::to_string(request.samples());
  if (target.crs != nullptr) request.set_crs(target.crs->text);
  if (target.oracle == nullptr) return c;
  if (line.size() < 2) {
    c.expect.Require(Code::INVALID_ARGUMENT,
                     {"vertices", "vertex", "line", "points"});
  }
  c.expect.Allow(Code::RESOURCE_EXHAUSTED, kCrossingNames);
  if (size == kPastCrossings || size == kPastVertices) {
    c.expect.Require(Code::RESOURCE_EXHAUSTED, kCrossingNames);
  }
  if (request.samples() > HostileLimits::kProfileSamples) {
    c.expect.Require(Code::RESOURCE_EXHAUSTED, {"samples"});
  }
  return c;
}

std::vector<size_t> GridFieldCounts(const HostileServer& server) {
  std::vector<size_t> counts(kFieldCount, 0);
  counts[kFieldX] = counts[kFieldY] = counts[kFieldNodata] =
      HostileCoordinates().size();
  counts[kFieldDataset] = HostileDatasetNames().size();
  counts[kFieldInterpolation] = kHostileInterpolations;
  counts[kFieldSize] = kGridShapes;
  counts[kFieldCellSize] = HostileCoordinates().size() + kRelativeCellSizes;
  (void)server;
  return counts;
}

HostileCase<v1::GridRequest> DrawGrid(CaseDraw& draw,
                                      const HostileServer& server,
                                      Transport transport) {
  HostileCase<v1::GridRequest> c;
  const Target target = DrawTarget(draw, server, false, transport, &c.expect);
  c.oracle = target.oracle;
  c.summary = target.summary;
  v1::GridRequest& request = c.request;
  request.set_dataset(target.dataset);
  request.set_interpolation(
      DrawInterpolation(draw, target, &c.expect, &c.summary));
  const BoundingBox& f = target.frame;
  BoundingBox box;
  box.min_x = f.min_x + draw.Uniform(-0.1, 0.5) * f.width();
  box.max_x = box.min_x + draw.Uniform(0.05, 0.7) * f.width();
  box.min_y = f.min_y + draw.Uniform(-0.1, 0.5) * f.height();
  box.max_y = box.min_y + draw.Uniform(0.05, 0.7) * f.height();
  const std::vector<double>& coordinates = HostileCoordinates();
  std::string hostile_box;
  if (const auto i = draw.Hostile(kFieldX, coordinates.size())) {
    (draw.Chance(0.5) ? box.min_x : box.max_x) = coordinates[*i];
    hostile_box += " x " + DoubleName(coordinates[*i]);
  }
  if (const auto i = draw.Hostile(kFieldY, coordinates.size())) {
    (draw.Chance(0.5) ? box.min_y : box.max_y) = coordinates[*i];
    hostile_box += " y " + DoubleName(coordinates[*i]);
  }
  // kGridShapes and kNoCell: benign.
  constexpr size_t kNoCell = SIZE_MAX;
  const bool shape_focus = draw.focus().field == kFieldSize;
  size_t shape =
      draw.Hostile(kFieldSize, kCheapGridShapes).value_or(kGridShapes);
  const size_t cell = shape_focus
                          ? kNoCell
                          : draw.Hostile(kFieldCellSize, coordinates.size() +
                                                             kRelativeCellSizes)
                                .value_or(kNoCell);
  if (cell != kNoCell) shape = kGridShapes;
  if (shape == kEmptyBox) box.max_x = box.min_x;
  if (shape == kInvertedBox) std::swap(box.min_x, box.max_x);
  if (shape != kNoBox) {
    v1::BoundingBox* b = request.mutable_box();
    b->set_min_x(box.min_x);
    b->set_min_y(box.min_y);
    b->set_max_x(box.max_x);
    b->set_max_y(box.max_y);
  }
  c.summary += " box (" + DoubleName(box.min_x) + ", " + DoubleName(box.min_y) +
               ", " + DoubleName(box.max_x) + ", " + DoubleName(box.max_y) +
               ")";
  if (const auto i = draw.Hostile(kFieldNodata, coordinates.size())) {
    request.set_nodata(coordinates[*i]);
  } else if (draw.Chance(0.5)) {
    request.set_nodata(-9999);
  }
  uint32_t width = 1 + static_cast<uint32_t>(draw.Below(40));
  uint32_t height = 1 + static_cast<uint32_t>(draw.Below(40));
  double cell_size = 0;
  constexpr uint32_t kMax = std::numeric_limits<uint32_t>::max();
  const uint32_t side =
      static_cast<uint32_t>(std::sqrt(HostileLimits::kGridCells));
  const uint32_t http_side =
      static_cast<uint32_t>(std::sqrt(HostileLimits::kHttpGridCells));
  switch (shape) {
    case kZeroWidth:
      width = 0;
      break;
    case kZeroHeight:
      height = 0;
      break;
    case kOneCell:
      width = height = 1;
      break;
    case kSizeAndCellSize:
      cell_size = 0.5;
      break;
    case kNeither:
      width = height = 0;
      break;
    case kAtHttpCells:
      width = height = http_side;
      break;
    case kPastHttpCells:
      width = http_side + 1;
      height = http_side;
      break;
    case kPastCells:
      width = side + 1;
      height = side;
      break;
    case kPastCellsThin:
      width = 1;
      height = HostileLimits::kGridCells + 1;
      break;
    case kHugeShape:
      width = height = kMax;
      break;
    case kAtCells:
      width = height = side;
      break;
    case kAtCellsThin:
      width = HostileLimits::kGridCells;
      height = 1;
      break;
    default:
      break;
  }
  if (cell != kNoCell) {
    width = height = 0;
    cell_size = cell < coordinates.size()
                    ? coordinates[cell]
                    : box.width() / (cell == coordinates.size() ? 300 : 100);
    c.summary += " cell_size " + DoubleName(cell_size);
  } else {
    c.summary += " " + std::to_string(width) + " x " + std::to_string(height);
  }
  request.set_width(width);
  request.set_height(height);
  request.set_cell_size(cell_size);
  if (target.oracle == nullptr) return c;
  if (shape == kNoBox) {
    c.expect.Require(Code::INVALID_ARGUMENT, {"box"});
    return c;
  }
  const bool finite =
      IsFinite({box.min_x, box.min_y}) && IsFinite({box.max_x, box.max_y});
  const bool representable =
      finite && std::isfinite(box.width()) && std::isfinite(box.height());
  if (!finite || !(box.min_x < box.max_x) || !(box.min_y < box.max_y)) {
    c.expect.Require(Code::INVALID_ARGUMENT, kBoxNames);
  } else if (!hostile_box.empty()) {
    // Arithmetic on the box may overflow: answered or refused.
    c.expect.Allow(Code::INVALID_ARGUMENT, {"box", "cell"});
  }
  if (shape == kZeroWidth || shape == kZeroHeight || shape == kNeither ||
      shape == kSizeAndCellSize) {
    c.expect.Require(Code::INVALID_ARGUMENT, kShapeNames);
  }
  if (cell != kNoCell) {
    if (!(cell_size > 0) || !std::isfinite(cell_size)) {
      c.expect.Require(Code::INVALID_ARGUMENT, kCellSizeNames);
    } else if (!representable) {
      c.expect.Allow(Code::INVALID_ARGUMENT, {"box", "cell"})
          .Allow(Code::RESOURCE_EXHAUSTED, {"cell_size", "cells"});
    } else {
      const long double columns =
          std::ceil(static_cast<long double>(box.width()) / cell_size);
      const long double rows =
          std::ceil(static_cast<long double>(box.height()) / cell_size);
      ExpectCells(columns * rows, transport, &c.expect);
      // The cells' growth of the box may overflow.
      c.expect.Allow(Code::INVALID_ARGUMENT, {"box", "cell"});
    }
  } else if (width > 0 && height > 0 && cell_size == 0) {
    ExpectCells(static_cast<long double>(width) * height, transport, &c.expect);
  }
  return c;
}

}  // namespace locator::test
