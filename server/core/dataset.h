// The loaders that produce a Dataset (common/dataset.h) from a spec.
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
// Thread-safety: free functions.

#ifndef LOCATOR_CORE_DATASET_H_
#define LOCATOR_CORE_DATASET_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/dataset.h"
#include "common/geometry.h"
#include "common/status.h"

namespace locator {

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
