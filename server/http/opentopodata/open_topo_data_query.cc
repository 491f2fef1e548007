#include "server/http/opentopodata/open_topo_data_query.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "common/input_text.h"
#include "common/status_macros.h"
#include "common/text_fields.h"
#include "server/http/opentopodata/encoded_polyline.h"

namespace locator {
namespace {

constexpr std::string_view kEncodedPrefix = "enc:";

std::string_view Trimmed(std::string_view text) {
  while (!text.empty() && text.front() == ' ') text.remove_prefix(1);
  while (!text.empty() && text.back() == ' ') text.remove_suffix(1);
  return text;
}

// One "lat,lng" at 1-based `position`.
StatusOr<Point2> ParseLatLng(std::string_view location, size_t position) {
  const std::string prefix = "Unable to parse location " +
                             QuotedInput(location) + " in position " +
                             std::to_string(position) + ".";
  const size_t comma = location.find(',');
  if (comma == std::string_view::npos) {
    return Status::InvalidArgument(prefix +
                                   " Add locations like lat1,lon1|lat2,lon2.");
  }
  double lat = 0;
  double lng = 0;
  if (!ParseDouble(Trimmed(location.substr(0, comma)), &lat) ||
      !ParseDouble(Trimmed(location.substr(comma + 1)), &lng)) {
    return Status::InvalidArgument(prefix);
  }
  // Written so that NaN fails too.
  if (!(lat >= -90 && lat <= 90)) {
    return Status::InvalidArgument(
        prefix +
        " Latitude must be between -90 and 90. Provide locations in lat,lon "
        "order.");
  }
  if (!(lng >= -180 && lng <= 180)) {
    return Status::InvalidArgument(prefix +
                                   " Longitude must be between -180 and 180.");
  }
  return Point2{lng, lat};
}

StatusOr<std::vector<Point2>> ParseLocations(std::string_view locations) {
  if (locations.find(',') == std::string_view::npos) {
    if (locations.starts_with(kEncodedPrefix)) {
      locations.remove_prefix(kEncodedPrefix.size());
    }
    return DecodePolyline(locations);
  }
  // Open Topo Data drops '|' at both ends.
  while (locations.starts_with('|')) locations.remove_prefix(1);
  while (locations.ends_with('|')) locations.remove_suffix(1);
  std::vector<Point2> points;
  size_t position = 1;
  while (true) {
    const size_t bar = locations.find('|');
    ASSIGN_OR_RETURN(const Point2 point,
                     ParseLatLng(locations.substr(0, bar), position));
    points.push_back(point);
    if (bar == std::string_view::npos) break;
    locations.remove_prefix(bar + 1);
    ++position;
  }
  return points;
}

StatusOr<v1::Interpolation> ParseInterpolation(
    std::optional<std::string_view> name) {
  if (!name.has_value() || name->empty() || *name == "bilinear" ||
      *name == "linear") {
    return v1::INTERPOLATION_LINEAR;
  }
  if (*name == "nearest") return v1::INTERPOLATION_NEAREST;
  if (*name == "natural") return v1::INTERPOLATION_NATURAL_NEIGHBOR;
  std::string message =
      "Invalid interpolation method " + QuotedInput(*name) + ".";
  if (*name == "cubic") {
    message +=
        " A TIN has no cubic interpolation: its surface is linear over each "
        "triangle.";
  }
  return Status::InvalidArgument(
      message +
      " The valid interpolation methods are: bilinear, linear, nearest, "
      "natural.");
}

// Open Topo Data's integers are Python's; these fit in 64 bits.
bool ParseInteger(std::string_view text, int64_t* value) {
  text = Trimmed(text);
  if (text.starts_with('+')) text.remove_prefix(1);
  const auto [end, error] =
      std::from_chars(text.data(), text.data() + text.size(), *value);
  return !text.empty() && error == std::errc() &&
         end == text.data() + text.size();
}

StatusOr<uint32_t> ParseSamples(std::optional<std::string_view> text) {
  if (!text.has_value() || text->empty()) return 0u;
  int64_t samples = 0;
  if (!ParseInteger(*text, &samples)) {
    return Status::InvalidArgument("Invalid value for samples argument " +
                                   QuotedInput(*text) +
                                   ". Samples should be an integer.");
  }
  if (samples < 2) {
    return Status::InvalidArgument(
        "Must provide at least 2 samples. The ends of the path are included "
        "as samples.");
  }
  // Past uint32, the server's sample limit refuses it by its own message.
  return static_cast<uint32_t>(std::min<int64_t>(samples, UINT32_MAX));
}

StatusOr<std::variant<OpenTopoDataQuery::NoData, int64_t>> ParseNoData(
    std::optional<std::string_view> text) {
  using NoData = OpenTopoDataQuery::NoData;
  if (!text.has_value() || *text == "null") return NoData::kNull;
  if (text->size() == 3 && (((*text)[0] | 0x20) == 'n') &&
      (((*text)[1] | 0x20) == 'a') && (((*text)[2] | 0x20) == 'n')) {
    return NoData::kNan;
  }
  int64_t value = 0;
  if (ParseInteger(*text, &value)) return value;
  return Status::InvalidArgument(
      "Invalid nodata value " + QuotedInput(*text) +
      ". Valid nodata values are 'null', 'nan', or an integer (64-bit).");
}

}  // namespace

StatusOr<OpenTopoDataQuery> ParseOpenTopoDataQuery(
    const RequestFields& fields) {
  OpenTopoDataQuery query;
  ASSIGN_OR_RETURN(query.interpolation,
                   ParseInterpolation(fields.Get("interpolation")));
  ASSIGN_OR_RETURN(query.nodata, ParseNoData(fields.Get("nodata_value")));
  const std::optional<std::string_view> locations = fields.Get("locations");
  const std::optional<std::string_view> path = fields.Get("path");
  if (locations.has_value() && path.has_value()) {
    return Status::InvalidArgument(
        "Provide either locations or path, not both.");
  }
  const std::string_view points = locations.value_or(path.value_or(""));
  if (points.empty()) {
    return Status::InvalidArgument(
        "No locations provided. Add locations in a query string: "
        "?locations=lat1,lon1|lat2,lon2.");
  }
  ASSIGN_OR_RETURN(query.points, ParseLocations(points));
  ASSIGN_OR_RETURN(query.samples, ParseSamples(fields.Get("samples")));
  if (path.has_value() && query.samples == 0) {
    return Status::InvalidArgument(
        "A path needs samples: add samples=N (at least 2) for N evenly "
        "spaced points along it.");
  }
  return query;
}

}  // namespace locator
