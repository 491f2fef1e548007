// GIS fixtures made at test time: GeoJSON text written to a scratch
// directory and converted with the real ogr2ogr, so that no binary file is
// kept in the repository.
//
// Thread-safety: free functions; each test uses its own directory.

#ifndef LOCATOR_TESTS_COMMON_GIS_GIS_FIXTURES_H_
#define LOCATOR_TESTS_COMMON_GIS_GIS_FIXTURES_H_

#include <string>
#include <vector>

#include "locator/geometry.h"

namespace locator::gis::testing {

struct PointZ {
  double x, y, z;
};

// Writes `text` to `path`.
void WriteFile(const std::string& path, const std::string& text);

// A GeoJSON FeatureCollection of PointZ features, each with the attribute
// "height" equal to its z (ogr2ogr can drop the Z and keep the field).
std::string PointsGeoJson(const std::vector<PointZ>& points);

// A GeoJSON FeatureCollection of features with the given geometry objects
// (GeoJSON text each, e.g. {"type":"LineString","coordinates":[...]}).
std::string GeometriesGeoJson(const std::vector<std::string>& geometries);

// Runs ogr2ogr with `args`; a failed run fails the test with its stderr.
void Ogr2Ogr(const std::vector<std::string>& args);

// Runs `program` (OGR2OGR_PATH or CS2CS_PATH) and returns its stdout; a
// failed run fails the test with its stderr.
std::string RunTool(const std::string& program,
                    const std::vector<std::string>& args);

// The UtmHill(n) points as the GeoPackage DIR/hill.gpkg (layer "hill",
// EPSG:32633, PointZ with z also in the attribute "height"), made by
// ogr2ogr; returns its path.
std::string UtmHillGeoPackage(int n, const std::string& dir);

// Overwrites the header of the middle one of the data pages of the
// GeoPackage `gpkg`'s feature tables (SQLite table leaf pages holding
// GeoPackage geometry blobs), so that SQLite finds the file malformed part
// way through the layer; returns that page's number (1-based). The same
// file always gets the same page.
int CorruptMiddleDataPage(const std::string& gpkg);

// The WKT2 of the CRS EPSG:`code`, as GDAL writes it.
std::string EpsgWkt2(int code);

// `points` transformed by the real cs2cs from `from` to `to` (both lon/lat
// or easting/northing CRSs; cs2cs takes and gives EPSG:4326 as lat, lon, and
// this function swaps them), through a file in `dir`.
std::vector<Point2> Cs2cs(const std::vector<Point2>& points,
                          const std::string& from, const std::string& to,
                          const std::string& dir);

// A hill of `n` x `n` points around (500000, 5500000) in UTM 33N metres:
// z = 400 + 300 * exp(-r^2 / 2 sigma^2), sigma 1.5 km, spacing 400 m.
std::vector<PointZ> UtmHill(int n);

}  // namespace locator::gis::testing

#endif  // LOCATOR_TESTS_COMMON_GIS_GIS_FIXTURES_H_
