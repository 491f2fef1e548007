// CircumdiskBound: a disk that surely contains a triangle's closed
// circumdisk, computed in double with a bound on every rounding error, so
// that a tile certifies a triangle only when no point it has not seen can
// lie on or in the circle.
//
// Thread-safety: a pure function.

#ifndef LOCATOR_CORE_TILING_CIRCUMDISK_H_
#define LOCATOR_CORE_TILING_CIRCUMDISK_H_

#include "locator/geometry.h"

namespace locator {

struct Disk {
  Point2 center;
  double radius = 0;
};

// A disk containing the closed circumdisk of the counter-clockwise triangle
// a, b, c: the computed circumcentre, with a radius grown by the proven
// bound on the centre's error (forward error analysis of the translated,
// power-of-two scaled formula). False when no finite bound exists: a
// nearly flat triangle, or coordinates whose squares overflow.
bool CircumdiskBound(const Point2& a, const Point2& b, const Point2& c,
                     Disk* out);

}  // namespace locator

#endif  // LOCATOR_CORE_TILING_CIRCUMDISK_H_
