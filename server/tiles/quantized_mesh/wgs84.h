// The WGS84 ellipsoid as quantized-mesh's header needs it: positions in
// Earth-centred, Earth-fixed coordinates (ECEF, metres), a sphere holding
// a tile's vertices, and the horizon occlusion point Cesium's
// EllipsoidalOccluder culls a tile with.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_SERVER_TILES_QUANTIZED_MESH_WGS84_H_
#define LOCATOR_SERVER_TILES_QUANTIZED_MESH_WGS84_H_

#include <array>
#include <span>

namespace locator {

using Vec3 = std::array<double, 3>;

// WGS84's semi-axes in metres (x and y equatorial, z polar).
inline constexpr Vec3 kWgs84Radii = {6378137.0, 6378137.0, 6356752.3142451793};

// The ECEF position of longitude `lon` and latitude `lat` (degrees) at
// `height` metres above the ellipsoid.
Vec3 GeodeticToEcef(double lon, double lat, double height);

struct Sphere {
  Vec3 centre = {0, 0, 0};
  double radius = 0;
};

// A sphere holding every one of `points` (the centre of their box and the
// distance to the farthest); radius 0 at the origin for none.
Sphere BoundingSphere(std::span<const Vec3> points);

// Cesium's horizon occlusion point of `points` seen in the direction of
// `direction` (EllipsoidalOccluder.computeHorizonCullingPoint), in the
// ellipsoid-scaled frame (ECEF divided by kWgs84Radii): while it is below
// a viewer's horizon, so are all the points. Points below the ellipsoid
// count as on it, as Cesium's own method does. Where the points spread so
// far round the Earth that no such point exists, a point 1000 radii out
// along `direction`, which only hides the tile from the far side.
Vec3 HorizonOcclusionPoint(std::span<const Vec3> points, const Vec3& direction);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_QUANTIZED_MESH_WGS84_H_
