// The metadata documents of locatord's OGC API - EDR (OGC 19-086r6): the
// landing page, the conformance classes, and a collection (one dataset)
// with its extent, queries, CRSs, formats and parameter. Links are
// absolute paths on this server ("/edr/collections/NAME/position"), which
// a client resolves against the document's own URL.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_SERVER_HTTP_EDR_EDR_METADATA_H_
#define LOCATOR_SERVER_HTTP_EDR_EDR_METADATA_H_

#include <optional>
#include <string>
#include <string_view>

#include "common/json_writer.h"
#include "locator/geometry.h"
#include "locator/v1/locator.pb.h"

namespace locator {

// Where the EDR API's paths start.
inline constexpr std::string_view kEdrPath = "/edr";

// GET /edr/: the landing page.
std::string EdrLandingPage();
// GET /edr/conformance: the conformance classes implemented.
std::string EdrConformance();

// What a collection shows of its dataset.
struct EdrCollectionFacts {
  // Redacted as GetStats answers it.
  v1::DatasetStats stats;
  // The dataset's bounding box in longitude/latitude; nullopt when it has
  // no CRS or PROJ cannot map it.
  std::optional<BoundingBox> lon_lat_box;
};

// Writes the collection of `facts` (the body of GET /edr/collections/NAME,
// and an element of GET /edr/collections).
void WriteEdrCollection(const EdrCollectionFacts& facts, JsonWriter* json);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_EDR_EDR_METADATA_H_
