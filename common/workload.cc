#include "common/workload.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/random.h"

namespace locator {
namespace {

// Paper, Section III: the 1-cluster square is 0.04 wide, the 3-cluster
// squares 0.06, the diagonal bands +-0.02 high.
constexpr double kOneClusterSide = 0.04;
constexpr double kThreeClusterSide = 0.06;
constexpr std::array<Point2, 3> kThreeClusterCorners = {
    Point2{0.47, 0.17}, Point2{0.77, 0.77}, Point2{0.17, 0.77}};
constexpr double kBandHalfHeight = 0.02;

Point2 UniformPoint(std::mt19937_64& rng) {
  // x is drawn before y: the order is part of the stream's definition.
  const double x = UnitDouble(rng);
  const double y = UnitDouble(rng);
  return Point2{x, y};
}

// One of the three 3-cluster squares, chosen uniformly.
const Point2& ThreeClusterCorner(std::mt19937_64& rng) {
  return kThreeClusterCorners[UniformIndex(rng, 3)];
}

}  // namespace

const std::vector<WorkloadKind>& AllWorkloadKinds() {
  static const std::vector<WorkloadKind> kinds = {
      WorkloadKind::kUniform,      WorkloadKind::kOneCluster,
      WorkloadKind::kThreeCluster, WorkloadKind::kDCluster,
      WorkloadKind::kXCluster,     WorkloadKind::kMixed,
      WorkloadKind::kDrift};
  return kinds;
}

std::string_view WorkloadName(WorkloadKind kind) {
  switch (kind) {
    case WorkloadKind::kUniform:
      return "uniform";
    case WorkloadKind::kOneCluster:
      return "1-cluster";
    case WorkloadKind::kThreeCluster:
      return "3-cluster";
    case WorkloadKind::kDCluster:
      return "d-cluster";
    case WorkloadKind::kXCluster:
      return "x-cluster";
    case WorkloadKind::kMixed:
      return "mixed";
    case WorkloadKind::kDrift:
      return "drift";
  }
  return "unknown";
}

Status ParseWorkloadKind(std::string_view name, WorkloadKind* kind) {
  std::string valid;
  for (WorkloadKind k : AllWorkloadKinds()) {
    if (WorkloadName(k) == name) {
      *kind = k;
      return Status::OK();
    }
    if (!valid.empty()) valid += ", ";
    valid += WorkloadName(k);
  }
  return Status::InvalidArgument("unknown workload '" + std::string(name) +
                                 "'; valid: " + valid);
}

Workload::Workload(WorkloadKind kind, const BoundingBox& box, uint64_t seed,
                   uint64_t drift_period)
    : kind_(kind),
      box_(box),
      rng_(seed),
      // A period of 0 would mean dividing by zero; treat it as "every query".
      drift_period_(std::max<uint64_t>(drift_period, 1)) {}

Point2 Workload::Next() {
  const Point2 u = NextUnit();
  ++count_;
  // min() because min + 1.0 * (max - min) can round past max.
  return Point2{std::min(box_.min_x + u.x * box_.width(), box_.max_x),
                std::min(box_.min_y + u.y * box_.height(), box_.max_y)};
}

Point2 Workload::NextUnit() {
  const auto three_cluster = [this] {
    const Point2& c = ThreeClusterCorner(rng_);
    return InSquare(c.x, c.y, kThreeClusterSide);
  };
  switch (kind_) {
    case WorkloadKind::kUniform:
      return UniformPoint(rng_);
    case WorkloadKind::kOneCluster:
      return InSquare(0.48, 0.48, kOneClusterSide);
    case WorkloadKind::kThreeCluster:
      return three_cluster();
    case WorkloadKind::kDCluster:
      return NearDiagonal(/*anti=*/false);
    case WorkloadKind::kXCluster:
      return NearDiagonal(/*anti=*/UnitDouble(rng_) < 0.5);
    case WorkloadKind::kMixed:
      return UnitDouble(rng_) < 0.5 ? three_cluster() : UniformPoint(rng_);
    case WorkloadKind::kDrift:
      if (count_ > 0 && count_ % drift_period_ == 0) {
        const double x = UniformDouble(rng_, 0.0, 1.0 - kOneClusterSide);
        const double y = UniformDouble(rng_, 0.0, 1.0 - kOneClusterSide);
        drift_corner_ = Point2{x, y};
      }
      return InSquare(drift_corner_.x, drift_corner_.y, kOneClusterSide);
  }
  return UniformPoint(rng_);  // not reached: the switch covers every kind
}

Point2 Workload::InSquare(double x0, double y0, double side) {
  // x is drawn before y: the order is part of the stream's definition.
  const double x = x0 + side * UnitDouble(rng_);
  const double y = y0 + side * UnitDouble(rng_);
  return Point2{x, y};
}

Point2 Workload::NearDiagonal(bool anti) {
  // Resampling both coordinates (not just the offset) keeps the density
  // uniform over the band's part inside the square, corners included.
  while (true) {
    const double x = UnitDouble(rng_);
    const double offset =
        UniformDouble(rng_, -kBandHalfHeight, kBandHalfHeight);
    const double y = (anti ? 1.0 - x : x) + offset;
    if (y >= 0.0 && y <= 1.0) return Point2{x, y};
  }
}

std::vector<Point2> WorkloadQueries(WorkloadKind kind, const BoundingBox& box,
                                    size_t count, uint64_t seed) {
  Workload workload(kind, box, seed);
  std::vector<Point2> queries(count);
  for (Point2& q : queries) q = workload.Next();
  return queries;
}

std::vector<Point2> RasterQueries(const BoundingBox& box, size_t count) {
  const size_t columns =
      static_cast<size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
  const size_t rows = columns == 0 ? 0 : (count + columns - 1) / columns;
  std::vector<Point2> queries(count);
  for (size_t i = 0; i < count; ++i) {
    queries[i] = {box.min_x + (i % columns + 0.5) * box.width() / columns,
                  box.min_y + (i / columns + 0.5) * box.height() / rows};
  }
  return queries;
}

}  // namespace locator
