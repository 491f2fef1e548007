// Dataset: the plain value a triangulation is built from — points, optional
// values, constraints (breaklines, domain rings, .poly segments and holes, a
// mesh given as triangles) and a CRS. The core's loaders
// (locator/dataset_sources.h) and the GIS adapters (common/gis) produce it; the
// engine consumes it.
//
// Thread-safety: plain values.

#ifndef LOCATOR_DATASET_H_
#define LOCATOR_DATASET_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "locator/geometry.h"

namespace locator {

// A polyline (breakline) or a ring (domain boundary; closed implicitly, the
// last point is not repeated), in dataset coordinates. `values` is empty or
// parallel to `points` (z along a surveyed breakline). `name` says where
// the source has it, for messages ("segment 3 at a.poly:12", "the exterior
// ring at lake.wkt:2", "roads.gpkg: layer 'roads': feature 7"); empty, the
// triangulation names it by its kind and index ("ring 0"). (Its default
// initializer lets aggregate initializations leave it out without a
// -Wmissing-field-initializers warning.)
struct Polyline {
  std::vector<Point2> points;
  std::vector<double> values;
  std::string name = {};
};

// A .poly regional attribute: the region around `seed` (bounded by the
// segments) carries `attribute`. Carried with the dataset; the core does not
// use it yet.
struct RegionalAttribute {
  Point2 seed;
  double attribute = 0;
};

// What a constrained triangulation keeps besides the points. All empty for a
// plain point cloud (the Delaunay triangulation of its convex hull).
struct DatasetConstraints {
  // Every segment of every breakline becomes a constrained edge; breaklines
  // do not bound the domain.
  std::vector<Polyline> breaklines;
  // Domain boundary rings, outer boundaries and holes alike: a face is in the
  // domain when the number of rings around it (its nesting depth) is odd.
  std::vector<Polyline> rings;
  // Triangle .poly semantics: every segment bounds regions; the region
  // reachable from outside the hull without crossing a segment is out of the
  // domain, and so is the region around each of these hole points.
  std::vector<Polyline> segments;
  std::vector<Point2> hole_seeds;
  // A mesh served as given: corner indices into Dataset::points. When set,
  // the in-domain faces are exactly these triangles.
  std::vector<std::array<uint32_t, 3>> triangles;
  // .poly regional attributes.
  std::vector<RegionalAttribute> regions;

  bool empty() const {
    return breaklines.empty() && rings.empty() && segments.empty() &&
           hole_seeds.empty() && triangles.empty();
  }
};

struct Dataset {
  std::vector<Point2> points;
  // Empty when the source has no values; otherwise parallel to `points`.
  std::vector<double> values;
  // The spec or path it came from, for stats and logs.
  std::string source;
  // Breaklines, domain and mesh triangles; empty for a plain point cloud.
  DatasetConstraints constraints;
  // The coordinate reference system as WKT; empty when the source has none.
  // The core carries it and never interprets it.
  std::string crs;

  bool has_values() const { return !values.empty(); }
};

struct DatasetLimits {
  // Loading more points than this fails with ResourceExhausted, before the
  // memory is committed (a build peaks at ~350 bytes per point: CGAL's
  // triangulation and the serving mesh derived from it).
  size_t max_points = 50'000'000;
};

}  // namespace locator

#endif  // LOCATOR_DATASET_H_
