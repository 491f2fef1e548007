#include "server/http/opentopodata/encoded_polyline.h"

#include <cstdint>
#include <string>

#include "common/input_text.h"

namespace locator {
namespace {

constexpr int kMaxChunks = 7;
constexpr double kScale = 1e5;

// Reads one zig-zag value from `encoded` at *offset, which it advances.
Status ReadValue(std::string_view encoded, size_t* offset, int64_t* value) {
  const size_t start = *offset;
  uint64_t bits = 0;
  for (int chunk = 0;; ++chunk) {
    if (*offset >= encoded.size()) {
      return Status::InvalidArgument(
          "Unable to parse locations as polyline: the value at byte " +
          std::to_string(start) + " is unfinished at the end");
    }
    const char c = encoded[*offset];
    if (c < 63 || c > 126) {
      return Status::InvalidArgument(
          "Unable to parse locations as polyline: byte " +
          std::to_string(*offset) + " (" +
          QuotedInput(encoded.substr(*offset, 1)) +
          ") is not a polyline character ('?' to '~')");
    }
    if (chunk == kMaxChunks) {
      return Status::InvalidArgument(
          "Unable to parse locations as polyline: the value at byte " +
          std::to_string(start) + " has more than " +
          std::to_string(kMaxChunks) + " chunks");
    }
    ++*offset;
    const uint64_t piece = static_cast<uint64_t>(c - 63);
    bits |= (piece & 0x1f) << (5 * chunk);
    if ((piece & 0x20) == 0) break;
  }
  const int64_t half = static_cast<int64_t>(bits >> 1);
  *value = (bits & 1) != 0 ? ~half : half;
  return Status::OK();
}

}  // namespace

StatusOr<std::vector<Point2>> DecodePolyline(std::string_view encoded) {
  std::vector<Point2> points;
  int64_t lat = 0;
  int64_t lng = 0;
  size_t offset = 0;
  while (offset < encoded.size()) {
    const size_t start = offset;
    int64_t delta = 0;
    if (Status read = ReadValue(encoded, &offset, &delta); !read.ok()) {
      return read;
    }
    lat += delta;
    if (offset == encoded.size()) {
      return Status::InvalidArgument(
          "Unable to parse locations as polyline: the latitude at byte " +
          std::to_string(start) + " has no longitude");
    }
    if (Status read = ReadValue(encoded, &offset, &delta); !read.ok()) {
      return read;
    }
    lng += delta;
    const Point2 point{static_cast<double>(lng) / kScale,
                       static_cast<double>(lat) / kScale};
    if (point.y < -90 || point.y > 90 || point.x < -180 || point.x > 180) {
      return Status::InvalidArgument(
          "Unable to parse locations as polyline: the point at byte " +
          std::to_string(start) + " is latitude " + NumberText(point.y) +
          ", longitude " + NumberText(point.x) +
          ", outside [-90, 90] x [-180, 180]");
    }
    points.push_back(point);
  }
  return points;
}

}  // namespace locator
