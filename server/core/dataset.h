// Dataset: the input points (and optional values) a triangulation is built
// from, and the loaders that produce one.
//
// Sources, selected by LoadDataset's spec:
//   uniform:N[:SEED]        N points uniform in the unit square.
//   clusters:N:K[:SEED]     N points in K Gaussian blobs in the unit square
//                           (non-uniform data).
//   PATH ending in .node    Triangle's node format.
//   PATH ending in .poly    Triangle's poly format: points (the node section
//                           inline), segments, holes and optional regional
//                           attributes; its segments and holes bound the
//                           domain with Triangle's semantics.
//   any other PATH          CSV/XYZ text: "x,y[,z]" per line, comma- or
//                           whitespace-separated, optional header line,
//                           '#' comments, blank lines ignored.
// Every parse error is InvalidArgument with "file:line: what is wrong"
// (not a number, NaN/inf, wrong column count, empty file). A missing file is
// NotFound / IOError with the path.
//
// Thread-safety: free functions; a Dataset is a plain value.

#ifndef LOCATOR_CORE_DATASET_H_
#define LOCATOR_CORE_DATASET_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/geometry.h"
#include "common/status.h"

namespace locator {

// A polyline (breakline) or a ring (domain boundary; closed implicitly, the
// last point is not repeated), in dataset coordinates. `values` is empty or
// parallel to `points` (z along a surveyed breakline).
struct Polyline {
  std::vector<Point2> points;
  std::vector<double> values;
};

// What a constrained triangulation keeps besides the points. All empty for a
// plain point cloud (the Delaunay triangulation of its convex hull).
// A .poly regional attribute: the region around `seed` (bounded by the
// segments) carries `attribute`. Carried with the dataset; the core does not
// use it yet.
struct RegionalAttribute {
  Point2 seed;
  double attribute = 0;
};

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
  // memory is committed (each point costs ~200 bytes once triangulated).
  size_t max_points = 50'000'000;
};

// Whether `spec` names a generator (uniform:, clusters:) rather than a file.
bool IsGeneratorSpec(std::string_view spec);

// Loads a dataset from a file path or a generator spec (see above).
Status LoadDataset(const std::string& spec, Dataset* out,
                   const DatasetLimits& limits = DatasetLimits());

// Parses CSV/XYZ text. `filename` is only used in error messages.
Status ParseXyzText(std::string_view text, std::string_view filename,
                    Dataset* out,
                    const DatasetLimits& limits = DatasetLimits());

// Parses Triangle .node text ("<#points> <dim=2> <#attributes> <#markers>"
// then "<index> <x> <y> [attributes...] [marker]"); the first attribute, if
// any, becomes the value.
Status ParseNodeText(std::string_view text, std::string_view filename,
                     Dataset* out,
                     const DatasetLimits& limits = DatasetLimits());

// Parses Triangle .poly text: a node section as ParseNodeText (the vertex
// count must not be 0: points in a separate .node are not supported), then
// "<#segments> <#markers>" and "<index> <from> <to> [marker]" rows, then
// "<#holes>" and "<index> <x> <y>" rows, then optionally "<#regions>" and
// "<index> <x> <y> <attribute> [max area]" rows. Segment endpoints are point
// indices numbered like the node section (from 0 or 1).
Status ParsePolyText(std::string_view text, std::string_view filename,
                     Dataset* out,
                     const DatasetLimits& limits = DatasetLimits());

// Deterministic generators (same seed, same points, on every platform).
Dataset GenerateUniform(size_t n, uint64_t seed);
Dataset GenerateClusters(size_t n, size_t k, uint64_t seed);

}  // namespace locator

#endif  // LOCATOR_CORE_DATASET_H_
