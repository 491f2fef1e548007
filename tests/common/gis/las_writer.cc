#include "tests/common/gis/las_writer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

namespace locator::gis::testing {
namespace {

constexpr size_t kMinRecordLength[11] = {20, 28, 26, 34, 57, 63,
                                         30, 36, 38, 59, 67};
constexpr size_t kVlrHeader = 54;

size_t HeaderSize(uint8_t minor) {
  return minor >= 4 ? 375 : minor == 3 ? 235 : 227;
}

struct Vlr {
  std::string user_id;
  uint16_t record_id;
  std::string payload;
};

std::vector<Vlr> Vlrs(const LasFileOptions& o) {
  std::vector<Vlr> vlrs;
  if (!o.user_vlr.empty()) vlrs.push_back({"locator test", 1, o.user_vlr});
  if (!o.wkt.empty() && !o.wkt_in_evlr) {
    vlrs.push_back({"LASF_Projection", 2112, o.wkt + std::string(1, '\0')});
  }
  if (!o.geo_keys.empty()) {
    std::string keys(o.geo_keys.size() * 2, '\0');
    std::memcpy(keys.data(), o.geo_keys.data(), keys.size());
    vlrs.push_back({"LASF_Projection", 34735, keys});
    if (!o.geo_doubles.empty()) {
      std::string doubles(o.geo_doubles.size() * 8, '\0');
      std::memcpy(doubles.data(), o.geo_doubles.data(), doubles.size());
      vlrs.push_back({"LASF_Projection", 34736, doubles});
    }
    if (!o.geo_ascii.empty()) {
      vlrs.push_back({"LASF_Projection", 34737, o.geo_ascii});
    }
  }
  return vlrs;
}

class Bytes {
 public:
  template <typename T>
  void Put(T value) {
    const size_t at = text_.size();
    text_.resize(at + sizeof(T));
    std::memcpy(text_.data() + at, &value, sizeof(T));
  }
  void PutText(const std::string& text, size_t width) {
    std::string field = text.substr(0, width);
    field.resize(width, '\0');
    text_ += field;
  }
  void PutZeros(size_t count) { text_.append(count, '\0'); }
  std::string& text() { return text_; }

 private:
  std::string text_;
};

void PutVlrHeader(Bytes* b, const Vlr& vlr, bool extended) {
  b->Put<uint16_t>(0);
  b->PutText(vlr.user_id, 16);
  b->Put<uint16_t>(vlr.record_id);
  if (extended) {
    b->Put<uint64_t>(vlr.payload.size());
  } else {
    b->Put<uint16_t>(static_cast<uint16_t>(vlr.payload.size()));
  }
  b->PutText("", 32);
}

void PutRecord(Bytes* b, const LasPoint& p, const LasFileOptions& o,
               size_t length) {
  const double coordinates[3] = {p.x, p.y, p.z};
  for (int axis = 0; axis < 3; ++axis) {
    b->Put<int32_t>(static_cast<int32_t>(
        std::llround((coordinates[axis] - o.offset[axis]) / o.scale[axis])));
  }
  b->Put<uint16_t>(0);  // intensity
  size_t written = 14;
  if (o.point_format < 6) {
    b->Put<uint8_t>(
        static_cast<uint8_t>((p.return_number & 7) | (p.returns & 7) << 3));
    b->Put<uint8_t>(static_cast<uint8_t>((p.classification & 31) |
                                         (p.withheld ? 0x80 : 0)));
    written += 2;
  } else {
    b->Put<uint8_t>(
        static_cast<uint8_t>((p.return_number & 15) | (p.returns & 15) << 4));
    b->Put<uint8_t>(p.withheld ? 0x4 : 0);
    b->Put<uint8_t>(p.classification);
    written += 3;
  }
  b->PutZeros(length - written);
}

}  // namespace

size_t LasFirstVlrLengthAt(const LasFileOptions& options) {
  return HeaderSize(options.minor_version) + 20;
}

std::vector<uint16_t> ProjectedGeoKeys(uint16_t code) {
  // Key directory version 1.1.0 with 3 keys: GTModelTypeGeoKey (1024) =
  // projected, GTRasterTypeGeoKey (1025) = PixelIsArea,
  // ProjectedCSTypeGeoKey (3072) = code.
  return {1, 1, 0, 3, 1024, 0, 1, 1, 1025, 0, 1, 1, 3072, 0, 1, code};
}

std::string LasBytes(const std::vector<LasPoint>& points,
                     const LasFileOptions& o) {
  const size_t header = HeaderSize(o.minor_version);
  const size_t length =
      o.record_length != 0 ? o.record_length : kMinRecordLength[o.point_format];
  const std::vector<Vlr> vlrs = Vlrs(o);
  size_t vlr_bytes = 0;
  for (const Vlr& vlr : vlrs) vlr_bytes += kVlrHeader + vlr.payload.size();
  const uint64_t count = points.size();
  const bool evlr = o.minor_version >= 4 && !o.wkt.empty() && o.wkt_in_evlr;

  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (size_t i = 0; i < points.size(); ++i) {
    const double c[3] = {points[i].x, points[i].y, points[i].z};
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = i == 0 ? c[axis] : std::min(lo[axis], c[axis]);
      hi[axis] = i == 0 ? c[axis] : std::max(hi[axis], c[axis]);
    }
  }

