// ReadElevationGrid: one band of any raster GDAL opens (GeoTIFF/COG, VRT,
// AAIGrid, ERDAS, SRTM .hgt, ...), read into an ElevationGrid
// (common/elevation_grid.h) for the terrain simplifier.
//
// Where samples sit. A sample sits at its pixel's centre in GDAL's
// geotransform, origin + (col + 0.5, row + 0.5) pixels, for PixelIsArea and
// PixelIsPoint rasters alike: GDAL's drivers already express a point-sampled
// raster's georeferencing as the pixels' outer edges (a PixelIsPoint
// GeoTIFF's tie point, an ASCII grid's xllcenter, an SRTM tile's integer
// degrees are pixel centres in GDAL's geotransform), and GDAL's data model
// says AREA_OR_POINT does not change how the geotransform is read. So a
// point sample lands exactly on the coordinates its file gives it. A raster
// without a geotransform is served in GDAL's pixel/line coordinates.
//
// Values. The band's scale and offset are applied; every pixel the band's
// mask marks invalid (its nodata value, a per-dataset mask, an alpha band)
// and every NaN is nodata (NaN in the grid). Values are stored as float, as
// ElevationGrid holds them.
//
// Memory. The grid is allocated once, after the size check; rows are read a
// strip of blocks at a time (about 16 MB) and GDAL's block cache is dropped
// after each strip, so the read peaks at the float grid plus one strip.
//
// Errors name the source and, where one is to blame, the band and pixel:
// NotFound for a missing file; InvalidArgument for a source GDAL cannot open
// as a raster, a band out of range, a complex or unknown data type, a
// rotated or degenerate geotransform, an infinite value or one beyond a
// float's range, no valid pixel, or an unknown a_srs; ResourceExhausted,
// before anything is read, when the raster has more pixels than
// DatasetLimits::max_points; IOError when GDAL fails reading.
//
// Thread-safety: may be called from several threads at once (GDAL handles
// are not shared; GDAL's error state is per thread).

#ifndef LOCATOR_COMMON_GIS_RASTER_GRID_H_
#define LOCATOR_COMMON_GIS_RASTER_GRID_H_

#include <string>
#include <vector>

#include "common/elevation_grid.h"
#include "common/gis/raster_dataset_spec.h"
#include "locator/dataset.h"
#include "locator/status.h"

namespace locator::gis {

// Reads the band `spec` names (RasterDatasetSpec) into *out; out->source is
// `spec`. *files (optional) gets the files GDAL read (the raster, its
// side-cars, a VRT's sources).
Status ReadElevationGrid(const std::string& spec, const DatasetLimits& limits,
                         ElevationGrid* out,
                         std::vector<std::string>* files = nullptr);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_RASTER_GRID_H_
