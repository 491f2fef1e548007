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

// "FACE", "EDGE", "VERTEX", "OUTSIDE_CONVEX_HULL", "OUTSIDE_DOMAIN" (the
// enum name without its LOCATION_TYPE_ prefix).
std::string LocationTypeName(v1::LocationType type);

// `message` as one line of JSON, every field present (defaults included).
std::string MessageToJson(const google::protobuf::Message& message);

// Multi-line "label  value" text, each ending in a newline.
std::string FormatLocate(const v1::LocateResponse& response);
std::string FormatStats(const v1::GetStatsResponse& stats);
std::string FormatTuning(const v1::TuningStats& tuning);
std::string FormatReload(const v1::ReloadResponse& response);

// The CSV header of `locator batch` output, newline included.
std::string BatchCsvHeader();
// Appends one CSV row per point of `response` (which asked for vertex ids,
// barycentric coordinates and values) for the queries xs/ys to `out`.
void AppendBatchCsvRows(std::span<const double> xs, std::span<const double> ys,
                        const v1::LocateBatchResponse& response,
                        std::string* out);

}  // namespace locator

#endif  // LOCATOR_CLIENT_CLI_FORMAT_H_
