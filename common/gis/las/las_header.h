// LasHeader: the public header block of an uncompressed LAS 1.0-1.4 file
// (ASPRS LAS Specification 1.4 R15) and the directory of its variable length
// records, read and checked strictly before any point is.
//
// What ParseLasHeader checks, each failure an InvalidArgument that starts
// with the file's name and says what is wrong and what was expected:
//   - the file is at least as long as the version's header (227 bytes for
//     1.0-1.2, 235 for 1.3, 375 for 1.4) and starts with "LASF";
//   - the version is 1.0-1.4; the header size is at least the version's and
//     inside the file;
//   - the point data starts after the header and the VLRs, and not past the
//     end of the file; every VLR header and payload lies between the header
//     and the point data; every EVLR (1.4) lies after the point data and
//     inside the file;
//   - the point format is 0-10 (6-10 only in LAS 1.4), and the record length
//     holds at least that format's fields;
//   - the point count (the 64-bit one in 1.4; the legacy 32-bit count, where
//     set, must agree with it) fits between the point data offset and the end
//     of the file (or the first EVLR);
//   - the scale factors are finite and not zero, the offsets finite, and no
//     scaled coordinate can overflow a double.
// A compressed file (LAZ: the point format's compression bits or a LASzip
// VLR) is FailedPrecondition, saying how to decompress it.
//
// Thread-safety: plain values and a free function.

#ifndef LOCATOR_COMMON_GIS_LAS_LAS_HEADER_H_
#define LOCATOR_COMMON_GIS_LAS_LAS_HEADER_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/gis/las/las_input.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis::las {

// A variable length record (VLR) or an extended one (EVLR, LAS 1.4): where
// its payload is in the file.
struct LasVlr {
  std::string user_id;  // up to 16 characters, trailing NULs removed
  uint16_t record_id = 0;
  uint64_t payload_offset = 0;
  uint64_t payload_length = 0;
  bool extended = false;
};

struct LasHeader {
  uint8_t version_major = 0;
  uint8_t version_minor = 0;
  uint16_t global_encoding = 0;
  uint16_t header_size = 0;
  uint64_t point_data_offset = 0;
  uint8_t point_format = 0;  // 0-10
  uint16_t point_record_length = 0;
  uint64_t point_count = 0;
  // x = X * scale[0] + offset[0], and so for y and z.
  std::array<double, 3> scale = {};
  std::array<double, 3> offset = {};
  // VLRs in file order, then EVLRs.
  std::vector<LasVlr> vlrs;

  // The first (E)VLR with `user_id` and `record_id`, or null.
  const LasVlr* FindVlr(std::string_view user_id, uint16_t record_id) const;
};

// Bytes a record of point format `format` (0-10) needs at least.
size_t MinPointRecordLength(uint8_t format);

// The message for a compressed LAS (LAZ) file `name`, saying how to
// decompress it.
std::string LazMessage(const std::string& name);

// Reads and checks the header and (E)VLR directory of `input` (see above).
StatusOr<LasHeader> ParseLasHeader(LasInput& input);

}  // namespace locator::gis::las

#endif  // LOCATOR_COMMON_GIS_LAS_LAS_HEADER_H_
