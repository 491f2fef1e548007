// A LAS 1.0-1.4 writer for tests, written from the ASPRS specification
// independently of the reader (common/gis/las/): fixtures are made at test
// time, and the bad-file tables patch the bytes it writes.
//
// Thread-safety: free functions.

#ifndef LOCATOR_TESTS_COMMON_GIS_LAS_WRITER_H_
#define LOCATOR_TESTS_COMMON_GIS_LAS_WRITER_H_

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace locator::gis::testing {

struct LasPoint {
  double x = 0, y = 0, z = 0;
  uint8_t classification = 1;
  uint8_t return_number = 1;
  uint8_t returns = 1;
  bool withheld = false;
};

struct LasFileOptions {
  uint8_t minor_version = 2;  // 1.minor_version
  uint8_t point_format = 1;   // 0-10
  // 0: the format's own length; more adds zero "extra bytes".
  uint16_t record_length = 0;
  std::array<double, 3> scale = {0.01, 0.01, 0.01};
  std::array<double, 3> offset = {0, 0, 0};
  // The OGC WKT record (2112), as a VLR, or as an EVLR when wkt_in_evlr.
  std::string wkt;
  bool wkt_in_evlr = false;
  // GeoTIFF key records (34735-34737); none when geo_keys is empty.
  std::vector<uint16_t> geo_keys;
  std::vector<double> geo_doubles;
  std::string geo_ascii;
  // Bytes of a user VLR ("locator test", record 1) added before the others.
  std::string user_vlr;
};

// Byte offsets of header fields the bad-file tables patch.
inline constexpr size_t kLasHeaderSizeAt = 94;
inline constexpr size_t kLasPointDataOffsetAt = 96;
inline constexpr size_t kLasVlrCountAt = 100;
inline constexpr size_t kLasPointFormatAt = 104;
inline constexpr size_t kLasRecordLengthAt = 105;
inline constexpr size_t kLasLegacyCountAt = 107;
inline constexpr size_t kLasScaleAt = 131;
inline constexpr size_t kLasEvlrStartAt = 235;
inline constexpr size_t kLasEvlrCountAt = 243;
inline constexpr size_t kLasPointCountAt = 247;
// The first VLR's record length field, in a file with VLRs.
size_t LasFirstVlrLengthAt(const LasFileOptions& options);

// The bytes of a LAS file holding `points` as `options` says.
std::string LasBytes(const std::vector<LasPoint>& points,
                     const LasFileOptions& options = LasFileOptions());

// Writes LasBytes(points, options) to `path`.
void WriteLasFile(const std::string& path, const std::vector<LasPoint>& points,
                  const LasFileOptions& options = LasFileOptions());

// GeoTIFF keys naming projected CRS EPSG:`code` (GTModelType projected,
// ProjectedCSTypeGeoKey `code`, linear units metre).
std::vector<uint16_t> ProjectedGeoKeys(uint16_t code);

// Overwrites `bytes` at `at` with `value`'s bytes (little-endian).
template <typename T>
void Patch(std::string* bytes, size_t at, T value) {
  for (size_t i = 0; i < sizeof(T); ++i) {
    (*bytes)[at + i] =
        static_cast<char>(reinterpret_cast<const unsigned char*>(&value)[i]);
  }
}

}  // namespace locator::gis::testing

#endif  // LOCATOR_TESTS_COMMON_GIS_LAS_WRITER_H_
