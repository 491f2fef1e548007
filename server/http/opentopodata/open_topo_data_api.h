// OpenTopoDataApi: Open Topo Data's elevation API
// (https://www.opentopodata.org/api/, itself Google Elevation's shape) on
// locatord's HTTP server, over the application's datasets:
//
//   GET  /opentopodata/v1/{dataset}?locations=lat,lng|lat,lng
//            [&interpolation=bilinear|linear|nearest|natural]
//            [&nodata_value=null|nan|INTEGER][&samples=N]
//   GET  /opentopodata/v1/{dataset}?path=lat,lng|lat,lng&samples=N
//   POST /opentopodata/v1/{dataset}   the same fields as a JSON object or a
//                                      form (see RequestFields)
//
//   200 {"results": [{"elevation": 815.0, "location": {"lat": ...,
//         "lng": ...}, "dataset": "name"}, ...], "status": "OK"}
//
// See OpenTopoDataQuery for the fields. The API is mounted under
// /opentopodata/ because Open Topo Data's /v1/{dataset} would collide with
// locatord's own /v1/datasets: an Open Topo Data client is pointed at
// http://HOST:PORT/opentopodata as its base URL. Points are latitude and
// longitude (EPSG:4326), located through the application's request CRS, so
// a dataset in UTM answers them; a dataset without a CRS cannot. Without
// `samples` the values are LocatorApp::LocateBatch's, with null (or
// nodata_value) outside the hull, the domain or the CRS's area of use; with
// `samples`, the points are a path and each result is one of
// LocatorApp::Profile's evenly spaced samples (straight in the dataset's
// CRS), its location mapped back to latitude/longitude.
//
// `{dataset}` may name several datasets, comma-separated, as Open Topo
// Data's multi-dataset requests do (at most kMaxDatasets): each point takes
// its value from the first of them that has one there, and its result
// names that dataset (the last one when none has); a path is sampled on
// the first. Every call is admitted as the JSON API's (LocatorApp::Admit: the
// drain, the data token, each dataset) and runs in its lanes
// (JsonApi::RunCall), the expensive one for paths and large batches. Errors
// have Open Topo Data's shape and statuses (OpenTopoDataError).
//
// Thread-safety: Handle() may be called from any thread.

#ifndef LOCATOR_SERVER_HTTP_OPENTOPODATA_OPEN_TOPO_DATA_API_H_
#define LOCATOR_SERVER_HTTP_OPENTOPODATA_OPEN_TOPO_DATA_API_H_

#include <cstddef>
#include <string_view>

#include "server/app/locator_app.h"
#include "server/http/http_server.h"
#include "server/http/json/json_api.h"

namespace locator {

class OpenTopoDataApi {
 public:
  // Where the API's paths start.
  static constexpr std::string_view kPathPrefix = "/opentopodata";
  // The most datasets one request may name.
  static constexpr size_t kMaxDatasets = 8;

  // Serves `app` in `lanes`' lanes; neither is owned, and both must outlive
  // the API's calls.
  OpenTopoDataApi(LocatorApp* app, JsonApi* lanes) : app_(app), lanes_(lanes) {}

  // Answers `request` (a path under kPathPrefix) through `reply`.
  void Handle(HttpRequest request, HttpReply reply);

 private:
  LocatorApp* const app_;
  JsonApi* const lanes_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_OPENTOPODATA_OPEN_TOPO_DATA_API_H_
