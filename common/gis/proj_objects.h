// PROJ handles for the CRS code of this library: owning pointers, the
// calling thread's PROJ context, and CRS creation with precise errors.
//
// Thread-safety: PROJ objects and contexts are not thread-safe. Every
// function here uses the calling thread's own context (created on first
// use, destroyed when the thread exits), so a PjPtr must be used and
// destroyed on the thread that created it.

#ifndef LOCATOR_COMMON_GIS_PROJ_OBJECTS_H_
#define LOCATOR_COMMON_GIS_PROJ_OBJECTS_H_

#include <proj.h>

#include <memory>
#include <string>
#include <string_view>

#include "common/status.h"

namespace locator::gis {

struct PjDeleter {
  void operator()(PJ* pj) const { proj_destroy(pj); }
};
using PjPtr = std::unique_ptr<PJ, PjDeleter>;

// The calling thread's PROJ context; never null.
PJ_CONTEXT* ThreadProjContext();

// PROJ's message for the last error on the calling thread's context.
std::string LastProjError();

// `crs` for a message, as QuotedInput() shows client text: in quotes, cut
// short when long (a WKT).
std::string QuotedCrs(std::string_view crs);

// Creates the CRS `crs` names ("EPSG:32633", WKT or a PROJ string; "+proj="
// strings need no "+type=crs"). InvalidArgument "unknown CRS '...'" when
// PROJ cannot make a CRS of it.
Status CreateCrs(std::string_view crs, PjPtr* out);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_PROJ_OBJECTS_H_
