#include "server/core/strategies/adaptive_paper_locator.h"

#include <algorithm>
#include <queue>
#include <random>
#include <unordered_set>

#include "server/core/geometry/wide_math.h"
#include "server/core/mesh/mesh_walk.h"
#include "server/core/tuning/hot_regions.h"

namespace locator {

namespace {

// "Slightly fatter": each side grows by this fraction of the rectangle.
constexpr double kFatten = 0.1;

bool Intersects(const BoundingBox& a, const BoundingBox& b) {
  return a.min_x <= b.max_x && b.min_x <= a.max_x && a.min_y <= b.max_y &&
         b.min_y <= a.max_y;
}

// r grown by kFatten of its size on every side. In Wide where r is wider
// than a double (a dataset spanning +-1e308), and then clamped to the
// doubles: a fat region must stay finite.
BoundingBox Fatten(const BoundingBox& r) {
  const BoundingBox fat = r.Inflated(kFatten);
  if (IsFinite({fat.min_x, fat.min_y}) && IsFinite({fat.max_x, fat.max_y}))
      [[likely]] {
    return fat;
  }
  const auto grow = [](double lo, double hi, double* fat_lo, double* fat_hi) {
    const Wide margin = (Wide{hi} - lo) * kFatten;
    *fat_lo = static_cast<double>(std::max(lo - margin, -kMaxDouble));
    *fat_hi = static_cast<double>(std::min(hi + margin, kMaxDouble));
  };
  BoundingBox wide;
  grow(r.min_x, r.max_x, &wide.min_x, &wide.max_x);
  grow(r.min_y, r.max_y, &wide.min_y, &wide.max_y);
  return wide;
}

BoundingBox FaceBox(const ServingMesh& mesh, uint32_t f) {
  BoundingBox b;
  for (int i = 0; i < 3; ++i) b.Extend(mesh.CornerPoint(f, i));
  return b;
}

}  // namespace

AdaptivePaperLocator::AdaptivePaperLocator(const ServingMesh& mesh,
                                           const TuningOptions& options)
    : mesh_(mesh),
      options_(options),
      fallback_(mesh),
      histogram_(GridGeometry(mesh.bounding_box(), options.grid_size)) {}

void AdaptivePaperLocator::Locate(const Point2& q, LocateResult* result,
                                  Detail detail) const {
  const Samples* s = samples_.Get();
  if (!s) {
    histogram_.Add(q);
    fallback_.Locate(q, result, detail);
    if (warmup_seen_.fetch_add(1, std::memory_order_relaxed) + 1 ==
        options_.warmup_queries) {
      Tune();
    }
    return;
  }
  const bool in_region =
      std::any_of(s->regions.begin(), s->regions.end(),
                  [&q](const BoundingBox& r) { return r.Contains(q); });
  if (!in_region) {
    fallback_.Locate(q, result, detail);
    return;
  }
  size_t best = 0;
  double best_d2 = SquaredDistance(s->points[0], q);
  for (size_t i = 1; i < s->points.size(); ++i) {
    const double d2 = SquaredDistance(s->points[i], q);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = i;
    }
  }
  result->cost = LocateCost();
  WalkAndDescribe(mesh_, s->faces[best], q, result, detail);
  result->cost.comparisons = static_cast<uint32_t>(s->points.size());
}

void AdaptivePaperLocator::Retune() { Tune(); }

void AdaptivePaperLocator::Tune() const {
  MutexLock lock(&tune_mu_);
  histogram_.Drain(&counts_);
  auto s = std::make_shared<Samples>();
  const std::shared_ptr<const Samples> old = samples_.Current();
  s->version = old ? old->version + 1 : 1;
  s->histogram = counts_;
  s->regions = FindHotRegions(histogram_.grid(), counts_);
  for (const BoundingBox& r : s->regions) {
    s->fat.push_back(Fatten(r));
    SampleRegion(s->fat.back(), s.get());
  }
  // A region whose sampling found nothing cannot serve queries.
  if (s->points.empty()) s->regions.clear();
  samples_.Publish(std::move(s));
}

void AdaptivePaperLocator::SampleRegion(const BoundingBox& fat,
                                        Samples* out) const {
  // Collect every edge whose midpoint lies in the fat rectangle by a
  // breadth-first search over the faces that overlap it, then draw the
  // samples uniformly without replacement. Same distribution as the paper's
  // rejection sampling, with a bounded running time.
  const Point2 centre =
      Midpoint({fat.min_x, fat.min_y}, {fat.max_x, fat.max_y});
  const uint32_t seed = FaceNear(mesh_, mesh_.DefaultStart(), centre);
  std::vector<std::pair<Point2, uint32_t>> edges;
  std::unordered_set<uint32_t> seen{seed};
  std::queue<uint32_t> frontier;
  frontier.push(seed);
  while (!frontier.empty()) {
    const uint32_t f = frontier.front();
    frontier.pop();
    for (int i = 0; i < 3; ++i) {
      const uint32_t n = mesh_.Neighbor(f, i);
      const bool hull = ServingMesh::IsHull(n);
      // Each edge once: from the face with the smaller index, or the hull
      // side.
      if (hull || f < n) {
        const Point2& a = mesh_.CornerPoint(f, Ccw(i));
        const Point2& b = mesh_.CornerPoint(f, Cw(i));
        const Point2 mid = Midpoint(a, b);
        if (fat.Contains(mid)) edges.emplace_back(mid, f);
      }
      if (!hull && !seen.count(n) && Intersects(FaceBox(mesh_, n), fat)) {
        seen.insert(n);
        frontier.push(n);
      }
    }
  }
  if (edges.empty()) {
    // The rectangle lies outside the hull: start from the nearest hull face.
    edges.emplace_back(mesh_.CornerPoint(seed, 0), seed);
  }
  std::mt19937_64 rng(options_.seed + out->points.size());
  const size_t k = std::min<size_t>(edges.size(), options_.samples_per_region);
  for (size_t i = 0; i < k; ++i) {
    std::uniform_int_distribution<size_t> pick(i, edges.size() - 1);
    std::swap(edges[i], edges[pick(rng)]);
    out->points.push_back(edges[i].first);
    out->faces.push_back(edges[i].second);
  }
}

TuningSummary AdaptivePaperLocator::Summary() const {
  TuningSummary sum;
  sum.grid_size = histogram_.grid().size();
  sum.grid_box = histogram_.grid().box();
  const std::shared_ptr<const Samples> s = samples_.Current();
  if (!s) return sum;
  sum.snapshot_version = s->version;
  sum.retune_count = s->version;
  sum.histogram = s->histogram;
  sum.hot_regions = s->regions;
  sum.start_points = s->points;
  sum.start_point_count = s->points.size();
  sum.memory_bytes =
      histogram_.MemoryBytes() + s->points.capacity() * sizeof(Point2) +
      s->faces.capacity() * sizeof(uint32_t) +
      (s->regions.capacity() + s->fat.capacity()) * sizeof(BoundingBox);
  return sum;
}

}  // namespace locator
