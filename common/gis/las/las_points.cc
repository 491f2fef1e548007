#include "common/gis/las/las_points.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "common/status_macros.h"

namespace locator::gis::las {
namespace {

// Bytes read per chunk of records.
constexpr size_t kChunkBytes = 1 << 20;
// The highest class point formats 0-5 can hold (5 bits).
constexpr int kMaxLegacyClass = 31;
constexpr uint8_t kFirstExtendedFormat = 6;

// The fields of one record the filter and the dataset need.
struct Record {
  int32_t raw[3];
  unsigned return_number;
  unsigned returns;
  unsigned classification;
  bool withheld;
};

// Decodes `bytes`, a record of point format `format` (LAS 1.4 R15, Tables
// 7 and 13): formats 0-5 pack 3-bit return fields into byte 14 and a 5-bit
// class with the withheld bit (7) into byte 15; formats 6-10 pack 4-bit
// return fields into byte 14, the withheld flag (bit 2) into byte 15 and the
// class into byte 16.
Record Decode(const unsigned char* bytes, uint8_t format) {
  Record r;
  std::memcpy(r.raw, bytes, sizeof(r.raw));
  const unsigned returns_byte = bytes[14];
  if (format < kFirstExtendedFormat) {
    r.return_number = returns_byte & 0x7;
    r.returns = (returns_byte >> 3) & 0x7;
    r.classification = bytes[15] & 0x1f;
    r.withheld = (bytes[15] & 0x80) != 0;
  } else {
    r.return_number = returns_byte & 0xf;
    r.returns = returns_byte >> 4;
    r.withheld = (bytes[15] & 0x4) != 0;
    r.classification = bytes[16];
  }
  return r;
}

// Whether a record with these return fields passes `returns`. Writers that
// leave the fields 0 make a point both first and last.
bool ReturnPasses(const Record& r, LasReturns returns) {
  switch (returns) {
    case LasReturns::kAll:
      return true;
    case LasReturns::kFirst:
      return r.return_number <= 1;
    case LasReturns::kLast:
      return r.return_number >= r.returns;
  }
  return false;
}

}  // namespace

Status ReadLasPoints(const LasHeader& header, LasInput& input,
                     const LasFilter& filter, size_t max_points, Dataset* out,
                     LasPointCounts* counts) {
  *counts = LasPointCounts();
  if (header.point_format < kFirstExtendedFormat &&
      filter.highest_class > kMaxLegacyClass) {
    return Status::InvalidArgument(
        input.name() + ": class " + std::to_string(filter.highest_class) +
        " cannot occur in point format " + std::to_string(header.point_format) +
        ", whose classes are 0-31");
  }
  const size_t length = header.point_record_length;
  const size_t per_chunk = std::max<size_t>(1, kChunkBytes / length);
  std::vector<unsigned char> chunk(per_chunk * length);
  // Without a filter every record is kept: reserve once.
  const bool keeps_all =
      filter.classes.all() && filter.returns == LasReturns::kAll;
  if (keeps_all) {
    const size_t expected =
        static_cast<size_t>(std::min<uint64_t>(header.point_count, max_points));
    out->points.reserve(out->points.size() + expected);
    out->values.reserve(out->values.size() + expected);
  }
  for (uint64_t done = 0; done < header.point_count;) {
    const size_t records = static_cast<size_t>(
        std::min<uint64_t>(per_chunk, header.point_count - done));
    RETURN_IF_ERROR(input.ReadAt(header.point_data_offset + done * length,
                                 records * length, chunk.data()));
    for (size_t i = 0; i < records; ++i) {
      const Record r = Decode(chunk.data() + i * length, header.point_format);
      ++counts->per_class[r.classification];
      if (r.withheld) {
        ++counts->withheld;
        continue;
      }
      if (!filter.classes.test(r.classification) ||
          !ReturnPasses(r, filter.returns)) {
        continue;
      }
      if (counts->kept == max_points) {
        return Status::ResourceExhausted(
            input.name() + ": more than " + std::to_string(max_points) +
            " points pass the filters (max_points limit)");
      }
      ++counts->kept;
      // ParseLasHeader checked that no scaled coordinate overflows.
      out->points.push_back({r.raw[0] * header.scale[0] + header.offset[0],
                             r.raw[1] * header.scale[1] + header.offset[1]});
      out->values.push_back(r.raw[2] * header.scale[2] + header.offset[2]);
    }
    done += records;
    counts->records = done;
  }
  return Status::OK();
}

}  // namespace locator::gis::las
