// How the `locator` CLI shows answers: human-readable text, JSON (the
// canonical proto3 JSON mapping, field names as in the .proto), and the CSV
// rows of `locator batch`.
//
// Thread-safety: stateless functions.

#ifndef LOCATOR_CLIENT_CLI_FORMAT_H_
#define LOCATOR_CLIENT_CLI_FORMAT_H_

#include <google/protobuf/message.h>

#include <span>
#include <string>

#include "locator/v1/locator.pb.h"

namespace locator {

// The shortest text that reads back as exactly `value` ("0.1", "1e-07").
std::string FormatDouble(double value);
// `value` with `decimals` digits after the point ("0.42").
std::string FormatFixed(double value, int decimals);

// The dataset's CRS: "WGS 84 / UTM zone 33N (EPSG:32633)", its name alone
// without an EPSG code, or "none".
std::string FormatCrs(const v1::DatasetStats& stats);

// "FACE", "EDGE", "VERTEX", "OUTSIDE_CONVEX_HULL", "OUTSIDE_DOMAIN" (the
// enum name without its LOCATION_TYPE_ prefix).
std::string LocationTypeName(v1::LocationType type);
// "LINE_VERTEX", "EDGE_CROSSING", "MESH_VERTEX", "SAMPLE".
std::string ProfilePointKindName(v1::ProfilePointKind kind);

// `message` as one line of JSON, every field present (defaults included).
std::string MessageToJson(const google::protobuf::Message& message);

// Multi-line "label  value" text, each ending in a newline.
std::string FormatLocate(const v1::LocateResponse& response);
std::string FormatStats(const v1::GetStatsResponse& stats);
std::string FormatTuning(const v1::TuningStats& tuning);
std::string FormatReload(const v1::ReloadResponse& response);

// One line per dataset under a header line: name, default mark, serving,
// points, triangles, CRS.
std::string FormatDatasets(const v1::ListDatasetsResponse& response);

// The profile as text: its length and crossings, then tables of the
// breakpoints (distance, x, y, z, triangle, kind), the samples and the
// gaps.
std::string FormatProfile(const v1::ProfileResponse& response);
// The profile as CSV, header kind,distance,x,y,z,triangle_id,segment: the
// breakpoints and samples in one table ordered by distance (breakpoints
// first at equal distances); z is empty where the surface has no value.
std::string ProfileCsv(const v1::ProfileResponse& response);

// The CSV header of `locator batch` output, newline included.
std::string BatchCsvHeader();
// Appends one CSV row per point of `response` (which asked for vertex ids,
// barycentric coordinates and values) for the queries xs/ys to `out`.
void AppendBatchCsvRows(std::span<const double> xs, std::span<const double> ys,
                        const v1::LocateBatchResponse& response,
                        std::string* out);

}  // namespace locator

#endif  // LOCATOR_CLIENT_CLI_FORMAT_H_