  Bytes b;
  b.PutText("LASF", 4);
  b.Put<uint16_t>(0);  // file source id
  // Global encoding bit 4: the CRS is WKT (LAS 1.4).
  b.Put<uint16_t>(o.minor_version >= 4 && !o.wkt.empty() ? 0x10 : 0);
  b.PutZeros(16);  // project GUID
  b.Put<uint8_t>(1);
  b.Put<uint8_t>(o.minor_version);
  b.PutText("locator test", 32);
  b.PutText("locator las_writer", 32);
  b.Put<uint16_t>(1);     // day of year
  b.Put<uint16_t>(2026);  // year
  b.Put<uint16_t>(static_cast<uint16_t>(header));
  b.Put<uint32_t>(static_cast<uint32_t>(header + vlr_bytes));
  b.Put<uint32_t>(static_cast<uint32_t>(vlrs.size()));
  b.Put<uint8_t>(o.point_format);
  b.Put<uint16_t>(static_cast<uint16_t>(length));
  const bool legacy =
      o.point_format < 6 && count <= std::numeric_limits<uint32_t>::max();
  b.Put<uint32_t>(legacy ? static_cast<uint32_t>(count) : 0);
  b.PutZeros(5 * 4);  // legacy points by return
  for (double scale : o.scale) b.Put<double>(scale);
  for (double offset : o.offset) b.Put<double>(offset);
  for (int axis = 0; axis < 3; ++axis) {
    b.Put<double>(hi[axis]);
    b.Put<double>(lo[axis]);
  }
  if (o.minor_version >= 3) b.Put<uint64_t>(0);  // waveform data
  if (o.minor_version >= 4) {
    const uint64_t points_end = header + vlr_bytes + count * length;
    b.Put<uint64_t>(evlr ? points_end : 0);
    b.Put<uint32_t>(evlr ? 1 : 0);
    b.Put<uint64_t>(count);
    b.PutZeros(15 * 8);  // points by return
  }
  EXPECT_EQ(b.text().size(), header);
  for (const Vlr& vlr : vlrs) {
    PutVlrHeader(&b, vlr, false);
    b.text() += vlr.payload;
  }
  for (const LasPoint& p : points) PutRecord(&b, p, o, length);
  if (evlr) {
    const Vlr wkt{"LASF_Projection", 2112, o.wkt + std::string(1, '\0')};
    PutVlrHeader(&b, wkt, true);
    b.text() += wkt.payload;
  }
  return b.text();
}

void WriteLasFile(const std::string& path, const std::vector<LasPoint>& points,
                  const LasFileOptions& options) {
  std::ofstream out(path, std::ios::binary);
  out << LasBytes(points, options);
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

}  // namespace locator::gis::testing
