// Triangle's .poly format: a node section, segments, holes and optional
// regional attributes (see ParsePolyText in dataset.h).

#include <string>
#include <utility>

#include "common/status_macros.h"
#include "locator/dataset_sources.h"
#include "server/core/dataset/dataset_text.h"

namespace locator {

using dataset_text::Cat;
using dataset_text::NodeSection;
using dataset_text::ParseFinite;
using dataset_text::ParseInteger;
using dataset_text::Quoted;
using dataset_text::ReadCount;
using dataset_text::ReadRow;
using dataset_text::Where;

StatusOr<Dataset> ParsePolyText(std::string_view text,
                                std::string_view filename,
                                const DatasetLimits& limits) {
  TextFieldReader reader(text);
  Dataset ds;
  NodeSection nodes;
  RETURN_IF_ERROR(
      dataset_text::ParseNodeSection(&reader, filename, limits, &ds, &nodes));
  const long long n = static_cast<long long>(ds.points.size());

  size_t segments = 0;
  RETURN_IF_ERROR(ReadCount(&reader, filename, 2,
                            "segment header '<#segments> <#markers>'",
                            &segments));
  TextFields f;
  Where where;
  for (size_t k = 0; k < segments; ++k) {
    RETURN_IF_ERROR(
        ReadRow(&reader, filename, 3, Cat("segment ", k), &f, &where));
    Polyline segment;
    for (size_t end = 1; end <= 2; ++end) {
      long long index;
      if (!ParseInteger(f.field[end], &index)) {
        return where.Error(Cat(Quoted(f.field[end]), " is not a point index"));
      }
      const long long i = index - nodes.first_index;
      if (i < 0 || i >= n) {
        return where.Error(Cat("segment refers to point ", index,
                               ", which is not among the ", n,
                               " points numbered from ", nodes.first_index));
      }
      segment.points.push_back(ds.points[i]);
    }
    segment.name = Cat("segment ", f.field[0], " at ", where.Prefix());
    ds.constraints.segments.push_back(std::move(segment));
  }

  size_t holes = 0;
  RETURN_IF_ERROR(
      ReadCount(&reader, filename, 1, "hole header '<#holes>'", &holes));
  for (size_t k = 0; k < holes; ++k) {
    RETURN_IF_ERROR(ReadRow(&reader, filename, 3, Cat("hole ", k), &f, &where));
    Point2 p;
    RETURN_IF_ERROR(ParseFinite(f.field[1], "coordinate", where, &p.x));
    RETURN_IF_ERROR(ParseFinite(f.field[2], "coordinate", where, &p.y));
    ds.constraints.hole_seeds.push_back(p);
  }

  // Optional: regional attributes "<index> x y attribute [max area]".
  TextFields rest;
  if (reader.Next(&rest)) {
    const Where header{filename, reader.line_number()};
    size_t regions = 0;
    if (rest.has_empty() || rest.count != 1 ||
        !ParseInteger(rest.field[0], &regions)) {
      return header.Error("expected regional attribute header '<#regions>'");
    }
    for (size_t k = 0; k < regions; ++k) {
      RETURN_IF_ERROR(
          ReadRow(&reader, filename, 4, Cat("region ", k), &f, &where));
      RegionalAttribute region;
      RETURN_IF_ERROR(
          ParseFinite(f.field[1], "coordinate", where, &region.seed.x));
      RETURN_IF_ERROR(
          ParseFinite(f.field[2], "coordinate", where, &region.seed.y));
      RETURN_IF_ERROR(
          ParseFinite(f.field[3], "attribute", where, &region.attribute));
      ds.constraints.regions.push_back(region);
    }
    if (reader.Next(&rest)) {
      return Where{filename, reader.line_number()}.Error(
          "unexpected line after the regional attributes");
    }
  }
  return ds;
}

}  // namespace locator
