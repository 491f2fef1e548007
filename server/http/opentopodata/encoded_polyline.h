// DecodePolyline: Google's Encoded Polyline Algorithm Format
// (https://developers.google.com/maps/documentation/utilities/polylinealgorithm),
// the "enc:..." form of Open Topo Data's and Google Elevation's `locations`
// and `path`: each coordinate is the difference from the previous one,
// times 1e5, zig-zag encoded in 5-bit chunks of characters '?' (63) to
// '~' (126), latitude first.
//
// Decoding is strict and bounded: a character outside '?'..'~', a value
// left unfinished at the end, a value of more than 7 chunks (more than
// 35 bits: no latitude or longitude needs them), a latitude without its
// longitude, or a point outside [-90, 90] x [-180, 180] is InvalidArgument
// naming its byte offset.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_SERVER_HTTP_OPENTOPODATA_ENCODED_POLYLINE_H_
#define LOCATOR_SERVER_HTTP_OPENTOPODATA_ENCODED_POLYLINE_H_

#include <string_view>
#include <vector>

#include "locator/geometry.h"
#include "locator/status_or.h"

namespace locator {

// The points of `encoded` (without "enc:"), x = longitude, y = latitude.
StatusOr<std::vector<Point2>> DecodePolyline(std::string_view encoded);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_OPENTOPODATA_ENCODED_POLYLINE_H_
