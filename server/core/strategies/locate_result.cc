#include "locator/locate_result.h"

namespace locator {

std::string_view LocationTypeName(LocationType type) {
  switch (type) {
    case LocationType::kFace:
      return "FACE";
    case LocationType::kEdge:
      return "EDGE";
    case LocationType::kVertex:
      return "VERTEX";
    case LocationType::kOutsideConvexHull:
      return "OUTSIDE_CONVEX_HULL";
    case LocationType::kOutsideDomain:
      return "OUTSIDE_DOMAIN";
  }
  return "UNKNOWN";
}

}  // namespace locator
