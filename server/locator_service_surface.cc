// LocatorService's surface methods: profiles and grids.

#include <utility>
#include <vector>

#include "server/locator_service.h"
#include "server/request_crs.h"
#include "server/status_mapping.h"
#include "server/surface_convert.h"

namespace locator {

grpc::Status LocatorService::RunProfile(const Admission& call,
                                        const v1::ProfileRequest& request,
                                        v1::ProfileResponse* response) const {
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
