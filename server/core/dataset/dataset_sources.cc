#include "locator/dataset_sources.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <system_error>
#include <type_traits>
#include <utility>
#include <vector>

#include "common/status_macros.h"
#include "server/core/dataset/dataset_text.h"
#include "server/core/dataset/file_io.h"

namespace locator {
namespace {

using namespace dataset_text;  // NOLINT: this file is its main user

constexpr uint64_t kDefaultSeed = 1;

Status BadSpec(std::string_view spec, std::string_view what) {
  return Status::InvalidArgument(
      Cat("bad dataset spec ", Quoted(spec), ": ", what));
}

std::vector<std::string_view> SplitOnColon(std::string_view s) {
  std::vector<std::string_view> parts;
  size_t start = 0;
  for (size_t colon; (colon = s.find(':', start)) != s.npos;
       start = colon + 1) {
    parts.push_back(s.substr(start, colon - start));
  }
  parts.push_back(s.substr(start));
  return parts;
}

// Parses the text of the dataset file `path` by its extension; a .ele reads
// its .node beside it.
StatusOr<Dataset> ParseDatasetFile(const std::string& path,
                                   std::string_view text,
                                   const DatasetLimits& limits) {
  if (path.ends_with(".node")) return ParseNodeText(text, path, limits);
  if (path.ends_with(".poly")) return ParsePolyText(text, path, limits);
  if (path.ends_with(".off")) return ParseOffText(text, path, limits);
  if (path.ends_with(".ele")) {
    const std::string node_path = DatasetCompanionFiles(path)[0];
    std::string node_text;
    RETURN_IF_ERROR(ReadWholeFile(node_path, Cat("node file of ", Quoted(path)),
                                  &node_text));
    return ParseEleText(text, path, node_text, node_path, limits);
  }
  return ParseXyzText(text, path, limits);
}

template <typename T>
void Append(std::vector<T>&& from, std::vector<T>* to) {
  to->insert(to->end(), std::make_move_iterator(from.begin()),
             std::make_move_iterator(from.end()));
}

// Adds a WKT file's breaklines and rings to the points' own constraints.
void AppendConstraints(DatasetConstraints&& wkt, DatasetConstraints* to) {
  Append(std::move(wkt.breaklines), &to->breaklines);
  Append(std::move(wkt.rings), &to->rings);
}

}  // namespace

std::vector<std::string> DatasetCompanionFiles(const std::string& path) {
  constexpr std::string_view kEle = ".ele";
  if (!path.ends_with(kEle)) return {};
  return {path.substr(0, path.size() - kEle.size()) + ".node"};
}

StatusOr<GeneratorSpec> ParseGeneratorSpec(const std::string& spec) {
  const std::vector<std::string_view> parts = SplitOnColon(spec);
  GeneratorSpec g;
  g.clusters = parts[0] == "clusters";
  const size_t required = g.clusters ? 3 : 2;
  if ((parts[0] != "uniform" && !g.clusters) ||
      (parts.size() != required && parts.size() != required + 1)) {
    return BadSpec(spec, g.clusters ? "expected clusters:N:K[:SEED]"
                                    : "expected uniform:N[:SEED]");
  }
  if (!ParseInteger(parts[1], &g.n) || g.n == 0) {
    return BadSpec(spec, "N must be a positive integer");
  }
  if (g.clusters && (!ParseInteger(parts[2], &g.k) || g.k == 0)) {
    return BadSpec(spec, "K must be a positive integer");
  }
  if (g.k > g.n) return BadSpec(spec, "K must not exceed N");
  g.seed = kDefaultSeed;
  if (parts.size() == required + 1 && !ParseInteger(parts.back(), &g.seed)) {
    return BadSpec(spec, "SEED must be an unsigned 64-bit integer");
  }
  return g;
}

std::string GeneratorSpec::CanonicalKey() const {
  const std::string counts =
      clusters ? Cat("clusters:", std::to_string(n), ":", std::to_string(k))
               : Cat("uniform:", std::to_string(n));
  return Cat(counts, ":", std::to_string(seed), " generator version ",
             std::to_string(kGeneratorVersion));
}

bool IsGeneratorSpec(std::string_view spec) {
  return spec.starts_with("uniform:") || spec.starts_with("clusters:");
}

StatusOr<Dataset> LoadDataset(const std::string& spec,
                              const DatasetLimits& limits) {
  Dataset ds;
  std::string_view points_spec;
  std::string_view wkt_path;
  if (SplitWktConstraintsSpec(spec, &points_spec, &wkt_path)) {
    ASSIGN_OR_RETURN(ds, LoadDataset(std::string(points_spec), limits));
    std::string text;
    RETURN_IF_ERROR(ReadWholeFile(std::string(wkt_path), "constraints", &text));
    ASSIGN_OR_RETURN(DatasetConstraints wkt,
                     ParseWktConstraints(text, wkt_path));
    AppendConstraints(std::move(wkt), &ds.constraints);
  } else if (IsGeneratorSpec(spec)) {
    ASSIGN_OR_RETURN(const GeneratorSpec g, ParseGeneratorSpec(spec));
    if (g.n > limits.max_points) return TooManyPoints(spec, limits.max_points);
    ds = g.clusters ? GenerateClusters(g.n, g.k, g.seed)
                    : GenerateUniform(g.n, g.seed);
  } else {
    std::string text;
    RETURN_IF_ERROR(ReadWholeFile(spec, "dataset", &text));
    ASSIGN_OR_RETURN(ds, ParseDatasetFile(spec, text, limits));
  }
  ds.source = spec;
  return ds;
}

StatusOr<Dataset> ParseXyzText(std::string_view text, std::string_view filename,
                               const DatasetLimits& limits) {
  const size_t estimate = ReserveEstimate(text, limits.max_points);
  Dataset ds;
  ds.points.reserve(estimate);
  TextFieldReader reader(text);
  TextFields f;
  size_t columns = 0;
  size_t columns_line = 0;
  bool first_line = true;
  while (reader.Next(&f)) {
    const Where where{filename, reader.line_number()};
    if (f.has_empty()) return where.Error("empty field");
    double unused;
    if (std::exchange(first_line, false) &&
        ParseNumber(f.field[0], &unused) == NumberKind::kNotANumber) {
      continue;  // a header such as "x,y,z"
    }
    if (f.count != 2 && f.count != 3) {
      return where.Error(Cat("expected 2 or 3 columns, got ", f.count));
    }
    if (columns == 0) {
      columns = f.count;
      columns_line = where.line;
      if (columns == 3) ds.values.reserve(estimate);
    } else if (f.count != columns) {
      return where.Error(Cat("expected ", columns, " columns like line ",
                             columns_line, ", got ", f.count));
    }
    if (ds.points.size() == limits.max_points) {
      return TooManyPoints(where.Prefix(), limits.max_points);
    }
    RETURN_IF_ERROR(ParsePoint(f, 0, columns == 3, where, &ds));
  }
  if (ds.points.empty()) return EmptyDataset(filename);
  return ds;
}

namespace dataset_text {

Status ReadCount(TextFieldReader* reader, std::string_view filename,
                 size_t max_fields, std::string_view what, size_t* count) {
  TextFields f;
  if (!reader->Next(&f)) {
    return Status::InvalidArgument(
        Cat(filename, ":", reader->line_number(), ": missing ", what));
  }
  const Where where{filename, reader->line_number()};
  if (f.has_empty() || f.count > max_fields ||
      !ParseInteger(f.field[0], count)) {
    return where.Error(Cat("expected ", what));
  }
  return Status::OK();
}

Status ReadRow(TextFieldReader* reader, std::string_view filename,
               size_t min_fields, std::string_view what, TextFields* f,
               Where* where) {
  const bool more = reader->Next(f);
  *where = Where{filename, reader->line_number()};
  if (!more) return where->Error(Cat("missing ", what));
  if (f->has_empty()) return where->Error("empty field");
  if (f->count < min_fields) {
    return where->Error(
        Cat("expected ", min_fields, " fields for ", what, ", got ", f->count));
  }
  return Status::OK();
}

Status ParseNodeSection(TextFieldReader* reader, std::string_view filename,
                        const DatasetLimits& limits, Dataset* out,
                        NodeSection* section) {
  TextFields f;
  if (!reader->Next(&f)) return EmptyDataset(filename);
  const Where header{filename, reader->line_number()};
  section->header_line = header.line;
  if (f.has_empty() || f.count != 4) {
    return header.Error(
        "expected header '<#points> <dim> <#attributes> <#markers>'");
  }
  std::array<size_t, 4> h;
  for (size_t i = 0; i < h.size(); ++i) {
    if (!ParseInteger(f.field[i], &h[i])) {
      return header.Error(
          Cat(Quoted(f.field[i]), " is not a non-negative integer"));
    }
  }
  const auto [num_points, dim, num_attributes, num_markers] = h;
  if (dim != 2) return header.Error(Cat("dimension must be 2, got ", dim));
  if (num_markers > 1) {
    return header.Error(
        Cat("boundary marker count must be 0 or 1, got ", num_markers));
  }
  if (num_points == 0) return EmptyDataset(filename);
  if (num_points > limits.max_points) {
    return TooManyPoints(header.Prefix(), limits.max_points);
  }
  const std::string declared =
      Cat("the ", num_points, " points declared on line ", header.line);
  const bool with_value = num_attributes > 0;
  // The declared count does not size the reservation: a few bytes of
  // header may declare millions of points that the text does not hold.
  Dataset ds;
  while (ds.points.size() < num_points) {
    const bool more = reader->Next(&f);
    const Where where{filename, reader->line_number()};
    if (!more) {
      return where.Error(
          Cat("found only ", ds.points.size(), " of ", declared));
    }
    if (f.has_empty()) return where.Error("empty field");
    // Written as a subtraction so that a huge declared attribute count
    // cannot overflow into a match.
    if (f.count < 3 + num_markers ||
        f.count - 3 - num_markers != num_attributes) {
      return where.Error(Cat(
          "expected ", 3 + num_attributes + num_markers, " fields (index x y, ",
          num_attributes, " attribute(s), ", num_markers,
          " marker(s)) as declared on line ", header.line, ", got ", f.count));
    }
    long long index;
    if (!ParseInteger(f.field[0], &index)) {
      return where.Error(Cat(Quoted(f.field[0]), " is not an integer index"));
    }
    if (ds.points.empty()) {
      section->first_index = index;
    } else if (index != section->first_index +
                            static_cast<long long>(ds.points.size())) {
      return where.Error(
          Cat("point index ", index, " out of sequence (expected ",
              section->first_index + static_cast<long long>(ds.points.size()),
              ")"));
    }
    // Further attributes and the marker are not used, so not validated.
    RETURN_IF_ERROR(ParsePoint(f, 1, with_value, where, &ds));
  }
  *out = std::move(ds);
  return Status::OK();
}

}  // namespace dataset_text

StatusOr<Dataset> ParseNodeText(std::string_view text,
                                std::string_view filename,
                                const DatasetLimits& limits) {
  TextFieldReader reader(text);
  Dataset ds;
  NodeSection section;
  RETURN_IF_ERROR(ParseNodeSection(&reader, filename, limits, &ds, &section));
  TextFields f;
  if (reader.Next(&f)) {
    return Where{filename, reader.line_number()}.Error(
        Cat("more than the ", ds.points.size(), " points declared on line ",
            section.header_line));
  }
  return ds;
}

}  // namespace locator
