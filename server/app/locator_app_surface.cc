// LocatorApp's surface methods: profiles and grids.

#include <string>
#include <utility>
#include <vector>

#include "common/status_macros.h"
#include "server/app/locator_app.h"
#include "server/app/query_options.h"
#include "server/app/request_crs.h"
#include "server/app/surface_convert.h"

namespace locator {
namespace {

// What a Profile request makes the server allocate for, checked before
// anything is: its samples against --max-profile-samples, and its line's
// vertices against --max-profile-crossings (the trace enters at least one
// triangle per vertex, so a longer line could never finish).
Status CheckProfileSize(const v1::ProfileRequest& request,
                        uint64_t max_crossings, uint32_t max_samples) {
  if (request.samples() > max_samples) {
    return Status::ResourceExhausted(
        "a profile of " + std::to_string(request.samples()) +
        " samples exceeds this server's limit of " +
        std::to_string(max_samples) +
        " samples per request (locatord --max-profile-samples)");
  }
  if (static_cast<uint64_t>(request.vertices_size()) > max_crossings) {
    return Status::ResourceExhausted(
        "a profile line of " + std::to_string(request.vertices_size()) +
        " vertices enters more triangles than this server's limit of " +
        std::to_string(max_crossings) +
        " per request (locatord --max-profile-crossings)");
  }
  return Status::OK();
}

}  // namespace

Status LocatorApp::Profile(const Admission& call,
                           const v1::ProfileRequest& request,
                           v1::ProfileResponse* response) const {
  RETURN_IF_ERROR(
      CheckProfileSize(request, max_profile_crossings_, max_profile_samples_));
  ASSIGN_OR_RETURN(const QueryOptions query, QueryOptionsOf(request));
  ProfileOptions options;
  options.samples = request.samples();
  options.max_faces = max_profile_crossings_;
  options.interpolation = query.interpolation;
  std::vector<Point2> line = FromProfileRequest(request);
  RETURN_IF_ERROR(PointsInDatasetCrs(*call.engine, query.crs, line));
  ::locator::Profile profile;
  RETURN_IF_ERROR(call.engine->TraceProfile(line, options, &profile));
  ToProfileResponse(profile, response);
  return Status::OK();
}

StatusOr<RasterSpec> LocatorApp::GridSpec(
    const Admission& call, const v1::GridRequest& request) const {
  RasterSpec spec;
  RETURN_IF_ERROR(FromGridRequest(request, max_grid_cells_, &spec));
  RETURN_IF_ERROR(call.engine->CheckInterpolation(spec.interpolation));
  return spec;
}

}  // namespace locator
