// Terrain tiles of a dataset for web maps: a TileAddress rendered as a
// terrain PNG (TerrainEncoding), and the TileJSON 3.0.0 document that
// tells a map where the tiles are and which zooms are worth asking for.
//
// A pixel holds the TIN's linear value at its centre: the centres, in
// EPSG:3857, are transformed with PROJ to the dataset's CRS (the calling
// thread's CrsTransformer) and rendered by the engine's scan-coherent walk
// (Engine::RenderPoints), never by one locate per pixel. A pixel outside
// the hull or the domain, or outside the area of use of the dataset's CRS,
// is transparent (alpha 0); every other pixel is opaque.
//
// A dataset without a CRS gets no tiles (FAILED_PRECONDITION): its
// coordinates have no place on the map, and guessing one would draw the
// terrain somewhere it is not. Nor does one without values.
//
// Thread-safety: free functions over a thread-safe Engine; any thread.

#ifndef LOCATOR_SERVER_TILES_TERRAIN_TILE_H_
#define LOCATOR_SERVER_TILES_TERRAIN_TILE_H_

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "locator/engine.h"
#include "locator/status.h"
#include "locator/status_or.h"
#include "server/tiles/terrain_encoding.h"
#include "server/tiles/tile_address.h"

namespace locator {

// The CRS tiles are requested in.
inline constexpr std::string_view kTileCrs = "EPSG:3857";

// OK if dataset `name` served by `engine` can be tiled: it has a CRS and
// values; FAILED_PRECONDITION saying which it lacks otherwise (naming
// `tile_crs`, the CRS of the tiles asked for).
Status CheckTileSource(const Engine& engine, std::string_view name,
                       std::string_view tile_crs = kTileCrs);

// The box of `engine`'s dataset mapped to `crs`: the bounds of its outline
// sampled 16 times a side, since a box of a projected CRS bends in another.
// InvalidArgument if PROJ cannot map a sample.
StatusOr<BoundingBox> DatasetBoxIn(const Engine& engine, std::string_view crs);

// How far a pixel centre given by TilePixelsInDatasetCrs may lie from its
// exact transform, in x and in y, as a fraction of the tile's pixel width
// in the dataset's CRS (along its top or bottom row, the shorter): 1/1000 of a
// pixel. A pixel's value is then off the value at its exact centre by at most
// the facet's slope times that (docs/http-api.md gives the figures per zoom and
// encoding).
inline constexpr double kTilePositionTolerance = 1e-3;

// The pixel centres of `tile` in the dataset's CRS, row by row from the
// north-west (TileAddress::Raster()'s cell centres transformed with
// CrsTransformer::ToDatasetWhereDefined: NaN where undefined). A tile
// inside the area of use of the dataset's CRS is transformed as GDAL's
// approximate transformer does, in two dimensions: exactly at a block's
// corners and at the middles of its sides and of itself, bilinearly inside
// where that is within kTilePositionTolerance (of a pixel of the tile's
// shorter edge row), else in quarters; a tile reaching outside, exactly
// pixel by pixel.
// Errors are CrsTransformer::ForThread's.
Status TilePixelsInDatasetCrs(const Engine& engine, const TileAddress& tile,
                              std::vector<Point2>* pixels);

// The PNG of `tile` of `engine`'s dataset in `encoding`, after
// CheckTileSource (`name` is the dataset's, for its errors).
StatusOr<std::string> RenderTerrainTile(const Engine& engine,
                                        std::string_view name,
                                        const TileAddress& tile,
                                        TerrainEncoding encoding);

// The TileJSON 3.0.0 document of dataset `name` (after CheckTileSource),
// with `tiles_url` (a URL template with {z}, {x} and {y}) as its one tile
// URL: bounds and centre in lon/lat (EPSG:4326) from the dataset's box,
// minzoom the deepest zoom at which one tile still spans the box, maxzoom
// the zoom whose pixels are as wide as the mean spacing of the vertices,
// the encoding, and "scheme": "xyz". InvalidArgument if PROJ cannot map
// the box to lon/lat.
StatusOr<std::string> TileJson(const Engine& engine, std::string_view name,
                               std::string_view tiles_url,
                               TerrainEncoding encoding);

// The entity tag of the tiles (and TileJSON) of a dataset served as
// `generation`, drawn as `variant` (the encoding's name, or the shading's
// parameters), quoted as HTTP wants it: the generation changes with every
// reload, and a random number drawn once per process tells this run's
// generation 1 from the last run's, whose data may differ.
std::string TileETag(uint64_t generation, std::string_view variant);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_TERRAIN_TILE_H_
