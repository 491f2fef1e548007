#include "tests/core/locator_checks.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tests/core/test_datasets.h"

namespace locator::test {

namespace {

// Failures AllAgree() describes in full; the rest are only counted.
constexpr int kReportedFailures = 5;

CGAL::Orientation Side(const Point2& a, const Point2& b, const Point2& q) {
  return CGAL::orientation(Triangulation::ToCgal(a), Triangulation::ToCgal(b),
                           Triangulation::ToCgal(q));
}

bool SamePoint(const Point2& a, const Point2& b) {
  return a.x == b.x && a.y == b.y;
}

// The location type the exact sides of q against the three edges imply,
// for a triangle that contains q; false if q is outside it.
bool TypeFromSides(const CGAL::Orientation side[3], LocationType* type,
                   int* feature) {
  int zeros = 0;
  int zero = -1;
  int nonzero = -1;
  for (int i = 0; i < 3; ++i) {
    if (side[i] == CGAL::RIGHT_TURN) return false;
    if (side[i] == CGAL::COLLINEAR) {
      ++zeros;
      zero = i;
    } else {
      nonzero = i;
    }
  }
  *type = zeros == 0   ? LocationType::kFace
          : zeros == 1 ? LocationType::kEdge
                       : LocationType::kVertex;
  *feature = zeros == 0 ? -1 : (zeros == 1 ? zero : nonzero);
  return zeros < 3;
}

}  // namespace

TriangleIndex::TriangleIndex(const Triangulation& t) : ids_(t.num_triangles()) {
  // CGAL's faces, rotated as the serving mesh rotates every face: the
  // smallest id first.
  const auto& dt = t.cgal();
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    if (!t.InDomain(f)) continue;
    const std::array<uint32_t, 3> ids = t.CornerIds(f);
    const size_t r = std::min_element(ids.begin(), ids.end()) - ids.begin();
    for (int i = 0; i < 3; ++i) ids_[f->info()][i] = ids[(i + r) % 3];
  }
}

std::string DescribeAnswer(const Point2& q, const LocateResult& r) {
  std::ostringstream out;
  out.precision(17);
  out << "(" << q.x << ", " << q.y << ") " << LocationTypeName(r.type)
      << " triangle " << r.triangle_id << " ids [" << r.vertex_ids[0] << " "
      << r.vertex_ids[1] << " " << r.vertex_ids[2] << "] feature "
      << int{r.feature_index} << " hull edge [" << r.hull_edge_ids[0] << " "
      << r.hull_edge_ids[1] << "] domain edge [" << r.domain_edge_ids[0] << " "
      << r.domain_edge_ids[1] << "]";
  return out.str();
}

::testing::AssertionResult AnswerIsConsistent(const Triangulation& t,
                                              const TriangleIndex& index,
                                              const Point2& q,
                                              const LocateResult& got) {
  auto fail = [&](std::string_view what) {
    return ::testing::AssertionFailure()
           << what << ": " << DescribeAnswer(q, got);
  };
  if (got.type == LocationType::kOutsideDomain) {
    if (got.triangle_id != -1 || got.vertex_ids[0] != -1) {
      return fail("a triangle outside the domain");
    }
    if (got.has_value || got.barycentric != std::array<double, 3>{0, 0, 0}) {
      return fail("a value or barycentrics outside the domain");
    }
    Point2 a, b;
    if (!t.VertexPoint(got.domain_edge_ids[0], &a) ||
        !t.VertexPoint(got.domain_edge_ids[1], &b)) {
      return fail("no domain boundary edge");
    }
    return ::testing::AssertionSuccess();
  }
  // Outside the hull, a hull triangle outside the domain has no id.
  const bool hull_out_of_domain =
      got.type == LocationType::kOutsideConvexHull && got.triangle_id == -1;
  if (!hull_out_of_domain &&
      (got.triangle_id < 0 ||
       static_cast<size_t>(got.triangle_id) >= index.size())) {
    return fail("triangle id out of range");
  }
  if (!hull_out_of_domain && got.vertex_ids != index.ids(got.triangle_id)) {
    return fail("vertex ids are not the triangle's");
  }
  for (int i = 0; i < 3; ++i) {
    Point2 p;
    if (!t.VertexPoint(got.vertex_ids[i], &p) ||
        !SamePoint(p, got.vertices[i])) {
      return fail("corner coordinates do not match the vertex ids");
    }
  }
  CGAL::Orientation side[3];
  for (int i = 0; i < 3; ++i) {
    side[i] = Side(got.vertices[Ccw(i)], got.vertices[Cw(i)], q);
  }
  const int fi = got.feature_index;
  if (got.type == LocationType::kOutsideConvexHull) {
    if (fi < 0 || fi > 2) return fail("bad feature index");
    if (side[fi] != CGAL::RIGHT_TURN) return fail("hull edge does not see q");
    if (got.hull_edge_ids[0] != got.vertex_ids[Ccw(fi)] ||
        got.hull_edge_ids[1] != got.vertex_ids[Cw(fi)]) {
      return fail("hull edge is not the triangle's edge `feature_index`");
    }
    if (got.has_value) return fail("value outside the hull");
    return ::testing::AssertionSuccess();
  }
  LocationType type;
  int feature;
  if (!TypeFromSides(side, &type, &feature)) {
    return fail("triangle does not contain q");
  }
  if (type != got.type || feature != fi) {
    return fail("type/feature do not match the exact position of q");
  }
  const double sum =
      got.barycentric[0] + got.barycentric[1] + got.barycentric[2];
  if (!(std::abs(sum - 1) <= kBarycentricTolerance)) {
    return fail("barycentrics sum to " + std::to_string(sum));
  }
  if (type == LocationType::kEdge && got.barycentric[fi] != 0) {
    return fail("edge answer with a non-zero opposite barycentric");
  }
  if (type == LocationType::kVertex && got.barycentric[fi] != 1) {
    return fail("vertex answer with barycentric != 1 at the vertex");
  }
  if (got.has_value != t.has_values()) return fail("has_value is wrong");
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult AllAgree(const PointLocator& locator,
                                    const Triangulation& t,
                                    const TriangleIndex& index,
                                    std::span<const Point2> queries,
                                    std::span<const LocateResult> refs) {
  if (queries.size() != refs.size()) {
    return ::testing::AssertionFailure() << "queries/references mismatch";
  }
  int failures = 0;
  std::ostringstream report;
  auto note = [&](size_t i, const std::string& what) {
    if (++failures <= kReportedFailures) {
      report << "\n  query " << i << ": " << what;
    }
  };
  LocateResult got;
  for (size_t i = 0; i < queries.size(); ++i) {
    const Point2& q = queries[i];
    locator.Locate(q, &got);
    if (!t.Agrees(q, got, refs[i])) {
      note(i, "got " + DescribeAnswer(q, got) + " but reference " +
                  DescribeAnswer(q, refs[i]));
      continue;
    }
    if (auto ok = AnswerIsConsistent(t, index, q, got); !ok) {
      note(i, ok.message());
    }
    if (auto ok = AnswerIsConsistent(t, index, q, refs[i]); !ok) {
      note(i, std::string("reference: ") + ok.message());
    }
  }
  if (failures == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << locator.name() << ": " << failures << " of " << queries.size()
         << " answers wrong:" << report.str();
}

void ExpectAllAgree(const PointLocator& locator, const Triangulation& t,
                    std::span<const Point2> queries) {
  const TriangleIndex index(t);
  const std::vector<LocateResult> refs = ReferenceAnswers(t, queries);
  EXPECT_TRUE(AllAgree(locator, t, index, queries, refs));
}

}  // namespace locator::test
