#include "common/gis/las/las_header.h"

#include <bit>
#include <cmath>
#include <cstring>

#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator::gis::las {
namespace {

static_assert(std::endian::native == std::endian::little,
              "LAS is little-endian; this reader copies fields as they are");

// Offsets of the public header block's fields (LAS 1.4 R15, Table 3).
constexpr size_t kGlobalEncodingAt = 6;
constexpr size_t kVersionMajorAt = 24;
constexpr size_t kVersionMinorAt = 25;
constexpr size_t kHeaderSizeAt = 94;
constexpr size_t kPointDataOffsetAt = 96;
constexpr size_t kVlrCountAt = 100;
constexpr size_t kPointFormatAt = 104;
constexpr size_t kRecordLengthAt = 105;
constexpr size_t kLegacyPointCountAt = 107;
constexpr size_t kScaleAt = 131;
constexpr size_t kOffsetAt = 155;
constexpr size_t kEvlrStartAt = 235;
constexpr size_t kEvlrCountAt = 243;
constexpr size_t kPointCountAt = 247;

// The header's size in each version.
constexpr size_t kHeaderSize12 = 227;
constexpr size_t kHeaderSize13 = 235;
constexpr size_t kHeaderSize14 = 375;

constexpr size_t kVlrHeaderSize = 54;
constexpr size_t kEvlrHeaderSize = 60;
constexpr size_t kVlrUserIdAt = 2;
constexpr size_t kVlrUserIdSize = 16;
constexpr size_t kVlrRecordIdAt = 18;
constexpr size_t kVlrLengthAt = 20;

// LASzip marks compressed point formats with bit 7 (and bit 6) set, and
// describes its compression in this VLR.
constexpr uint8_t kCompressionBits = 0xC0;
constexpr std::string_view kLaszipUserId = "laszip encoded";
constexpr uint16_t kLaszipRecordId = 22204;

constexpr uint8_t kMaxPointFormat = 10;
constexpr size_t kMinRecordLength[kMaxPointFormat + 1] = {
    20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

template <typename T>
T Get(const unsigned char* bytes, size_t at) {
  T value;
  std::memcpy(&value, bytes + at, sizeof(T));
  return value;
}

std::string Num(uint64_t value) { return std::to_string(value); }

// The user id field of a (E)VLR header: up to 16 characters, NUL-padded;
// bytes that are not printable ASCII become '?' (it goes into messages).
std::string UserId(const unsigned char* bytes) {
  std::string id;
  for (size_t i = 0; i < kVlrUserIdSize && bytes[kVlrUserIdAt + i] != 0; ++i) {
    const unsigned char c = bytes[kVlrUserIdAt + i];
    id += c >= 0x20 && c < 0x7f ? static_cast<char>(c) : '?';
  }
  return id;
}

// Collects errors that all start with the file's name.
class Checker {
 public:
  explicit Checker(const std::string& name) : name_(name) {}
  Status Bad(const std::string& what) const {
    return Status::InvalidArgument(name_ + ": " + what);
  }

 private:
  const std::string& name_;
};

Status CheckScaleAndOffset(const Checker& check, const LasHeader& h) {
  constexpr char kAxes[] = "XYZ";
  // The largest |int32| a record may hold.
  constexpr double kMaxRaw = 2147483648.0;
  for (int axis = 0; axis < 3; ++axis) {
    const double scale = h.scale[axis];
    const double offset = h.offset[axis];
    const std::string name(1, kAxes[axis]);
    if (!std::isfinite(scale) || scale == 0) {
      return check.Bad(name + " scale factor " + std::to_string(scale) +
                       " must be finite and not zero");
    }
    if (!std::isfinite(offset)) {
      return check.Bad(name + " offset must be finite");
    }
    if (!std::isfinite(std::abs(scale) * kMaxRaw + std::abs(offset))) {
      return check.Bad(name +
                       " scale factor and offset let coordinates "
                       "overflow a double");
    }
  }
  return Status::OK();
}

Status ReadVlrs(LasInput& input, const Checker& check, uint32_t count,
                LasHeader* h) {
  const uint64_t space = h->point_data_offset - h->header_size;
  if (uint64_t{count} > space / kVlrHeaderSize) {
    return check.Bad(Num(count) + " VLRs of at least " + Num(kVlrHeaderSize) +
                     " bytes each do not fit in the " + Num(space) +
                     " bytes between the header and the point data");
  }
  uint64_t at = h->header_size;
  for (uint32_t i = 0; i < count; ++i) {
    unsigned char bytes[kVlrHeaderSize];
    if (at + kVlrHeaderSize > h->point_data_offset) {
      return check.Bad("VLR " + Num(i) + " at offset " + Num(at) +
                       " runs past the point data offset " +
                       Num(h->point_data_offset));
    }
    RETURN_IF_ERROR(input.ReadAt(at, sizeof(bytes), bytes));
    LasVlr vlr;
    vlr.user_id = UserId(bytes);
    vlr.record_id = Get<uint16_t>(bytes, kVlrRecordIdAt);
    vlr.payload_offset = at + kVlrHeaderSize;
    vlr.payload_length = Get<uint16_t>(bytes, kVlrLengthAt);
    if (vlr.payload_offset + vlr.payload_length > h->point_data_offset) {
      return check.Bad(
          "VLR " + Num(i) + " (" + QuotedInput(vlr.user_id) + ", record " +
          Num(vlr.record_id) + ") of " + Num(vlr.payload_length) +
          " bytes at offset " + Num(vlr.payload_offset) +
          " runs past the point data offset " + Num(h->point_data_offset));
    }
    at = vlr.payload_offset + vlr.payload_length;
    h->vlrs.push_back(std::move(vlr));
  }
  return Status::OK();
}

Status ReadEvlrs(LasInput& input, const Checker& check, uint64_t start,
                 uint32_t count, uint64_t points_end, LasHeader* h) {
  const uint64_t size = input.size();
  if (start < points_end || start > size) {
    return check.Bad("the first EVLR's offset " + Num(start) +
                     " is not between the end of the point data (" +
                     Num(points_end) + ") and the end of the file (" +
                     Num(size) + ")");
  }
  if (uint64_t{count} > (size - start) / kEvlrHeaderSize) {
    return check.Bad(Num(count) + " EVLRs do not fit in the " +
                     Num(size - start) + " bytes after offset " + Num(start));
  }
  uint64_t at = start;
  for (uint32_t i = 0; i < count; ++i) {
    unsigned char bytes[kEvlrHeaderSize];
    if (at > size || size - at < kEvlrHeaderSize) {
      return check.Bad("EVLR " + Num(i) + " at offset " + Num(at) +
                       " runs past the end of the file");
    }
    RETURN_IF_ERROR(input.ReadAt(at, sizeof(bytes), bytes));
    LasVlr vlr;
    vlr.extended = true;
    vlr.user_id = UserId(bytes);
    vlr.record_id = Get<uint16_t>(bytes, kVlrRecordIdAt);
    vlr.payload_offset = at + kEvlrHeaderSize;
    vlr.payload_length = Get<uint64_t>(bytes, kVlrLengthAt);
    if (vlr.payload_length > size - vlr.payload_offset) {
      return check.Bad(
          "EVLR " + Num(i) + " (" + QuotedInput(vlr.user_id) + ", record " +
          Num(vlr.record_id) + ") of " + Num(vlr.payload_length) +
          " bytes at offset " + Num(vlr.payload_offset) +
          " runs past the end of the file (" + Num(size) + " bytes)");
    }
    at = vlr.payload_offset + vlr.payload_length;
    h->vlrs.push_back(std::move(vlr));
  }
  return Status::OK();
}

}  // namespace

const LasVlr* LasHeader::FindVlr(std::string_view user_id,
                                 uint16_t record_id) const {
  for (const LasVlr& vlr : vlrs) {
    if (vlr.user_id == user_id && vlr.record_id == record_id) return &vlr;
  }
  return nullptr;
}

size_t MinPointRecordLength(uint8_t format) { return kMinRecordLength[format]; }

std::string LazMessage(const std::string& name) {
  return name +
         ": a compressed LAS file (LAZ), which locator does not read; "
         "decompress it first, e.g. `laszip -i " +
         name + " -o out.las` (LAStools) or `pdal translate " + name +
         " out.las`, and serve out.las";
}

StatusOr<LasHeader> ParseLasHeader(LasInput& input) {
  const Checker check(input.name());
  const uint64_t size = input.size();
  unsigned char b[kHeaderSize14] = {};
  if (size < kHeaderSize12) {
    return check.Bad("truncated header: the file has " + Num(size) +
                     " bytes, a LAS header at least " + Num(kHeaderSize12));
  }
  const size_t head = size < sizeof(b) ? static_cast<size_t>(size) : sizeof(b);
  RETURN_IF_ERROR(input.ReadAt(0, head, b));
  if (std::memcmp(b, "LASF", 4) != 0) {
    return check.Bad("not a LAS file (it does not start with \"LASF\")");
  }
  LasHeader h;
  h.version_major = b[kVersionMajorAt];
  h.version_minor = b[kVersionMinorAt];
  const std::string version = Num(h.version_major) + "." + Num(h.version_minor);
  if (h.version_major != 1 || h.version_minor > 4) {
    return check.Bad("LAS version " + version +
                     " is not supported (1.0 to 1.4 are)");
  }
  const size_t version_header = h.version_minor >= 4   ? kHeaderSize14
                                : h.version_minor == 3 ? kHeaderSize13
                                                       : kHeaderSize12;
  if (size < version_header) {
    return check.Bad("truncated header: the file has " + Num(size) +
                     " bytes, a LAS " + version + " header " +
                     Num(version_header));
  }
  h.global_encoding = Get<uint16_t>(b, kGlobalEncodingAt);
  h.header_size = Get<uint16_t>(b, kHeaderSizeAt);
  if (h.header_size < version_header || h.header_size > size) {
    return check.Bad("header size " + Num(h.header_size) +
                     " is not between the LAS " + version + " header's " +
                     Num(version_header) + " bytes and the file's " +
                     Num(size));
  }
  const uint8_t format_byte = b[kPointFormatAt];
  if ((format_byte & kCompressionBits) != 0) {
    return Status::FailedPrecondition(LazMessage(input.name()));
  }
  h.point_format = format_byte;
  if (h.point_format > kMaxPointFormat) {
    return check.Bad("point data record format " + Num(h.point_format) +
                     " is unknown (LAS has formats 0 to 10)");
  }
  if (h.point_format >= 6 && h.version_minor < 4) {
    return check.Bad("point data record format " + Num(h.point_format) +
                     " needs LAS 1.4, but the file is LAS " + version);
  }
  h.point_record_length = Get<uint16_t>(b, kRecordLengthAt);
  if (h.point_record_length < MinPointRecordLength(h.point_format)) {
    return check.Bad("point data record length " + Num(h.point_record_length) +
                     " is too short for format " + Num(h.point_format) +
                     ", whose fields take " +
                     Num(MinPointRecordLength(h.point_format)) + " bytes");
  }
  h.point_data_offset = Get<uint32_t>(b, kPointDataOffsetAt);
  if (h.point_data_offset < h.header_size) {
    return check.Bad("offset to point data " + Num(h.point_data_offset) +
                     " lies inside the header (" + Num(h.header_size) +
                     " bytes)");
  }
  if (h.point_data_offset > size) {
    return check.Bad("offset to point data " + Num(h.point_data_offset) +
                     " lies past the end of the file (" + Num(size) +
                     " bytes)");
  }
  RETURN_IF_ERROR(ReadVlrs(input, check, Get<uint32_t>(b, kVlrCountAt), &h));
  if (h.FindVlr(kLaszipUserId, kLaszipRecordId) != nullptr) {
    return Status::FailedPrecondition(LazMessage(input.name()));
  }

  const uint32_t legacy_count = Get<uint32_t>(b, kLegacyPointCountAt);
  h.point_count = legacy_count;
  uint64_t evlr_start = 0;
  uint32_t evlr_count = 0;
  if (h.version_minor >= 4) {
    h.point_count = Get<uint64_t>(b, kPointCountAt);
    if (legacy_count != 0 && legacy_count != h.point_count) {
      return check.Bad("the legacy point count " + Num(legacy_count) +
                       " disagrees with the point count " + Num(h.point_count));
    }
    evlr_start = Get<uint64_t>(b, kEvlrStartAt);
    evlr_count = Get<uint32_t>(b, kEvlrCountAt);
  }
  const uint64_t data_end =
      evlr_count > 0 && evlr_start <= size && evlr_start >= h.point_data_offset
          ? evlr_start
          : size;
  const uint64_t room = data_end - h.point_data_offset;
  if (h.point_count > room / h.point_record_length) {
    return check.Bad(Num(h.point_count) + " points of " +
                     Num(h.point_record_length) + " bytes from offset " +
                     Num(h.point_data_offset) + " need more than the " +
                     Num(room) + " bytes the file holds there");
  }
  if (evlr_count > 0) {
    const uint64_t points_end =
        h.point_data_offset + h.point_count * h.point_record_length;
    RETURN_IF_ERROR(
        ReadEvlrs(input, check, evlr_start, evlr_count, points_end, &h));
  }
  for (int axis = 0; axis < 3; ++axis) {
    h.scale[axis] = Get<double>(b, kScaleAt + 8 * axis);
    h.offset[axis] = Get<double>(b, kOffsetAt + 8 * axis);
  }
  RETURN_IF_ERROR(CheckScaleAndOffset(check, h));
  return h;
}

}  // namespace locator::gis::las
