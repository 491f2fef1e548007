#include "locator/interpolation.h"

namespace locator {

std::string_view InterpolationName(Interpolation how) {
  switch (how) {
    case Interpolation::kLinear:
      return "linear";
    case Interpolation::kNaturalNeighbor:
      return "natural-neighbor";
    case Interpolation::kNearest:
      return "nearest";
  }
  return "unknown";
}

}  // namespace locator
