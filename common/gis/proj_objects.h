// PROJ handles for the CRS code of this library: owning pointers, the
// calling thread's PROJ contexts, and CRS creation with precise errors.
//
// Each thread has two contexts (proj_file_guard.h): one for the operator's
// own CRSs (a dataset's), which may read any regular file PROJ's normal
// look-up finds, and one for CRSs a request names, which reads only PROJ's
// own data files and the grids the operator's CRSs named.
//
// Thread-safety: PROJ objects and contexts are not thread-safe. A context
// here belongs to the calling thread (created on first use, destroyed when
// the thread exits), so a PjPtr must be used and destroyed on the thread
// that created it.

#ifndef LOCATOR_COMMON_GIS_PROJ_OBJECTS_H_
#define LOCATOR_COMMON_GIS_PROJ_OBJECTS_H_

#include <proj.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/gis/proj_file_guard.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis {

struct PjDeleter {
  void operator()(PJ* pj) const { proj_destroy(pj); }
};
using PjPtr = std::unique_ptr<PJ, PjDeleter>;

// The calling thread's context for the operator's own CRSs
// (ProjFileScope::kAnyRegularFile).
GuardedProjContext& ThreadProjContext();

// The calling thread's context for CRSs a request names
// (ProjFileScope::kDataDirectories).
GuardedProjContext& ThreadRequestProjContext();

// PROJ's message for the last error on `ctx`.
std::string LastProjError(PJ_CONTEXT* ctx);

// `crs` for a message, as QuotedInput() shows client text: in quotes, cut
// short when long (a WKT).
std::string QuotedCrs(std::string_view crs);

// Creates the CRS `crs` names ("EPSG:32633", WKT, PROJJSON or a PROJ string;
// "+proj=" strings need no "+type=crs") in `ctx`. InvalidArgument "unknown
// CRS '...'" when PROJ cannot make a CRS of it, or naming the file it
// needed and `ctx` did not let it open (an +init file).
StatusOr<PjPtr> CreateCrs(GuardedProjContext& ctx, std::string_view crs);

// A grid a CRS names: the name as the CRS gives it, and the file PROJ found
// for it ("" if none).
struct GridUse {
  std::string name;
  std::string file;
};

// The grids `crs` names (those of a bound CRS's transformation, of a
// deriving conversion, of every part of a compound CRS), looked up in `ctx`.
std::vector<GridUse> GridsOf(GuardedProjContext& ctx, const PJ* crs);

// InvalidArgument naming `crs` and the file `ctx` refused since its last
// TakeRefusal(), or OK if none was.
Status RefusedFileError(GuardedProjContext& ctx, std::string_view crs);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_PROJ_OBJECTS_H_
