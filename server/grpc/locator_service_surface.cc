// LocatorService's surface methods: profiles and grids.

#include <string>
#include <utility>
#include <vector>

#include "server/grpc/locator_service.h"
#include "server/grpc/status_mapping.h"
#include "server/grpc/surface_convert.h"
#include "server/serving/request_crs.h"

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

grpc::Status LocatorService::RunProfile(const Admission& call,
                                        const v1::ProfileRequest& request,
                                        v1::ProfileResponse* response) const {
  if (Status status = CheckProfileSize(request, max_profile_crossings_,
                                       max_profile_samples_);
      !status.ok()) {
    return ToGrpcStatus(status);
  }
  ProfileOptions options;
  options.samples = request.samples();
  options.max_faces = max_profile_crossings_;
  if (Status status =
          FromInterpolation(request.interpolation(), &options.interpolation);
      !status.ok()) {
    return ToGrpcStatus(status);
  }
  std::vector<Point2> line = FromProfileRequest(request);
  if (Status status = LineInDatasetCrs(*call.engine, request.crs(), &line);
      !status.ok()) {
    return ToGrpcStatus(status);
  }
  ::locator::Profile profile;
  const Status status = call.engine->TraceProfile(line, options, &profile);
  if (status.ok()) ToProfileResponse(profile, response);
  return ToGrpcStatus(status);
}

grpc::Status LocatorService::GridSpec(const Admission& call,
                                      const v1::GridRequest& request,
                                      RasterSpec* spec) const {
  Status status = FromGridRequest(request, max_grid_cells_, spec);
  if (status.ok()) {
    status = call.engine->CheckInterpolation(spec->interpolation);
  }
  return ToGrpcStatus(status);
}

}  // namespace locator
