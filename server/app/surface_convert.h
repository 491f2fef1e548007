// Conversions between the locator.v1 surface messages (interpolation,
// Profile, Grid) and the core's plain types, with the checks the requests
// need before the engine sees them.
//
// Thread-safety: free functions.

#ifndef LOCATOR_SERVER_SURFACE_CONVERT_H_
#define LOCATOR_SERVER_SURFACE_CONVERT_H_

#include <cstdint>
#include <vector>

#include "locator/interpolation.h"
#include "locator/profile.h"
#include "locator/raster.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "locator/v1/locator.pb.h"

namespace locator {

// The core's interpolation for the request's enum value (UNSPECIFIED is
// linear). InvalidArgument for a value this server does not know (a newer
// client's).
StatusOr<Interpolation> FromInterpolation(int value);

// The request's polyline, unchecked (the engine checks count and
// finiteness).
std::vector<Point2> FromProfileRequest(const v1::ProfileRequest& request);

// Fills `response` from `profile`.
void ToProfileResponse(const Profile& profile, v1::ProfileResponse* response);

// The raster `request` asks for, with `interpolation` and the nodata value
// (NaN when absent): width x height over the box, or cells of cell_size
// with the box grown east and south to whole cells. InvalidArgument for a
// missing or empty box, neither or both of width x height and cell_size, a
// bad cell size; ResourceExhausted beyond `max_cells` cells.
Status FromGridRequest(const v1::GridRequest& request, uint64_t max_cells,
                       RasterSpec* spec);

// The header of the stream answering `spec` for a dataset with CRS
// `crs_wkt` ("" for none).
void ToGridHeader(const RasterSpec& spec, const std::string& crs_wkt,
                  v1::GridHeader* header);

// The values a grid is rendered and sent in at a time: 1 MiB of doubles.
inline constexpr size_t kGridBlockValues = size_t{1} << 17;
// Rows per block (and per GridResponse message) for `spec`: about
// kGridBlockValues values, at least one row.
uint32_t GridRowsPerBlock(const RasterSpec& spec);

}  // namespace locator

#endif  // LOCATOR_SERVER_SURFACE_CONVERT_H_
