#include "server/bench/datasets/domain_datasets.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "common/random.h"
#include "server/bench/datasets/quality_mesh.h"

namespace locator::bench {

namespace {

constexpr size_t kHoles = 5;
constexpr size_t kBreaklines = 50;

// A random walk of 2..6 vertices with steps of 0.02..0.08, inside the unit
// square (a step that would leave it is drawn again).
Polyline RandomBreakline(std::mt19937_64& rng) {
  Polyline line;
  line.points.push_back(
      {UniformDouble(rng, 0.02, 0.98), UniformDouble(rng, 0.02, 0.98)});
  const size_t vertices = 2 + static_cast<size_t>(UnitDouble(rng) * 5);
  while (line.points.size() < vertices) {
    const double angle = 2.0 * std::numbers::pi * UnitDouble(rng);
    const double step = UniformDouble(rng, 0.02, 0.08);
    const Point2 p{line.points.back().x + step * std::cos(angle),
                   line.points.back().y + step * std::sin(angle)};
    if (p.x > 0.0 && p.x < 1.0 && p.y > 0.0 && p.y < 1.0) {
      line.points.push_back(p);
    }
  }
  return line;
}

DomainDataset GenerateCdt(size_t n, uint64_t seed) {
  DomainDataset out;
  out.dataset = GenerateUniform(n, seed);
  // The constraints come from a stream of their own, so that the points
  // stay those of uniform:n:seed.
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  out.domain_rings.push_back(NotchedSquare());
  RandomHoles(kHoles, rng, &out.domain_rings, &out.hole_seeds);
  DatasetConstraints& c = out.dataset.constraints;
  c.rings = out.domain_rings;
  for (size_t i = 0; i < kBreaklines; ++i) {
    c.breaklines.push_back(RandomBreakline(rng));
  }
  out.dataset.source = "cdt:" + std::to_string(n) + ":" + std::to_string(seed);
  return out;
}

// Columns c and rows r with c * r ~ n and cells (1/(c-1)) x (1/(r-1)) about
// 50:1, i.e. r - 1 ~ 50 (c - 1).
DomainDataset GenerateAniso(size_t n, uint64_t seed) {
  constexpr double kAspect = 50.0;
  const double nd = static_cast<double>(std::max<size_t>(n, 8));
  const size_t cols = std::max<size_t>(
      2, static_cast<size_t>(std::lround(
             ((kAspect - 1) +
              std::sqrt((kAspect - 1) * (kAspect - 1) + 4 * kAspect * nd)) /
             (2 * kAspect))));
  const size_t rows =
      std::max<size_t>(2, static_cast<size_t>(std::lround(nd / cols)));
  const double dx = 1.0 / static_cast<double>(cols - 1);
  const double dy = 1.0 / static_cast<double>(rows - 1);
  std::mt19937_64 rng(seed);
  DomainDataset out;
  std::vector<Point2>& points = out.dataset.points;
  points.reserve(cols * rows);
  // Row-major, y outermost. A node moves by up to 0.2 of a cell along each
  // axis, except across the boundary, so every cell stays convex and the
  // union of the cells stays the unit square.
  for (size_t j = 0; j < rows; ++j) {
    for (size_t i = 0; i < cols; ++i) {
      const double jx = UniformDouble(rng, -0.2, 0.2);
      const double jy = UniformDouble(rng, -0.2, 0.2);
      const bool x_inside = i > 0 && i + 1 < cols;
      const bool y_inside = j > 0 && j + 1 < rows;
      points.push_back({(static_cast<double>(i) + (x_inside ? jx : 0)) * dx,
                        (static_cast<double>(j) + (y_inside ? jy : 0)) * dy});
    }
  }
  auto& triangles = out.dataset.constraints.triangles;
  for (size_t j = 0; j + 1 < rows; ++j) {
    for (size_t i = 0; i + 1 < cols; ++i) {
      const auto a = static_cast<uint32_t>(j * cols + i);  // lower left
      const auto b = a + 1;                                // lower right
      const auto d = static_cast<uint32_t>(a + cols);      // upper left
      const auto e = d + 1;                                // upper right
      if (rng() & 1) {
        triangles.push_back({a, b, e});
        triangles.push_back({a, e, d});
      } else {
        triangles.push_back({a, b, d});
        triangles.push_back({b, e, d});
      }
    }
  }
  out.domain_rings.push_back(Polyline{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}});
  out.dataset.source =
      "aniso:" + std::to_string(n) + ":" + std::to_string(seed);
  return out;
}

}  // namespace

std::string_view DomainKindName(DomainKind kind) {
  switch (kind) {
    case DomainKind::kCdt:
      return "cdt";
    case DomainKind::kMesh:
      return "mesh";
    case DomainKind::kAniso:
      return "aniso";
  }
  return "?";
}

Status ParseDomainKind(std::string_view name, DomainKind* kind) {
  for (DomainKind k :
       {DomainKind::kCdt, DomainKind::kMesh, DomainKind::kAniso}) {
    if (name == DomainKindName(k)) {
      *kind = k;
      return Status::OK();
    }
  }
  return Status::InvalidArgument("unknown domain kind '" + std::string(name) +
                                 "' (valid: cdt, mesh, aniso)");
}

DomainDataset GenerateDomainDataset(DomainKind kind, size_t n, uint64_t seed) {
  switch (kind) {
    case DomainKind::kCdt:
      return GenerateCdt(n, seed);
    case DomainKind::kMesh:
      return GenerateQualityMesh(n, seed);
    case DomainKind::kAniso:
      return GenerateAniso(n, seed);
  }
  return {};
}

Polyline NotchedSquare() {
  return Polyline{
      {{0, 0}, {1, 0}, {1, 1}, {0.65, 1}, {0.5, 0.75}, {0.35, 1}, {0, 1}}, {}};
}

void RandomHoles(size_t count, std::mt19937_64& rng,
                 std::vector<Polyline>* rings, std::vector<Point2>* centres) {
  struct Disk {
    Point2 centre;
    double radius;
  };
  std::vector<Disk> placed;
  while (placed.size() < count) {
    const double r = UniformDouble(rng, 0.04, 0.08);
    const Disk disk{{UniformDouble(rng, 0.05 + r, 0.95 - r),
                     UniformDouble(rng, 0.05 + r, 0.72 - r)},
                    r};
    const bool overlaps =
        std::any_of(placed.begin(), placed.end(), [&](const Disk& o) {
          return std::sqrt(SquaredDistance(o.centre, disk.centre)) <
                 o.radius + disk.radius + 0.02;
        });
    if (overlaps) continue;
    placed.push_back(disk);
    // A star: 2k corners at increasing angles, radii alternating r and 0.6 r,
    // so the ring is simple, concave and its centre sees all of it.
    const size_t corners = 2 * (3 + static_cast<size_t>(UnitDouble(rng) * 4));
    const double turn = 2.0 * std::numbers::pi * UnitDouble(rng);
    Polyline ring;
    for (size_t i = 0; i < corners; ++i) {
      const double angle = turn + 2.0 * std::numbers::pi *
                                      static_cast<double>(i) /
                                      static_cast<double>(corners);
      const double radius = (i % 2 == 0) ? r : 0.6 * r;
      ring.points.push_back({disk.centre.x + radius * std::cos(angle),
                             disk.centre.y + radius * std::sin(angle)});
    }
    rings->push_back(std::move(ring));
    centres->push_back(disk.centre);
  }
}

}  // namespace locator::bench
