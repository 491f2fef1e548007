// Domain datasets: the three kinds of non-Delaunay input that locator-bench
// measures Jump&Walk on (the paper's open question, Section IV), each a
// Dataset with constraints, in the unit square:
//
//   cdt    n uniform points, 50 random breaklines (polylines, crossings
//          allowed) and a concave outer ring with 5 star-shaped hole rings.
//   mesh   a quality mesh of the same kind of domain (concave outer ring,
//          5 holes) made by CGAL's Delaunay_mesher_2 with a size field that
//          is 12x finer near a focus point than far from it (about 150x the
//          point density), served as given: points plus in-domain triangles.
//   aniso  a jittered structured grid whose cells are about 50 times wider
//          than tall, each cell split by a random diagonal (so not Delaunay),
//          served as given: points plus triangles covering the unit square.
//
// Every generator is deterministic: the same (n, seed) gives the same dataset
// (the mesher is run on the same input in the same order). Point counts are
// exactly n for cdt, within 1% of n for aniso and within 5% for mesh.
//
// Benchmark-only code: not part of the shipped core library.
// Thread-safety: free functions over plain values.

#ifndef LOCATOR_SERVER_BENCH_DOMAIN_DATASETS_H_
#define LOCATOR_SERVER_BENCH_DOMAIN_DATASETS_H_

#include <cstddef>
#include <cstdint>
#include <random>
#include <string_view>
#include <vector>

#include "locator/dataset_sources.h"
#include "locator/geometry.h"
#include "locator/status.h"

namespace locator::bench {

enum class DomainKind { kCdt, kMesh, kAniso };

// "cdt", "mesh", "aniso".
std::string_view DomainKindName(DomainKind kind);
// Parses a name above; InvalidArgument listing the valid names otherwise.
Status ParseDomainKind(std::string_view name, DomainKind* kind);

// A generated dataset and the region its in-domain triangles cover.
struct DomainDataset {
  Dataset dataset;
  // The domain as rings, the outer boundary first, then the holes (each
  // counter-clockwise, last point not repeated). For cdt these are also
  // dataset.constraints.rings.
  std::vector<Polyline> domain_rings;
  // A point strictly inside each hole.
  std::vector<Point2> hole_seeds;
};

// The dataset of `kind` with about n points (see above) for `seed`.
DomainDataset GenerateDomainDataset(DomainKind kind, size_t n, uint64_t seed);

// The pieces the generators share (exposed for the mesh generator and tests).

// The concave outer boundary of cdt and mesh: the unit square with a
// V-shaped notch cut into its top edge down to y = 0.75; counter-clockwise.
Polyline NotchedSquare();

// `count` disjoint star-shaped hole rings (counter-clockwise), each inside
// NotchedSquare() below y = 0.72, and their centres (as hole seeds).
void RandomHoles(size_t count, std::mt19937_64& rng,
                 std::vector<Polyline>* rings, std::vector<Point2>* centres);

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_DOMAIN_DATASETS_H_
