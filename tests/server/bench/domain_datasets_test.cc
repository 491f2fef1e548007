#include "server/bench/datasets/domain_datasets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <utility>
#include <vector>

namespace locator::bench {
namespace {

double Orient(const Point2& a, const Point2& b, const Point2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Whether segments ab and cd cross or touch (shared endpoints excluded by
// the callers).
bool SegmentsMeet(const Point2& a, const Point2& b, const Point2& c,
                  const Point2& d) {
  const double o1 = Orient(a, b, c), o2 = Orient(a, b, d);
  if (o1 == 0 && o2 == 0) {  // collinear: do the extents overlap?
    return std::max(std::min(a.x, b.x), std::min(c.x, d.x)) <=
               std::min(std::max(a.x, b.x), std::max(c.x, d.x)) &&
           std::max(std::min(a.y, b.y), std::min(c.y, d.y)) <=
               std::min(std::max(a.y, b.y), std::max(c.y, d.y));
  }
  const double o3 = Orient(c, d, a), o4 = Orient(c, d, b);
  return ((o1 > 0) != (o2 > 0) || o1 == 0 || o2 == 0) &&
         ((o3 > 0) != (o4 > 0) || o3 == 0 || o4 == 0);
}

// Signed area (positive when counter-clockwise).
double RingArea(const Polyline& ring) {
  double twice = 0;
  const size_t k = ring.points.size();
  for (size_t i = 0; i < k; ++i) {
    const Point2& p = ring.points[i];
    const Point2& q = ring.points[(i + 1) % k];
    twice += p.x * q.y - q.x * p.y;
  }
  return twice / 2;
}

bool InsideRing(const Point2& p, const Polyline& ring) {
  bool inside = false;
  const size_t k = ring.points.size();
  for (size_t i = 0, j = k - 1; i < k; j = i++) {
    const Point2& a = ring.points[i];
    const Point2& b = ring.points[j];
    if ((a.y > p.y) != (b.y > p.y) &&
        p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
      inside = !inside;
    }
  }
  return inside;
}

// No two segments of the rings meet except neighbours of one ring at their
// shared corner.
void ExpectRingsSimpleAndDisjoint(const std::vector<Polyline>& rings) {
  struct Segment {
    size_t ring, index;
    Point2 a, b;
  };
  std::vector<Segment> segments;
  for (size_t r = 0; r < rings.size(); ++r) {
    const size_t k = rings[r].points.size();
    for (size_t i = 0; i < k; ++i) {
      segments.push_back(
          {r, i, rings[r].points[i], rings[r].points[(i + 1) % k]});
    }
  }
  for (size_t s = 0; s < segments.size(); ++s) {
    for (size_t t = s + 1; t < segments.size(); ++t) {
      const Segment& u = segments[s];
      const Segment& v = segments[t];
      const size_t k = rings[u.ring].points.size();
      if (u.ring == v.ring &&
          (v.index == u.index + 1 || (u.index == 0 && v.index == k - 1))) {
        continue;  // neighbours share a corner
      }
      EXPECT_FALSE(SegmentsMeet(u.a, u.b, v.a, v.b))
          << "ring " << u.ring << " segment " << u.index << " meets ring "
          << v.ring << " segment " << v.index;
    }
  }
}

// The outer ring and the holes: counter-clockwise, simple, disjoint, every
// hole inside the outer ring and its seed inside it and no other hole.
void ExpectValidDomain(const DomainDataset& d) {
  ASSERT_FALSE(d.domain_rings.empty());
  ASSERT_EQ(d.hole_seeds.size() + 1, d.domain_rings.size());
  for (const Polyline& ring : d.domain_rings) {
    EXPECT_GT(RingArea(ring), 0) << "rings are counter-clockwise";
  }
  ExpectRingsSimpleAndDisjoint(d.domain_rings);
  for (size_t h = 1; h < d.domain_rings.size(); ++h) {
    EXPECT_TRUE(InsideRing(d.domain_rings[h].points[0], d.domain_rings[0]));
    for (size_t r = 1; r < d.domain_rings.size(); ++r) {
      EXPECT_EQ(InsideRing(d.hole_seeds[h - 1], d.domain_rings[r]), r == h);
    }
  }
}

double DomainArea(const DomainDataset& d) {
  double area = RingArea(d.domain_rings[0]);
  for (size_t h = 1; h < d.domain_rings.size(); ++h) {
    area -= RingArea(d.domain_rings[h]);
  }
  return area;
}

// Whether p lies on segment ab (up to rounding).
bool OnSegment(const Point2& p, const Point2& a, const Point2& b) {
  const double length = std::sqrt(SquaredDistance(a, b));
  if (std::abs(Orient(a, b, p)) > 1e-12 * length) return false;
  const double t = ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) /
                   (length * length);
  return t >= -1e-12 && t <= 1 + 1e-12;
}

bool OnDomainBoundary(const Point2& p, const Point2& q,
                      const std::vector<Polyline>& rings) {
  for (const Polyline& ring : rings) {
    const size_t k = ring.points.size();
    for (size_t i = 0; i < k; ++i) {
      const Point2& a = ring.points[i];
      const Point2& b = ring.points[(i + 1) % k];
      if (OnSegment(p, a, b) && OnSegment(q, a, b)) return true;
    }
  }
  return false;
}

// A mesh served as given: every triangle counter-clockwise and not
// degenerate, every point a corner, consistently oriented and manifold (a
// directed edge at most once, so an edge has at most two triangles, on
// opposite sides), its border edges on the domain boundary, and its area
// the domain's: together, the triangles cover the domain exactly once.
void ExpectMeshCoversDomainOnce(const DomainDataset& d) {
  const std::vector<Point2>& points = d.dataset.points;
  const auto& triangles = d.dataset.constraints.triangles;
  ASSERT_FALSE(triangles.empty());
  std::vector<bool> used(points.size(), false);
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  double area = 0;
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& c = triangles[t];
    for (uint32_t i : c) ASSERT_LT(i, points.size()) << "triangle " << t;
    const double twice = Orient(points[c[0]], points[c[1]], points[c[2]]);
    ASSERT_GT(twice, 0) << "triangle " << t << " is not counter-clockwise";
    area += twice / 2;
    for (int e = 0; e < 3; ++e) {
      used[c[e]] = true;
      const std::pair<uint32_t, uint32_t> edge(c[e], c[(e + 1) % 3]);
      ASSERT_EQ(++directed[edge], 1)
          << "directed edge of triangle " << t << " appears twice";
    }
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
  size_t border = 0;
  for (const auto& [edge, count] : directed) {
    if (directed.count({edge.second, edge.first})) continue;
    ++border;
    ASSERT_TRUE(OnDomainBoundary(points[edge.first], points[edge.second],
                                 d.domain_rings))
        << "border edge " << edge.first << "-" << edge.second
        << " is not on the domain boundary";
  }
  EXPECT_GT(border, 0u);
  EXPECT_NEAR(area, DomainArea(d), 1e-9);
}

bool SameDataset(const Dataset& a, const Dataset& b) {
  auto same_points = [](const std::vector<Point2>& p,
                        const std::vector<Point2>& q) {
    return p.size() == q.size() &&
           std::memcmp(p.data(), q.data(), p.size() * sizeof(Point2)) == 0;
  };
  auto same_lines = [&](const std::vector<Polyline>& p,
                        const std::vector<Polyline>& q) {
    if (p.size() != q.size()) return false;
    for (size_t i = 0; i < p.size(); ++i) {
      if (!same_points(p[i].points, q[i].points)) return false;
    }
    return true;
  };
  return same_points(a.points, b.points) &&
         same_lines(a.constraints.rings, b.constraints.rings) &&
         same_lines(a.constraints.breaklines, b.constraints.breaklines) &&
         a.constraints.triangles == b.constraints.triangles &&
         a.source == b.source;
}

class DomainDatasetsTest : public ::testing::TestWithParam<DomainKind> {};

TEST_P(DomainDatasetsTest, SameSeedSameDataDifferentSeedDifferentData) {
  const DomainDataset a = GenerateDomainDataset(GetParam(), 10000, 3);
  const DomainDataset b = GenerateDomainDataset(GetParam(), 10000, 3);
  const DomainDataset c = GenerateDomainDataset(GetParam(), 10000, 4);
  EXPECT_TRUE(SameDataset(a.dataset, b.dataset));
  EXPECT_FALSE(SameDataset(a.dataset, c.dataset));
}

TEST_P(DomainDatasetsTest, NamesRoundTrip) {
  DomainKind parsed;
  ASSERT_TRUE(ParseDomainKind(DomainKindName(GetParam()), &parsed).ok());
  EXPECT_EQ(parsed, GetParam());
}

INSTANTIATE_TEST_SUITE_P(AllKinds, DomainDatasetsTest,
                         ::testing::Values(DomainKind::kCdt, DomainKind::kMesh,
                                           DomainKind::kAniso),
                         [](const auto& info) {
                           return std::string(DomainKindName(info.param));
                         });

TEST(DomainDatasets, UnknownKindIsAnError) {
  DomainKind kind;
  const Status s = ParseDomainKind("delaunay", &kind);
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(s.message().find("cdt, mesh, aniso"), std::string::npos);
}

TEST(DomainDatasets, CdtHasUniformPointsBreaklinesAndFiveHoles) {
  for (size_t n : {10000u, 50000u}) {
    const DomainDataset d = GenerateDomainDataset(DomainKind::kCdt, n, 1);
    const DatasetConstraints& c = d.dataset.constraints;
    EXPECT_EQ(d.dataset.points.size(), n);
    EXPECT_EQ(c.breaklines.size(), 50u);
    EXPECT_EQ(c.rings.size(), 6u);
    EXPECT_TRUE(c.triangles.empty());
    ASSERT_EQ(d.hole_seeds.size(), 5u);
    ExpectValidDomain(d);
    for (size_t r = 0; r < c.rings.size(); ++r) {
      EXPECT_EQ(RingArea(c.rings[r]), RingArea(d.domain_rings[r]));
    }
    // The points are those of uniform:n:1.
    EXPECT_TRUE(std::memcmp(d.dataset.points.data(),
                            GenerateUniform(n, 1).points.data(),
                            n * sizeof(Point2)) == 0);
    const BoundingBox unit{0, 0, 1, 1};
    size_t crossings = 0;
    for (size_t i = 0; i < c.breaklines.size(); ++i) {
      const auto& line = c.breaklines[i].points;
      ASSERT_GE(line.size(), 2u);
      for (size_t k = 0; k < line.size(); ++k) {
        EXPECT_TRUE(unit.Contains(line[k]));
        if (k > 0) {
          EXPECT_GT(SquaredDistance(line[k - 1], line[k]), 0);
        }
      }
      for (size_t j = i + 1; j < c.breaklines.size(); ++j) {
        const auto& other = c.breaklines[j].points;
        for (size_t k = 1; k < line.size(); ++k) {
          for (size_t m = 1; m < other.size(); ++m) {
            crossings +=
                SegmentsMeet(line[k - 1], line[k], other[m - 1], other[m]);
          }
        }
      }
    }
    // Crossing breaklines are part of what the kind exercises.
    EXPECT_GT(crossings, 0u);
  }
}

TEST(DomainDatasets, MeshIsAGradedQualityMeshOfTheDomain) {
  for (size_t n : {10000u, 50000u}) {
    const DomainDataset d = GenerateDomainDataset(DomainKind::kMesh, n, 2);
    const double count = static_cast<double>(d.dataset.points.size());
    EXPECT_NEAR(count, static_cast<double>(n), 0.05 * n);
    EXPECT_EQ(d.hole_seeds.size(), 5u);
    EXPECT_TRUE(d.dataset.constraints.rings.empty());
    ExpectValidDomain(d);
    ExpectMeshCoversDomainOnce(d);
    // No triangle in a hole.
    const auto& p = d.dataset.points;
    for (const auto& t : d.dataset.constraints.triangles) {
      const Point2 centroid{(p[t[0]].x + p[t[1]].x + p[t[2]].x) / 3,
                            (p[t[0]].y + p[t[1]].y + p[t[2]].y) / 3};
      for (size_t h = 1; h < d.domain_rings.size(); ++h) {
        ASSERT_FALSE(InsideRing(centroid, d.domain_rings[h]));
      }
    }
    // Strongly varying density: the largest triangles are much larger than
    // the smallest (the size field alone allows 12^2).
    std::vector<double> areas;
    for (const auto& t : d.dataset.constraints.triangles) {
      areas.push_back(Orient(p[t[0]], p[t[1]], p[t[2]]));
    }
    std::sort(areas.begin(), areas.end());
    EXPECT_GT(areas[areas.size() * 99 / 100], 50 * areas[areas.size() / 100]);
  }
}

// An interior edge is locally Delaunay when the opposite corner of one of its
// triangles is not strictly inside the other's circumcircle.
bool LocallyDelaunay(const Point2& a, const Point2& b, const Point2& c,
                     const Point2& d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) -
                     (bdx * bdx + bdy * bdy) * (adx * cdy - cdx * ady) +
                     (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return det <= 0;
}

TEST(DomainDatasets, AnisoIsAStretchedNonDelaunayGridOverTheUnitSquare) {
  for (size_t n : {10000u, 50000u}) {
    const DomainDataset d = GenerateDomainDataset(DomainKind::kAniso, n, 3);
    const auto& p = d.dataset.points;
    EXPECT_NEAR(static_cast<double>(p.size()), static_cast<double>(n),
                0.01 * n);
    EXPECT_TRUE(d.hole_seeds.empty());
    ExpectValidDomain(d);
    ExpectMeshCoversDomainOnce(d);
    // Long thin triangles: the median aspect (width over height of the
    // bounding box) is around 50.
    const auto& triangles = d.dataset.constraints.triangles;
    std::vector<double> aspects;
    for (const auto& t : triangles) {
      BoundingBox box;
      for (uint32_t i : t) box.Extend(p[i]);
      aspects.push_back(box.width() / box.height());
    }
    std::nth_element(aspects.begin(), aspects.begin() + aspects.size() / 2,
                     aspects.end());
    EXPECT_GT(aspects[aspects.size() / 2], 25);
    EXPECT_LT(aspects[aspects.size() / 2], 100);
    // Not Delaunay: a good share of the interior edges fail the empty
    // circle test.
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> opposite;
    for (const auto& t : triangles) {
      for (int e = 0; e < 3; ++e) {
        opposite[{t[e], t[(e + 1) % 3]}] = t[(e + 2) % 3];
      }
    }
    size_t interior = 0, flippable = 0;
    for (const auto& [edge, apex] : opposite) {
      const auto twin = opposite.find({edge.second, edge.first});
      if (twin == opposite.end() || edge.first > edge.second) continue;
      ++interior;
      flippable += !LocallyDelaunay(p[edge.first], p[edge.second], p[apex],
                                    p[twin->second]);
    }
    EXPECT_GT(flippable, interior / 10);
  }
}

}  // namespace
}  // namespace locator::bench
