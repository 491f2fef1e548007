// EdrApi: OGC API - Environmental Data Retrieval (OGC 19-086r6) on
// locatord's HTTP server, one collection per dataset:
//
//   GET /edr/                              landing page (EdrLandingPage)
//   GET /edr/conformance                   conformance classes
//   GET /edr/collections                   every serving dataset
//   GET /edr/collections/{name}            its extent, queries, CRSs,
//                                          formats and parameter
//   GET /edr/collections/{name}/position?coords=POINT(x y)
//                                       or coords=MULTIPOINT((x y),(x y))
//   GET /edr/collections/{name}/trajectory?coords=LINESTRING(x y, x y, ...)
//                                          [&samples=N]
//
// both queries with [&crs=...][&f=CoverageJSON|GeoJSON]
// [&parameter-name=elevation] (edr_parameters.h). A position answers the
// values LocatorApp::LocateBatch gives (null outside the hull, the domain
// or the CRS's area of use); a trajectory answers LocatorApp::Profile's
// exact breakpoints, or with `samples` (locator's extension) that many
// evenly spaced samples, their positions in the request's CRS. Other query
// parameters (datetime, z) are ignored: the data has neither.
//
// Every call is admitted as the JSON API's (LocatorApp::Admit: the drain,
// the data token, the dataset; the collections list as ListDatasets) and
// runs in its lanes (JsonApi::RunCall): metadata and small positions in the
// cheap one, trajectories and large positions in the expensive one. Errors
// are ApiError's. `coords` is parsed strictly (wkt_coordinates.h); CRS84
// points must be longitudes in [-180, 180] and latitudes in [-90, 90].
//
// Thread-safety: Handle() may be called from any thread.

#ifndef LOCATOR_SERVER_HTTP_EDR_EDR_API_H_
#define LOCATOR_SERVER_HTTP_EDR_EDR_API_H_

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "common/json_writer.h"
#include "server/app/locator_app.h"
#include "server/http/elevation/request_fields.h"
#include "server/http/http_server.h"
#include "server/http/json/json_api.h"

namespace locator {

class EdrApi {
 public:
  // The most points a `coords` may have; the URL's size bounds it first.
  static constexpr size_t kMaxCoordsPoints = 100'000;

  // Serves `app` in `lanes`' lanes; neither is owned, and both must outlive
  // the API's calls.
  EdrApi(LocatorApp* app, JsonApi* lanes) : app_(app), lanes_(lanes) {}

  // Whether `path` is one of this API's.
  static bool Serves(std::string_view path);
  // Answers `request` (a path Serves()) through `reply`.
  void Handle(HttpRequest request, HttpReply reply);

 private:
  // GET /edr/collections/{name}[/{query}]; `query` empty for the
  // collection itself.
  void ServeCollection(const HttpRequest& request, std::string name,
                       std::string query, HttpReply reply);
  // GET /edr/collections.
  void ServeCollections(const HttpRequest& request, HttpReply reply);
  // The admission of `request` (to `dataset` when given): nullopt, once
  // `reply` has the refusal, for a call the application does not admit.
  std::optional<LocatorApp::Admission> Admit(
      const HttpRequest& request, std::optional<std::string_view> dataset,
      HttpReply& reply) const;
  // Admits `request` (for `dataset` when given) and answers, in the cheap
  // lane, the JSON document `write` writes for the admitted call.
  using WriteDocument = std::function<void(
      const LocatorApp&, const LocatorApp::Admission&, JsonWriter*)>;
  void ServeDocument(const HttpRequest& request,
                     std::optional<std::string_view> dataset,
                     WriteDocument write, HttpReply reply);

  LocatorApp* const app_;
  JsonApi* const lanes_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_EDR_EDR_API_H_
