#include "common/gis/las/las_crs.h"

#include <geo_normalize.h>
#include <geo_simpletags.h>
#include <geotiff.h>
#include <geovalues.h>

#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

#include "common/gis/proj_objects.h"
#include "common/status_macros.h"

namespace locator::gis::las {
namespace {

constexpr std::string_view kProjectionUserId = "LASF_Projection";
constexpr uint16_t kWktRecord = 2112;
constexpr uint16_t kGeoKeyRecord = 34735;
constexpr uint16_t kGeoDoubleRecord = 34736;
constexpr uint16_t kGeoAsciiRecord = 34737;
// A CRS record larger than this is refused rather than read (a WKT is a few
// kilobytes; an EVLR's length is 64-bit).
constexpr uint64_t kMaxCrsRecordBytes = 1 << 20;

Status Bad(const LasInput& input, std::string_view record,
           const std::string& what) {
  return Status::InvalidArgument(input.name() + ": " + std::string(record) +
                                 ": " + what);
}

StatusOr<std::vector<unsigned char>> ReadPayload(LasInput& input,
                                                 const LasVlr& vlr,
                                                 std::string_view what) {
  if (vlr.payload_length > kMaxCrsRecordBytes) {
    return Bad(input, what,
               std::to_string(vlr.payload_length) + " bytes, more than the " +
                   std::to_string(kMaxCrsRecordBytes) +
                   " a CRS record may have");
  }
  std::vector<unsigned char> bytes(vlr.payload_length);
  RETURN_IF_ERROR(input.ReadAt(vlr.payload_offset, bytes.size(), bytes.data()));
  return bytes;
}

// `crs` (anything PROJ reads) as WKT2.
StatusOr<std::string> ToWkt2(const LasInput& input, std::string_view record,
                             const std::string& crs) {
  // The file's CRS is the operator's dataset's, as an OGR layer's is.
  GuardedProjContext& ctx = ThreadProjContext();
  const StatusOr<PjPtr> created = CreateCrs(ctx, crs);
  if (!created.ok()) return Bad(input, record, created.status().message());
  const char* text =
      proj_as_wkt(ctx.get(), created->get(), PJ_WKT2_2019, nullptr);
  if (text == nullptr) {
    return Bad(input, record,
               "PROJ cannot write the CRS as WKT: " + LastProjError(ctx.get()));
  }
  return std::string(text);
}

struct GtifDeleter {
  void operator()(GTIF* gtif) const { GTIFFree(gtif); }
};
struct SimpleTagsDeleter {
  void operator()(ST_TIFF* tags) const { ST_Destroy(tags); }
};

// Checks that every key of the directory `keys` (uint16 values) refers only
// to values inside its records, so that libgeotiff reads nothing else.
Status CheckKeyDirectory(const LasInput& input,
                         const std::vector<uint16_t>& keys, size_t doubles,
                         size_t ascii) {
  constexpr std::string_view kWhat = "GeoTIFF key directory (record 34735)";
  if (keys.size() < 4) {
    return Bad(input, kWhat, "shorter than its 4-value header");
  }
  const size_t count = keys[3];
  if (keys.size() < 4 * (count + 1)) {
    return Bad(input, kWhat,
               std::to_string(count) + " keys need " +
                   std::to_string(4 * (count + 1)) + " values, it has " +
                   std::to_string(keys.size()));
  }
  for (size_t k = 1; k <= count; ++k) {
    const uint16_t id = keys[4 * k];
    const uint16_t location = keys[4 * k + 1];
    const size_t values = keys[4 * k + 2];
    const size_t index = keys[4 * k + 3];
    // Short values may also sit in the directory itself (location 34735).
    const size_t available = location == kGeoDoubleRecord  ? doubles
                             : location == kGeoAsciiRecord ? ascii
                             : location == kGeoKeyRecord   ? keys.size()
                             : location == 0               ? 1
                                                           : 0;
    const bool fits = location == 0 ? values <= 1
                                    : available != 0 && index <= available &&
                                          values <= available - index;
    if (!fits) {
      return Bad(input, kWhat,
                 "key " + std::to_string(id) + " refers to " +
                     std::to_string(values) + " values at " +
                     std::to_string(index) + " of record " +
                     std::to_string(location) + ", which has " +
                     std::to_string(available));
    }
  }
  return Status::OK();
}

// The CRS the GeoTIFF keys define, in a form PROJ reads ("EPSG:32633" or
// a PROJ string).
StatusOr<std::string> GeoKeysCrs(LasInput& input, const LasHeader& header,
                                 const LasVlr& key_vlr) {
  ASSIGN_OR_RETURN(std::vector<unsigned char> bytes,
                   ReadPayload(input, key_vlr, "GeoTIFF key directory"));
  std::vector<uint16_t> keys(bytes.size() / 2);
  // An empty record: no copy (memcpy from an empty vector's null data is
  // undefined even for 0 bytes).
  if (!keys.empty()) std::memcpy(keys.data(), bytes.data(), keys.size() * 2);
  std::vector<double> doubles;
  std::vector<char> ascii;
  if (const LasVlr* vlr = header.FindVlr(kProjectionUserId, kGeoDoubleRecord)) {
    ASSIGN_OR_RETURN(bytes, ReadPayload(input, *vlr, "GeoTIFF doubles"));
    doubles.resize(bytes.size() / sizeof(double));
    if (!doubles.empty()) {
      std::memcpy(doubles.data(), bytes.data(),
                  doubles.size() * sizeof(double));
    }
  }
  if (const LasVlr* vlr = header.FindVlr(kProjectionUserId, kGeoAsciiRecord)) {
    ASSIGN_OR_RETURN(bytes, ReadPayload(input, *vlr, "GeoTIFF ASCII"));
    ascii.assign(bytes.begin(), bytes.end());
  }
  RETURN_IF_ERROR(CheckKeyDirectory(input, keys, doubles.size(), ascii.size()));
  // libgeotiff reads the ASCII parameters as one C string.
  ascii.push_back('\0');

  std::unique_ptr<ST_TIFF, SimpleTagsDeleter> tags(ST_Create());
  ST_SetKey(tags.get(), kGeoKeyRecord, static_cast<int>(keys.size()), STT_SHORT,
            keys.data());
  if (!doubles.empty()) {
    ST_SetKey(tags.get(), kGeoDoubleRecord, static_cast<int>(doubles.size()),
              STT_DOUBLE, doubles.data());
  }
  ST_SetKey(tags.get(), kGeoAsciiRecord, static_cast<int>(ascii.size()),
            STT_ASCII, ascii.data());
  std::unique_ptr<GTIF, GtifDeleter> gtif(GTIFNewSimpleTags(tags.get()));
  constexpr std::string_view kWhat = "GeoTIFF keys";
  if (gtif == nullptr) return Bad(input, kWhat, "libgeotiff cannot read them");
  GTIFAttachPROJContext(gtif.get(), ThreadProjContext().get());
  GTIFDefn defn;
  if (!GTIFGetDefn(gtif.get(), &defn) || !defn.DefnSet) {
    return Bad(input, kWhat, "they define no coordinate reference system");
  }
  if (defn.Model == ModelTypeGeocentric) {
    return Bad(input, kWhat, "a geocentric CRS has no horizontal plane");
  }
  if (defn.Model == ModelTypeProjected && defn.PCS != KvUserDefined) {
    return "EPSG:" + std::to_string(static_cast<uint16_t>(defn.PCS));
  }
  if (defn.Model == ModelTypeGeographic && defn.GCS != KvUserDefined) {
    return "EPSG:" + std::to_string(static_cast<uint16_t>(defn.GCS));
  }
  char* proj_string = GTIFGetProj4Defn(&defn);
  std::string crs = proj_string == nullptr ? "" : proj_string;
  GTIFFreeMemory(proj_string);
  if (crs.empty()) {
    return Bad(input, kWhat, "libgeotiff cannot express their CRS for PROJ");
  }
  return crs;
}

}  // namespace

StatusOr<std::string> ReadLasCrs(const LasHeader& header, LasInput& input) {
  if (const LasVlr* vlr = header.FindVlr(kProjectionUserId, kWktRecord)) {
    constexpr std::string_view kWhat = "OGC WKT record (2112)";
    ASSIGN_OR_RETURN(const std::vector<unsigned char> bytes,
                     ReadPayload(input, *vlr, kWhat));
    // The WKT is NUL-terminated, possibly padded.
    std::string text(bytes.begin(), bytes.end());
    text.resize(std::strlen(text.c_str()));
    if (text.empty()) return Bad(input, kWhat, "empty");
    return ToWkt2(input, kWhat, text);
  }
  if (const LasVlr* vlr = header.FindVlr(kProjectionUserId, kGeoKeyRecord)) {
    ASSIGN_OR_RETURN(const std::string crs, GeoKeysCrs(input, header, *vlr));
    return ToWkt2(input, "GeoTIFF keys", crs);
  }
  return std::string();
}

}  // namespace locator::gis::las
