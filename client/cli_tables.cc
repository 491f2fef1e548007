// The `locator` CLI's tabular outputs: the datasets list and profiles (text
// and CSV). Declared in client/cli_format.h.

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "client/cli_format.h"
#include "common/str_cat.h"

namespace locator {
namespace {

using Row = std::vector<std::string>;

// `rows` as columns, each padded to its widest cell and separated by two
// spaces, every line starting with `indent` and ending in a newline.
std::string RenderColumns(const std::vector<Row>& rows,
                          std::string_view indent = "") {
  std::vector<size_t> widths;
  for (const Row& row : rows) {
    widths.resize(std::max(widths.size(), row.size()), 0);
    for (size_t i = 0; i < row.size(); ++i) {
      widths[i] = std::max(widths[i], row[i].size());
    }
  }
  std::string out;
  for (const Row& row : rows) {
    std::string line(indent);
    for (size_t i = 0; i < row.size(); ++i) {
      line.append(row[i]);
      if (i + 1 < row.size()) line.append(widths[i] - row[i].size() + 2, ' ');
    }
    // A last cell left empty leaves spaces behind.
    line.erase(line.find_last_not_of(' ') + 1);
    out.append(line);
    out.push_back('\n');
  }
  return out;
}

std::string ValueText(const v1::ProfilePoint& point, std::string_view none) {
  return point.has_value() ? FormatDouble(point.value()) : std::string(none);
}

// The table of `points`: distance, x, y, z, triangle, and with `kinds` the
// kind of each point.
std::string PointTable(
    const google::protobuf::RepeatedPtrField<v1::ProfilePoint>& points,
    bool kinds) {
  std::vector<Row> rows = {{"distance", "x", "y", "z", "triangle"}};
  if (kinds) rows[0].push_back("kind");
  for (const v1::ProfilePoint& point : points) {
    Row row = {FormatDouble(point.distance()), FormatDouble(point.point().x()),
               FormatDouble(point.point().y()), ValueText(point, "none"),
               std::to_string(point.triangle_id())};
    if (kinds) row.push_back(ProfilePointKindName(point.kind()));
    rows.push_back(std::move(row));
  }
  return RenderColumns(rows, "  ");
}

}  // namespace

std::string FormatDatasets(const v1::ListDatasetsResponse& response) {
  std::vector<Row> rows = {
      {"name", "default", "serving", "points", "triangles", "crs"}};
  for (const v1::DatasetEntry& entry : response.datasets()) {
    const v1::DatasetStats& stats = entry.stats();
    const bool serving = entry.serving();
    rows.push_back({entry.name(), entry.is_default() ? "*" : "",
                    serving ? "yes" : "no (loading)",
                    serving ? std::to_string(stats.input_points()) : "-",
                    serving ? std::to_string(stats.triangles()) : "-",
                    serving ? FormatCrs(stats) : "-"});
  }
  return RenderColumns(rows);
}

std::string FormatProfile(const v1::ProfileResponse& response) {
  std::string out = RenderColumns(
      {{"length", FormatDouble(response.length())},
       {"crossings", std::to_string(response.crossings())},
       {"breakpoints", std::to_string(response.breakpoints_size())}});
  out.append(PointTable(response.breakpoints(), /*kinds=*/true));
  if (response.samples_size() > 0) {
    out.append(
        StrCat({"samples  ", std::to_string(response.samples_size()), "\n"}));
    out.append(PointTable(response.samples(), /*kinds=*/false));
  }
  out.append(StrCat(
      {"gaps  ",
       response.gaps().empty() ? "none" : std::to_string(response.gaps_size()),
       "\n"}));
  if (response.gaps_size() > 0) {
    std::vector<Row> rows = {{"from", "to", "reason"}};
    for (const v1::ProfileGap& gap : response.gaps()) {
      rows.push_back({FormatDouble(gap.from_distance()),
                      FormatDouble(gap.to_distance()),
                      LocationTypeName(gap.reason())});
    }
    out.append(RenderColumns(rows, "  "));
  }
  return out;
}

std::string ProfileCsv(const v1::ProfileResponse& response) {
  std::vector<const v1::ProfilePoint*> breakpoints, samples, points;
  for (const v1::ProfilePoint& point : response.breakpoints()) {
    breakpoints.push_back(&point);
  }
  for (const v1::ProfilePoint& point : response.samples()) {
    samples.push_back(&point);
  }
  // std::merge takes from the first range on ties: breakpoints first.
  std::merge(breakpoints.begin(), breakpoints.end(), samples.begin(),
             samples.end(), std::back_inserter(points),
             [](const v1::ProfilePoint* a, const v1::ProfilePoint* b) {
               return a->distance() < b->distance();
             });
  std::string out = "kind,distance,x,y,z,triangle_id,segment\n";
  for (const v1::ProfilePoint* point : points) {
    out.append(StrCat(
        {ProfilePointKindName(point->kind()), ",",
         FormatDouble(point->distance()), ",", FormatDouble(point->point().x()),
         ",", FormatDouble(point->point().y()), ",", ValueText(*point, ""), ",",
         std::to_string(point->triangle_id()), ",",
         std::to_string(point->segment()), "\n"}));
  }
  return out;
}

}  // namespace locator
