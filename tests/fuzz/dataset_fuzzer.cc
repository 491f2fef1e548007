// Fuzzes the dataset parsers: every input is parsed as CSV/XYZ text, as
// Triangle .node, .poly and .ele text (the .ele against a fixed .node of four
// points numbered from 1) and as OFF text, with the limits locatord uses,
// and as a WKT constraints file. Every dataset that parses with constraints
// (a .poly, a mesh, WKT over the fixed four points) is then triangulated,
// as locatord would: bad domains and meshes (self-intersecting boundaries,
// hole points outside every ring, non-manifold or overlapping meshes, empty
// domains) must be refused, never crash.
//
// Aborts unless each parse either
//   - succeeds with at least one point, finite coordinates and values, values
//     empty or one per point, mesh corners that name points, and a dataset
//     that survives a round trip: the
//     points written back as CSV with 17 significant digits parse to exactly
//     the same doubles; or
//     (for WKT: polylines of at least 2 points, rings of at least 3,
//     finite coordinates and values, values empty or one per point); or
//   - fails with InvalidArgument or ResourceExhausted and a message that
//     starts with the file name, followed by ": " or by ":LINE: " with LINE a
//     line of the input;
// and unless triangulating a constrained dataset either succeeds with at
// least one triangle in the domain or fails with InvalidArgument.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/cgal/triangulation.h"

