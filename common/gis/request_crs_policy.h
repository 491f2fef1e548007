// The policy for a CRS a request names (LocateRequest.crs and its kin, a
// Reload's a_srs): what PROJ may do for it and what it may cost.
//
//   - At most kMaxRequestCrsBytes bytes, refused before PROJ parses it.
//   - Made in the thread's request context (ThreadRequestProjContext()):
//     PROJ reads only its own data files and the grids of the operator's
//     datasets, never a device or a FIFO, never the network.
//   - Every grid it names is looked up when it is made, so that a grid PROJ
//     may not open is refused by name (InvalidArgument), not silently left
//     out of the transformation PROJ picks.
//   - Verdicts are shared by all threads (CrsVerdicts): a CRS that failed
//     fails again without being made.
// With no file to wait for, making a CRS costs PROJ's parsing and database
// look-ups only, bounded by the length limit.
//
// Thread-safety: free functions; may run on any thread.

#ifndef LOCATOR_COMMON_GIS_REQUEST_CRS_POLICY_H_
#define LOCATOR_COMMON_GIS_REQUEST_CRS_POLICY_H_

#include <cstddef>
#include <string>
#include <string_view>

#include "common/gis/proj_objects.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis {

// A WKT2 of a compound CRS with its bound transformations is a few
// kilobytes, its PROJJSON about twice that.
inline constexpr size_t kMaxRequestCrsBytes = 16 * 1024;

// InvalidArgument naming the limit when `crs` is longer than
// kMaxRequestCrsBytes.
Status CheckRequestCrsLength(std::string_view crs);

// Creates the CRS `crs` names in the calling thread's request context, as
// CreateCrs() does; InvalidArgument too when it is too long or names a file
// the request context does not let PROJ open (a grid, an +init file).
StatusOr<PjPtr> CreateRequestCrs(std::string_view crs);

// Whether a request may name `crs`: CreateRequestCrs()'s status, decided
// once per CRS text for the whole process.
Status CheckRequestCrs(const std::string& crs);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_REQUEST_CRS_POLICY_H_
