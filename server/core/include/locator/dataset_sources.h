// The loaders that produce a Dataset (locator/dataset.h) from a spec.
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
//   PATH ending in .ele     Triangle's element format: a mesh served as given,
//                           its points from the .node file of the same base
//                           name beside it (mesh.ele reads mesh.node).
//   PATH ending in .off     OFF (Object File Format): a triangle mesh served
//                           as given; every vertex's z is its value.
//   POINTS+PATH.wkt         the dataset POINTS (any spec above or below)
//                           constrained by the WKT file PATH.wkt (see
//                           ParseWktConstraints), e.g. survey.xyz+lakes.wkt.
//   any other PATH          CSV/XYZ text: "x,y[,z]" per line, comma- or
//                           whitespace-separated, optional header line,
//                           '#' comments, blank lines ignored.
// Every parse error is InvalidArgument with "file:line: what is wrong"
// (not a number, NaN/inf, wrong column count, empty file). A missing file is
// NotFound / IOError with the path.
//
// Thread-safety: free functions.

#ifndef LOCATOR_DATASET_SOURCES_H_
#define LOCATOR_DATASET_SOURCES_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "locator/dataset.h"
#include "locator/geometry.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator {

// Whether `spec` names a generator (uniform:, clusters:) rather than a file.
bool IsGeneratorSpec(std::string_view spec);

// The other files the dataset file `path` reads besides itself: for
// mesh.ele, mesh.node; none for the other formats.
std::vector<std::string> DatasetCompanionFiles(const std::string& path);

// Loads a dataset from a file path or a generator spec (see above).
StatusOr<Dataset> LoadDataset(const std::string& spec,
                              const DatasetLimits& limits = DatasetLimits());

// Parses CSV/XYZ text. `filename` is only used in error messages.
StatusOr<Dataset> ParseXyzText(std::string_view text, std::string_view filename,
                               const DatasetLimits& limits = DatasetLimits());

// Parses Triangle .node text ("<#points> <dim=2> <#attributes> <#markers>"
// then "<index> <x> <y> [attributes...] [marker]"); the first attribute, if
// any, becomes the value.
StatusOr<Dataset> ParseNodeText(std::string_view text,
                                std::string_view filename,
                                const DatasetLimits& limits = DatasetLimits());

// Parses Triangle .poly text: a node section as ParseNodeText (the vertex
// count must not be 0: points in a separate .node are not supported), then
// "<#segments> <#markers>" and "<index> <from> <to> [marker]" rows, then
// "<#holes>" and "<index> <x> <y>" rows, then optionally "<#regions>" and
// "<index> <x> <y> <attribute> [max area]" rows. Segment endpoints are point
// indices numbered like the node section (from 0 or 1).
StatusOr<Dataset> ParsePolyText(std::string_view text,
                                std::string_view filename,
                                const DatasetLimits& limits = DatasetLimits());

// Parses OFF text: the header "OFF" (its counts may follow on the same
// line), "<#vertices> <#faces> <#edges>", vertex rows "x y z" and face rows
// "3 i j k [colour...]" with 0-based vertex indices. z becomes the value, so
// an OFF dataset always has values (all zero for a flat mesh). A face with
// another corner count is an error: only triangles are served.
StatusOr<Dataset> ParseOffText(std::string_view text, std::string_view filename,
                               const DatasetLimits& limits = DatasetLimits());

// Parses Triangle's .ele text ("<#triangles> <nodes per triangle: 3 or 6>
// <#attributes>", then "<index> <n1> <n2> <n3> [more nodes] [attributes]")
// against the points of the .node text (as ParseNodeText); node indices are
// numbered like the .node file. Only the first three nodes of a triangle
// (its corners) are used.
StatusOr<Dataset> ParseEleText(std::string_view ele_text,
                               std::string_view ele_filename,
                               std::string_view node_text,
                               std::string_view node_filename,
                               const DatasetLimits& limits = DatasetLimits());

// Parses WKT text into constraints: LINESTRING and MULTILINESTRING become
// breaklines, every ring of a POLYGON and MULTIPOLYGON a domain ring (a
// polygon's interior rings must lie inside its exterior ring);
// GEOMETRYCOLLECTIONs of these and EMPTY geometries are accepted.
// Geometries follow each other, separated by whitespace or ';'. With Z (as
// "LINESTRING Z (...)" or as a third coordinate), z is the value along the
// line or ring; a vertex without z must then be a dataset point. Keywords
// are case-insensitive; M coordinates are refused.
StatusOr<DatasetConstraints> ParseWktConstraints(std::string_view text,
                                                 std::string_view filename);

// Splits "POINTS+PATH.wkt" at its last '+' into the points spec and the WKT
// path; false (outputs untouched) for any other spec.
bool SplitWktConstraintsSpec(std::string_view spec, std::string_view* points,
                             std::string_view* wkt);

// Deterministic generators (same seed, same points, on every platform).
Dataset GenerateUniform(size_t n, uint64_t seed);
Dataset GenerateClusters(size_t n, size_t k, uint64_t seed);

// Changes whenever a generator above would give other points for the same
// arguments, so that what was derived from generated points (mesh files)
// is not reused across the change.
inline constexpr uint32_t kGeneratorVersion = 1;

// A generator spec, parsed (see LoadDataset).
struct GeneratorSpec {
  bool clusters = false;  // clusters:N:K[:SEED], else uniform:N[:SEED]
  size_t n = 0;
  size_t k = 1;
  uint64_t seed = 1;

  // "uniform:N:SEED" or "clusters:N:K:SEED" with kGeneratorVersion: equal
  // for specs that generate the same points.
  std::string CanonicalKey() const;
};

// Parses a spec for which IsGeneratorSpec() holds; InvalidArgument naming
// what is wrong otherwise.
StatusOr<GeneratorSpec> ParseGeneratorSpec(const std::string& spec);

}  // namespace locator

#endif  // LOCATOR_DATASET_SOURCES_H_
