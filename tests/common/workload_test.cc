#include "common/workload.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace locator {
namespace {

// A non-unit target box, so the tests also check the mapping.
const BoundingBox kBox{10, -5, 30, 5};
// Slack for the unit -> box -> unit round trip.
constexpr double kEps = 1e-9;

Point2 ToUnit(const Point2& p) {
  return {(p.x - kBox.min_x) / kBox.width(),
          (p.y - kBox.min_y) / kBox.height()};
}

bool InSquare(const Point2& u, double x0, double y0, double side) {
  return u.x >= x0 - kEps && u.x <= x0 + side + kEps && u.y >= y0 - kEps &&
         u.y <= y0 + side + kEps;
}

// Index of the paper's 3-cluster square containing `u`, or -1.
int ThreeClusterSquare(const Point2& u) {
  if (InSquare(u, 0.47, 0.17, 0.06)) return 0;
  if (InSquare(u, 0.77, 0.77, 0.06)) return 1;
  if (InSquare(u, 0.17, 0.77, 0.06)) return 2;
  return -1;
}

bool NearDiagonal(const Point2& u, bool anti) {
  const double diagonal = anti ? 1 - u.x : u.x;
  return std::abs(u.y - diagonal) <= 0.02 + kEps;
}

TEST(WorkloadNamesTest, RoundTrip) {
  const std::vector<WorkloadKind>& kinds = AllWorkloadKinds();
  ASSERT_EQ(kinds.size(), 7u);
  std::set<std::string_view> names;
  for (WorkloadKind kind : kinds) {
    WorkloadKind parsed = WorkloadKind::kUniform;
    ASSERT_TRUE(ParseWorkloadKind(WorkloadName(kind), &parsed).ok());
    EXPECT_EQ(parsed, kind);
    names.insert(WorkloadName(kind));
  }
  EXPECT_EQ(names.size(), kinds.size());
  EXPECT_EQ(WorkloadName(WorkloadKind::kOneCluster), "1-cluster");
  EXPECT_EQ(WorkloadName(WorkloadKind::kXCluster), "x-cluster");
}

TEST(WorkloadNamesTest, UnknownNameListsValidOnes) {
  WorkloadKind kind = WorkloadKind::kDrift;
  const Status s = ParseWorkloadKind("Uniform", &kind);
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(s.message(),
            "unknown workload 'Uniform'; valid: uniform, 1-cluster, "
            "3-cluster, d-cluster, x-cluster, mixed, drift");
  EXPECT_EQ(kind, WorkloadKind::kDrift);
}

TEST(WorkloadTest, EveryKindStaysInBoxAndIsDeterministic) {
  for (WorkloadKind kind : AllWorkloadKinds()) {
    // A box whose corners are not exactly representable sums.
    const BoundingBox box{0.1, 0.2, 0.7, 0.3};
    Workload a(kind, box, 5, /*drift_period=*/100);
    Workload b(kind, box, 5, /*drift_period=*/100);
    Workload c(kind, box, 6, /*drift_period=*/100);
    bool differs = false;
    for (int i = 0; i < 20000; ++i) {
      const Point2 p = a.Next();
      const Point2 q = b.Next();
      const Point2 r = c.Next();
      ASSERT_TRUE(IsFinite(p) && box.Contains(p)) << WorkloadName(kind);
      ASSERT_EQ(p.x, q.x);
      ASSERT_EQ(p.y, q.y);
      differs |= p.x != r.x || p.y != r.y;
    }
    EXPECT_TRUE(differs) << WorkloadName(kind);
    EXPECT_EQ(a.count(), 20000u);
    EXPECT_EQ(a.kind(), kind);
  }
}

TEST(WorkloadTest, UniformCoversTheBox) {
  Workload w(WorkloadKind::kUniform, kBox, 1);
  std::set<int> cells;
  for (int i = 0; i < 10000; ++i) {
    const Point2 u = ToUnit(w.Next());
    cells.insert(static_cast<int>(u.x * 4) * 4 + static_cast<int>(u.y * 4));
  }
  EXPECT_EQ(cells.size(), 16u);
}

TEST(WorkloadTest, OneClusterSquare) {
  Workload w(WorkloadKind::kOneCluster, kBox, 2);
  for (int i = 0; i < 10000; ++i) {
    ASSERT_TRUE(InSquare(ToUnit(w.Next()), 0.48, 0.48, 0.04));
  }
}

TEST(WorkloadTest, ThreeClusterHitsAllThreeSquares) {
  Workload w(WorkloadKind::kThreeCluster, kBox, 3);
  int hits[3] = {0, 0, 0};
  for (int i = 0; i < 9000; ++i) {
    const int square = ThreeClusterSquare(ToUnit(w.Next()));
    ASSERT_GE(square, 0);
    ++hits[square];
  }
  for (int h : hits) EXPECT_GT(h, 2500);
}

TEST(WorkloadTest, DClusterBand) {
  Workload w(WorkloadKind::kDCluster, kBox, 4);
  double min_x = 1, max_x = 0;
  for (int i = 0; i < 10000; ++i) {
    const Point2 u = ToUnit(w.Next());
    ASSERT_TRUE(NearDiagonal(u, /*anti=*/false)) << u.x << "," << u.y;
    min_x = std::min(min_x, u.x);
    max_x = std::max(max_x, u.x);
  }
  EXPECT_LT(min_x, 0.01);
  EXPECT_GT(max_x, 0.99);
}

TEST(WorkloadTest, XClusterUsesBothDiagonals) {
  Workload w(WorkloadKind::kXCluster, kBox, 5);
  int main_only = 0, anti_only = 0;
  for (int i = 0; i < 10000; ++i) {
    const Point2 u = ToUnit(w.Next());
    const bool main = NearDiagonal(u, false), anti = NearDiagonal(u, true);
    ASSERT_TRUE(main || anti) << u.x << "," << u.y;
    main_only += main && !anti;
    anti_only += anti && !main;
  }
  EXPECT_GT(main_only, 4000);
  EXPECT_GT(anti_only, 4000);
}

TEST(WorkloadTest, MixedIsHalfThreeCluster) {
  Workload w(WorkloadKind::kMixed, kBox, 6);
  int clustered = 0;
  for (int i = 0; i < 10000; ++i) {
    clustered += ThreeClusterSquare(ToUnit(w.Next())) >= 0;
  }
  // Half from the squares, plus uniform points that land in them (~1%).
  EXPECT_GT(clustered, 4600);
  EXPECT_LT(clustered, 5600);
}

TEST(WorkloadTest, DriftJumpsEveryPeriodAndNotBefore) {
  constexpr int kPeriod = 50;
  Workload w(WorkloadKind::kDrift, kBox, 7, kPeriod);
  BoundingBox previous;
  for (int block = 0; block < 20; ++block) {
    BoundingBox current;
    for (int i = 0; i < kPeriod; ++i) current.Extend(ToUnit(w.Next()));
    // All of a block fits one 0.04 square inside the unit square...
    EXPECT_LE(current.width(), 0.04 + kEps) << block;
    EXPECT_LE(current.height(), 0.04 + kEps) << block;
    EXPECT_TRUE(BoundingBox({-kEps, -kEps, 1 + kEps, 1 + kEps})
                    .Contains({current.min_x, current.min_y}));
    EXPECT_TRUE(BoundingBox({-kEps, -kEps, 1 + kEps, 1 + kEps})
                    .Contains({current.max_x, current.max_y}));
    if (block == 0) {
      EXPECT_TRUE(InSquare({current.min_x, current.min_y}, 0.48, 0.48, 0.04));
      EXPECT_TRUE(InSquare({current.max_x, current.max_y}, 0.48, 0.48, 0.04));
    } else {
      // ...and the square moved at the block boundary.
      BoundingBox both = current;
      both.Extend({previous.min_x, previous.min_y});
      both.Extend({previous.max_x, previous.max_y});
      EXPECT_GT(std::max(both.width(), both.height()), 0.04) << block;
    }
    previous = current;
  }
  EXPECT_EQ(w.count(), 20u * kPeriod);
}

}  // namespace
}  // namespace locator
