#include "client/cli_format.h"

#include <array>
#include <charconv>
#include <cmath>
#include <string_view>

#include "common/proto_json.h"
#include "common/str_cat.h"

namespace locator {
namespace {

constexpr double kMiB = 1024.0 * 1024.0;

// Lines are "label" padded to one column, then the value.
void AppendLine(std::string_view label, const std::string& value,
                std::string* out) {
  constexpr size_t kLabelWidth = 13;
  out->append(label);
  out->append(label.size() < kLabelWidth ? kLabelWidth - label.size() : 1, ' ');
  out->append(value);
  out->push_back('\n');
}

std::string FormatPoint(const v1::Point& point) {
  return StrCat(
      {"(", FormatDouble(point.x()), ", ", FormatDouble(point.y()), ")"});
}

std::string FormatBox(const v1::BoundingBox& box) {
  return StrCat({"[", FormatDouble(box.min_x()), ", ",
                 FormatDouble(box.max_x()), "] x [", FormatDouble(box.min_y()),
                 ", ", FormatDouble(box.max_y()), "]"});
}

std::string FormatMiB(uint64_t bytes) {
  return StrCat({FormatFixed(bytes / kMiB, 1), " MiB"});
}

// The values, formatted by `format`, separated by spaces.
template <typename Values, typename Format>
std::string Join(const Values& values, Format format) {
  std::string joined;
  for (const auto& value : values) {
    if (!joined.empty()) joined.push_back(' ');
    joined.append(format(value));
  }
  return joined;
}

// One line of a simplification's certificate.
std::string FormatSimplification(const v1::SimplificationStats& s) {
  std::string line = StrCat({std::to_string(s.source_samples()), " samples to ",
                             std::to_string(s.vertices()), " vertices, ",
                             std::to_string(s.triangles()), " triangles in ",
                             FormatDouble(s.build_seconds()), " s; max error ",
                             FormatDouble(s.max_error()), " (target ",
                             FormatDouble(s.target_error())});
  if (s.max_points() != 0) {
    line += StrCat({", max_points ", std::to_string(s.max_points())});
  }
  line += ")";
  if (s.unserved_samples() != 0) {
    line += StrCat({"; ", std::to_string(s.unserved_samples()),
                    " samples outside the domain"});
  }
  return line;
}

// The lines describing a served dataset.
std::string FormatDataset(const v1::DatasetStats& dataset) {
  std::string out;
  AppendLine("dataset",
             dataset.source().empty() ? "(redacted)" : dataset.source(), &out);
  AppendLine("points",
             StrCat({std::to_string(dataset.input_points()), " read, ",
                     std::to_string(dataset.vertices()), " vertices, ",
                     std::to_string(dataset.duplicates_merged()),
                     " duplicates merged, ",
                     std::to_string(dataset.triangles()), " triangles"}),
             &out);
  AppendLine("bounds", FormatBox(dataset.bounding_box()), &out);
  AppendLine("crs", FormatCrs(dataset), &out);
  AppendLine("values", dataset.has_values() ? "yes" : "no", &out);
  AppendLine("build", StrCat({FormatDouble(dataset.build_seconds()), " s"}),
             &out);
  if (dataset.has_simplification()) {
    AppendLine("simplified", FormatSimplification(dataset.simplification()),
               &out);
  }
  return out;
}

// `name` without `prefix`; the number for a value newer than this client,
// which has no name.
std::string ShortEnumName(std::string name, std::string_view prefix,
                          int number) {
  if (name.starts_with(prefix)) name.erase(0, prefix.size());
  return name.empty() ? std::to_string(number) : name;
}

// The state file line of a tuning: where, whether restored, why not.
std::string FormatPersistence(const v1::TuningPersistence& persistence) {
  std::string state = persistence.state_path();
  if (persistence.restored_from_state()) state += " (restored)";
  if (!persistence.load_error().empty()) {
    state += StrCat({" (ignored: ", persistence.load_error(), ")"});
  }
  state += StrCat({"; ", std::to_string(persistence.saves()), " saves"});
  if (!persistence.save_error().empty()) {
    state += StrCat({"; last save failed: ", persistence.save_error()});
  }
  return state;
}

}  // namespace

std::string FormatDouble(double value) {
  std::array<char, 32> text;
  const auto [end, error] = std::to_chars(text.begin(), text.end(), value);
  return std::string(text.begin(), end);
}

std::string FormatFixed(double value, int decimals) {
  std::array<char, 64> text;
  const auto [end, error] = std::to_chars(text.begin(), text.end(), value,
                                          std::chars_format::fixed, decimals);
  // Too long for the buffer (a huge value): the shortest form instead.
  if (error != std::errc()) return FormatDouble(value);
  return std::string(text.begin(), end);
}

std::string FormatCrs(const v1::DatasetStats& stats) {
  if (!stats.has_crs()) return "none";
  const v1::CrsStats& crs = stats.crs();
  if (crs.epsg_code() == 0) return crs.name();
  return StrCat({crs.name(), " (EPSG:", std::to_string(crs.epsg_code()), ")"});
}

std::string LocationTypeName(v1::LocationType type) {
  return ShortEnumName(v1::LocationType_Name(type), "LOCATION_TYPE_", type);
}

std::string ProfilePointKindName(v1::ProfilePointKind kind) {
  return ShortEnumName(v1::ProfilePointKind_Name(kind), "PROFILE_POINT_KIND_",
                       kind);
}

std::string MessageToJson(const google::protobuf::Message& message) {
  return ProtoJson(message) + "\n";
}

std::string FormatLocate(const v1::LocateResponse& response) {
  std::string out;
  AppendLine("type", LocationTypeName(response.type()), &out);
  const bool outside_domain =
      response.type() == v1::LOCATION_TYPE_OUTSIDE_DOMAIN;
  // Outside the domain there is no triangle: its id and corners are -1.
  if (!outside_domain) {
    AppendLine("triangle", std::to_string(response.triangle_id()), &out);
  }
  for (int i = 0; i < response.vertex_ids_size() && !outside_domain; ++i) {
    std::string vertex = std::to_string(response.vertex_ids(i));
    if (i < response.vertices_size()) {
      vertex.push_back(' ');
      vertex.append(FormatPoint(response.vertices(i)));
    }
    AppendLine(i == 0 ? "vertices" : "", vertex, &out);
  }
  if (response.hull_edge_vertex_ids_size() > 0) {
    AppendLine("hull edge",
               Join(response.hull_edge_vertex_ids(),
                    [](int64_t id) { return std::to_string(id); }),
               &out);
  }
  if (response.domain_edge_vertex_ids_size() > 0) {
    AppendLine("domain edge",
               Join(response.domain_edge_vertex_ids(),
                    [](int64_t id) { return std::to_string(id); }),
               &out);
  }
  AppendLine("barycentric",
             !response.barycentric().empty()
                 ? Join(response.barycentric(), FormatDouble)
             : outside_domain ? "none (outside the domain: in a hole or "
                                "beyond its boundary)"
                              : "none (outside the convex hull)",
             &out);
  AppendLine("value",
             response.has_value() ? FormatDouble(response.value()) : "none",
             &out);
  const v1::Cost& cost = response.cost();
  AppendLine("cost",
             StrCat({std::to_string(cost.total()), " (",
                     std::to_string(cost.faces_visited()), " faces visited, ",
                     std::to_string(cost.comparisons()), " comparisons, ",
                     std::to_string(cost.table_lookups()), " table lookups)"}),
             &out);
  return out;
}

std::string FormatStats(const v1::GetStatsResponse& stats) {
  std::string out = FormatDataset(stats.dataset());
  AppendLine(
      "generation",
      StrCat({std::to_string(stats.generation()),
              stats.reload_in_progress() ? " (reload in progress)" : ""}),
      &out);
  AppendLine("strategy", stats.strategy(), &out);
  AppendLine(
      "serving",
      StrCat({std::to_string(stats.queries_served()), " queries; mean cost ",
              FormatDouble(stats.mean_cost_lifetime()), " lifetime, ",
              FormatDouble(stats.mean_cost_recent()), " over the last ",
              std::to_string(stats.recent_window())}),
      &out);
  AppendLine("memory",
             StrCat({FormatMiB(stats.memory().triangulation_bytes()),
                     " triangulation, ",
                     FormatMiB(stats.memory().tuning_bytes()), " tuning"}),
             &out);
  return out + FormatTuning(stats.tuning());
}

std::string FormatTuning(const v1::TuningStats& tuning) {
  std::string out;
  const std::string grid = std::to_string(tuning.grid_size());
  AppendLine("tuning",
             StrCat({"snapshot ", std::to_string(tuning.snapshot_version()),
                     " after ", std::to_string(tuning.retune_count()),
                     " re-tunes; ", std::to_string(tuning.start_point_count()),
                     " start points; histogram ", grid, "x", grid}),
             &out);
  for (int i = 0; i < tuning.hot_regions_size(); ++i) {
    AppendLine(i == 0 ? "hot regions" : "", FormatBox(tuning.hot_regions(i)),
               &out);
  }
  if (!tuning.persistence().state_path().empty()) {
    AppendLine("state", FormatPersistence(tuning.persistence()), &out);
  }
  return out;
}

std::string FormatReload(const v1::ReloadResponse& response) {
  std::string out = FormatDataset(response.dataset());
  AppendLine("generation", std::to_string(response.generation()), &out);
  return out + FormatTuning(response.tuning());
}

std::string BatchCsvHeader() {
  return "x,y,type,triangle_id,v0,v1,v2,b0,b1,b2,value,cost\n";
}

void AppendBatchCsvRows(std::span<const double> xs, std::span<const double> ys,
                        const v1::LocateBatchResponse& response,
                        std::string* out) {
  for (size_t i = 0; i < xs.size(); ++i) {
    const auto type = static_cast<v1::LocationType>(response.types(i));
    // Barycentric coordinates mean nothing outside the hull or the domain
    // (the server sends zeros); leave those cells empty, like a missing
    // value.
    const bool inside = type != v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL &&
                        type != v1::LOCATION_TYPE_OUTSIDE_DOMAIN;
    out->append(StrCat({FormatDouble(xs[i]), ",", FormatDouble(ys[i]), ",",
                        LocationTypeName(type), ",",
                        std::to_string(response.triangle_ids(i))}));
    for (size_t k = 0; k < 3; ++k) {
      out->push_back(',');
      out->append(std::to_string(response.vertex_ids(3 * i + k)));
    }
    for (size_t k = 0; k < 3; ++k) {
      out->push_back(',');
      if (inside) out->append(FormatDouble(response.barycentric(3 * i + k)));
    }
    out->push_back(',');
    const double value = response.values(i);
    if (!std::isnan(value)) out->append(FormatDouble(value));
    out->push_back(',');
    out->append(std::to_string(response.costs(i)));
    out->push_back('\n');
  }
}

}  // namespace locator