namespace locator {
namespace {

constexpr std::string_view kCsvName = "fuzz.csv";
constexpr std::string_view kNodeName = "fuzz.node";
constexpr std::string_view kPolyName = "fuzz.poly";
constexpr std::string_view kOffName = "fuzz.off";
constexpr std::string_view kEleName = "fuzz.ele";
constexpr std::string_view kWktName = "fuzz.wkt";
constexpr std::string_view kEleNodes =
    "4 2 1 0\n1 0 0 5\n2 1 0 6\n3 0 1 7\n4 1 1 8\n";

void Fail(std::string_view what, const Status& status) {
  std::fprintf(stderr, "dataset_fuzzer: %.*s (%s)\n",
               static_cast<int>(what.size()), what.data(),
               status.ToString().c_str());
  std::abort();
}

StatusOr<Dataset> ParseEleAgainstFixedNodes(std::string_view text,
                                            std::string_view name,
                                            const DatasetLimits& limits) {
  return ParseEleText(text, name, kEleNodes, "fuzz.node", limits);
}

// 1-based lines in `text` as FieldReader counts them.
size_t LineCount(std::string_view text) {
  size_t lines = 1;
  for (char c : text) lines += c == '\n';
  return lines;
}

void CheckError(const Status& status, std::string_view text,
                std::string_view name) {
  if (status.code() != Status::Code::kInvalidArgument &&
      status.code() != Status::Code::kResourceExhausted) {
    Fail("unexpected error code", status);
  }
  std::string_view rest = status.message();
  if (!rest.starts_with(name) || rest.size() < name.size() + 2 ||
      rest[name.size()] != ':') {
    Fail("error does not start with the file name", status);
  }
  rest.remove_prefix(name.size() + 1);
  if (rest.starts_with(' ')) return;  // a whole-file error: "name: what"
  size_t line = 0;
  size_t digits = 0;
  for (; digits < rest.size() && rest[digits] >= '0' && rest[digits] <= '9';
       ++digits) {
    line = line * 10 + static_cast<size_t>(rest[digits] - '0');
  }
  if (digits == 0 || !rest.substr(digits).starts_with(": ")) {
    Fail("error is neither 'name: what' nor 'name:LINE: what'", status);
  }
  if (line < 1 || line > LineCount(text)) Fail("line out of range", status);
}

// The dataset as CSV that must parse back to exactly the same doubles.
std::string ToCsv(const Dataset& ds) {
  std::string csv;
  char row[128];
  for (size_t i = 0; i < ds.points.size(); ++i) {
    int n = ds.has_values()
                ? std::snprintf(row, sizeof(row), "%.17g,%.17g,%.17g\n",
                                ds.points[i].x, ds.points[i].y, ds.values[i])
                : std::snprintf(row, sizeof(row), "%.17g,%.17g\n",
                                ds.points[i].x, ds.points[i].y);
    csv.append(row, static_cast<size_t>(n));
  }
  return csv;
}

bool SameDoubles(const Dataset& a, const Dataset& b) {
  if (a.points.size() != b.points.size() || a.values != b.values) return false;
  for (size_t i = 0; i < a.points.size(); ++i) {
    if (a.points[i].x != b.points[i].x || a.points[i].y != b.points[i].y) {
      return false;
    }
  }
  return true;
}

// Triangulates `ds` if it has constraints (see the file comment).
void CheckTriangulates(const Dataset& ds) {
  if (ds.constraints.empty()) return;
  const StatusOr<std::unique_ptr<Triangulation>> t = Triangulation::Build(ds);
  if (t.ok()) {
    if ((*t)->num_triangles() == 0) Fail("built an empty domain", t.status());
  } else if (t.status().code() != Status::Code::kInvalidArgument) {
    Fail("triangulating failed with an unexpected code", t.status());
  }
}

void CheckDataset(const Dataset& ds) {
  const Status ok;
  if (ds.points.empty()) Fail("parsed an empty dataset", ok);
  if (ds.has_values() && ds.values.size() != ds.points.size()) {
    Fail("values not parallel to points", ok);
  }
  for (const Point2& p : ds.points) {
    if (!IsFinite(p)) Fail("parsed a non-finite coordinate", ok);
  }
  for (double v : ds.values) {
    if (!std::isfinite(v)) Fail("parsed a non-finite value", ok);
  }
  for (const auto& triangle : ds.constraints.triangles) {
    for (uint32_t corner : triangle) {
      if (corner >= ds.points.size()) Fail("a mesh corner names no point", ok);
    }
  }
  const StatusOr<Dataset> again = ParseXyzText(ToCsv(ds), kCsvName);
  if (!again.ok()) Fail("its own CSV does not parse", again.status());
  if (!SameDoubles(ds, *again)) Fail("CSV round trip changed the doubles", ok);
  CheckTriangulates(ds);
}

template <typename Parser>
void Check(Parser parse, std::string_view text, std::string_view name) {
  const StatusOr<Dataset> ds = parse(text, name, DatasetLimits());
  if (ds.ok()) {
    CheckDataset(*ds);
  } else {
    CheckError(ds.status(), text, name);
  }
}

void CheckPolylines(const std::vector<Polyline>& lines, size_t min_points) {
  const Status ok;
  for (const Polyline& line : lines) {
    if (line.points.size() < min_points) Fail("a polyline too short", ok);
    if (!line.values.empty() && line.values.size() != line.points.size()) {
      Fail("polyline values not parallel to its points", ok);
    }
    for (const Point2& p : line.points) {
      if (!IsFinite(p)) Fail("parsed a non-finite WKT coordinate", ok);
    }
    for (double v : line.values) {
      if (!std::isfinite(v)) Fail("parsed a non-finite WKT z", ok);
    }
  }
}

void CheckWkt(std::string_view text) {
  Dataset ds;
  ds.points = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  StatusOr<DatasetConstraints> constraints =
      ParseWktConstraints(text, kWktName);
  if (!constraints.ok()) {
    return CheckError(constraints.status(), text, kWktName);
  }
  ds.constraints = *std::move(constraints);
  CheckPolylines(ds.constraints.breaklines, 2);
  CheckPolylines(ds.constraints.rings, 3);
  CheckTriangulates(ds);
}

}  // namespace
}  // namespace locator

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  locator::Check(locator::ParseXyzText, text, locator::kCsvName);
  locator::Check(locator::ParseNodeText, text, locator::kNodeName);
  locator::Check(locator::ParsePolyText, text, locator::kPolyName);
  locator::Check(locator::ParseOffText, text, locator::kOffName);
  locator::Check(locator::ParseEleAgainstFixedNodes, text, locator::kEleName);
  locator::CheckWkt(text);
  return 0;
}
