// Meshes served as given: OFF, and Triangle's .ele with its .node (see
// ParseOffText and ParseEleText in dataset.h). Both fill
// DatasetConstraints::triangles; the triangulation checks that they form a
// valid mesh.

#include <array>
#include <cstdint>
#include <string>
#include <utility>

#include "common/status_macros.h"
#include "locator/dataset_sources.h"
#include "server/core/dataset/dataset_text.h"

namespace locator {

using dataset_text::Cat;
using dataset_text::EmptyDataset;
using dataset_text::NodeSection;
using dataset_text::ParseInteger;
using dataset_text::ParsePoint;
using dataset_text::Quoted;
using dataset_text::ReadRow;
using dataset_text::TooManyPoints;
using dataset_text::Where;

namespace {

// The points a mesh's corner indices refer to, for checks and errors.
struct CornerRange {
  long long first_index;  // the index of point 0
  size_t count;
  std::string_view noun;  // "vertex", "node"
  std::string described;  // "the 600 nodes numbered from 1 in mesh.node"
};

// Reads three corner indices from fields [first, first + 3) of `f` into
// *corners, as 0-based point indices.
Status ReadCorners(const TextFields& f, size_t first, const CornerRange& range,
                   std::string_view triangle, const Where& where,
                   std::array<uint32_t, 3>* corners) {
  for (size_t c = 0; c < 3; ++c) {
    long long index;
    if (!ParseInteger(f.field[first + c], &index)) {
      return where.Error(
          Cat(Quoted(f.field[first + c]), " is not a ", range.noun, " index"));
    }
    const long long i = index - range.first_index;
    if (i < 0 || i >= static_cast<long long>(range.count)) {
      return where.Error(Cat(triangle, " refers to ", range.noun, " ", index,
                             ", which is not among ", range.described));
    }
    (*corners)[c] = static_cast<uint32_t>(i);
  }
  return Status::OK();
}

Status NoMoreLines(TextFieldReader* reader, std::string_view filename,
                   std::string_view after) {
  TextFields f;
  if (!reader->Next(&f)) return Status::OK();
  return Where{filename, reader->line_number()}.Error(
      Cat("unexpected line after ", after));
}

// Reads OFF's header: "OFF" alone or followed by the counts, then the counts
// "<#vertices> <#faces> <#edges>" if they were not on the same line.
Status ReadOffHeader(TextFieldReader* reader, std::string_view filename,
                     size_t* vertices, size_t* faces) {
  TextFields f;
  if (!reader->Next(&f)) return EmptyDataset(filename);
  Where where{filename, reader->line_number()};
  if (f.has_empty() || f.field[0] != "OFF") {
    return where.Error("expected the header 'OFF'");
  }
  size_t first = 1;
  if (f.count == 1) {
    if (!reader->Next(&f)) return where.Error("missing the counts line");
    where = Where{filename, reader->line_number()};
    first = 0;
  }
  if (f.has_empty() || f.count - first != 3 ||
      !ParseInteger(f.field[first], vertices) ||
      !ParseInteger(f.field[first + 1], faces)) {
    return where.Error("expected counts '<#vertices> <#faces> <#edges>'");
  }
  return Status::OK();
}

}  // namespace

StatusOr<Dataset> ParseOffText(std::string_view text, std::string_view filename,
                               const DatasetLimits& limits) {
  TextFieldReader reader(text);
  size_t vertices = 0;
  size_t faces = 0;
  RETURN_IF_ERROR(ReadOffHeader(&reader, filename, &vertices, &faces));
  if (vertices == 0) return EmptyDataset(filename);
  if (vertices > limits.max_points) {
    return TooManyPoints(Cat(filename, ":", reader.line_number()),
                         limits.max_points);
  }
  Dataset ds;
  TextFields f;
  Where where;
  for (size_t v = 0; v < vertices; ++v) {
    RETURN_IF_ERROR(ReadRow(&reader, filename, 3, Cat("vertex ", v, " 'x y z'"),
                            &f, &where));
    if (f.count != 3) {
      return where.Error(
          Cat("expected 3 fields for vertex ", v, " 'x y z', got ", f.count));
    }
    RETURN_IF_ERROR(ParsePoint(f, 0, true, where, &ds));
  }
  const CornerRange range{0, vertices, "vertex",
                          Cat("the ", vertices, " vertices numbered from 0")};
  for (size_t t = 0; t < faces; ++t) {
    const std::string face = Cat("face ", t);
    RETURN_IF_ERROR(ReadRow(&reader, filename, 1, face, &f, &where));
    size_t corners = 0;
    if (!ParseInteger(f.field[0], &corners)) {
      return where.Error(Cat(Quoted(f.field[0]), " is not a corner count"));
    }
    if (corners != 3) {
      return where.Error(Cat("only triangles are served; ", face, " has ",
                             corners, " corners"));
    }
    if (f.count < 4) {
      return where.Error(
          Cat(face, " lists ", f.count - 1, " of its 3 corners"));
    }
    std::array<uint32_t, 3> triangle;
    RETURN_IF_ERROR(ReadCorners(f, 1, range, face, where, &triangle));
    ds.constraints.triangles.push_back(triangle);
  }
  RETURN_IF_ERROR(NoMoreLines(&reader, filename, Cat("the ", faces, " faces")));
  return ds;
}

StatusOr<Dataset> ParseEleText(std::string_view ele_text,
                               std::string_view ele_filename,
                               std::string_view node_text,
                               std::string_view node_filename,
                               const DatasetLimits& limits) {
  Dataset ds;
  NodeSection nodes;
  TextFieldReader node_reader(node_text);
  RETURN_IF_ERROR(dataset_text::ParseNodeSection(&node_reader, node_filename,
                                                 limits, &ds, &nodes));
  const size_t n = ds.points.size();
  RETURN_IF_ERROR(
      NoMoreLines(&node_reader, node_filename, Cat("the ", n, " points")));
  const CornerRange range{nodes.first_index, n, "node",
                          Cat("the ", n, " nodes numbered from ",
                              nodes.first_index, " in ", node_filename)};

  TextFieldReader reader(ele_text);
  TextFields f;
  if (!reader.Next(&f)) {
    return Status::InvalidArgument(Cat(ele_filename, ": no triangles"));
  }
  const Where header{ele_filename, reader.line_number()};
  size_t triangles = 0;
  size_t per_triangle = 0;
  size_t attributes = 0;
  if (f.has_empty() || f.count != 3 || !ParseInteger(f.field[0], &triangles) ||
      !ParseInteger(f.field[1], &per_triangle) ||
      !ParseInteger(f.field[2], &attributes)) {
    return header.Error(
        "expected header '<#triangles> <nodes per triangle> <#attributes>'");
  }
  if (per_triangle != 3 && per_triangle != 6) {
    return header.Error(
        Cat("nodes per triangle must be 3 or 6, got ", per_triangle));
  }
  Where where;
  for (size_t t = 0; t < triangles; ++t) {
    const std::string triangle = Cat("triangle ", t);
    RETURN_IF_ERROR(ReadRow(&reader, ele_filename, 4, triangle, &f, &where));
    // Written as a subtraction so that a huge declared attribute count
    // cannot overflow into a match.
    if (f.count < 1 + per_triangle ||
        f.count - 1 - per_triangle != attributes) {
      return where.Error(Cat("expected ", 1 + per_triangle + attributes,
                             " fields (index, ", per_triangle, " nodes, ",
                             attributes, " attribute(s)) as declared on line ",
                             header.line, ", got ", f.count));
    }
    std::array<uint32_t, 3> corners;
    RETURN_IF_ERROR(ReadCorners(f, 1, range, triangle, where, &corners));
    ds.constraints.triangles.push_back(corners);
  }
  RETURN_IF_ERROR(
      NoMoreLines(&reader, ele_filename, Cat("the ", triangles, " triangles")));
  return ds;
}

}  // namespace locator
