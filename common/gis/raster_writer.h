// RasterWriter: writes a single-band Float64 raster to a GeoTIFF file
// through GDAL, a run of rows at a time, so that a raster streamed from a
// server is never held whole in memory.
//
// The file is north-up: row 0 is the northern edge, and the geotransform is
// (box.min_x, cell_width, 0, box.max_y, 0, -cell_height). It carries the
// CRS (when the shape has one), the nodata value and tiles:
//   GTiff  written in place, tiled 256 x 256 (TILED=YES, BLOCKXSIZE=256,
//          BLOCKYSIZE=256 unless the creation options say otherwise);
//   COG    GDAL's COG driver can only copy a finished dataset, so the rows
//          go to a tiled temporary GTiff next to the output
//          ("<path>.<pid>.tmp.tif"), which Close() copies to the
//          Cloud-Optimized GeoTIFF and removes.
// Creation options (NAME=VALUE, as gdal_translate -co) go to the output's
// driver and are checked against its list first.
//
// Errors are Status values naming the file and carrying GDAL's message:
// InvalidArgument for a bad shape, an unknown format or a bad creation
// option; IOError for a file GDAL cannot create or write.
//
// Owns the open GDAL dataset and the files it writes until Close(). A writer
// destroyed before a successful Close() closes its dataset and removes its
// files, so that a failed run leaves no partial raster behind.
//
// Thread-safety: none; one thread drives a writer (GDAL's error state is
// per thread). Different writers may run on different threads.

#ifndef LOCATOR_COMMON_GIS_RASTER_WRITER_H_
#define LOCATOR_COMMON_GIS_RASTER_WRITER_H_

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"

class GDALDataset;

namespace locator::gis {

// The raster's size and georeferencing, as plain values.
struct RasterShape {
  uint32_t width = 0;   // columns, 1 .. INT_MAX (GDAL's limit)
  uint32_t height = 0;  // rows, 1 .. INT_MAX
  // The outer edges; the geotransform's origin is (min_x, max_y).
  BoundingBox box;
  // Cell width and height, both positive and finite.
  double cell_width = 0;
  double cell_height = 0;
  // The value of cells without one (NaN allowed).
  double nodata = 0;
  // The CRS as WKT (WKT1 or WKT2); empty: none.
  std::string crs_wkt;
};

// What file to write and how.
struct RasterFormat {
  // "GTiff" or "COG" (GDAL's driver names).
  std::string driver = "";
  // NAME=VALUE creation options of that driver.
  std::vector<std::string> creation_options = {};
};

// "COG" when this GDAL has the COG driver (GDAL >= 3.1), else "GTiff".
std::string DefaultRasterDriver();

// Checks `format` as RasterWriter::Open() does (GTiff or COG, NAME=VALUE
// creation options that the driver accepts), without creating a file.
Status CheckRasterFormat(const RasterFormat& format);

class RasterWriter {
 public:
  // Creates `path` for a raster of `shape` in `format`. InvalidArgument for
  // a bad shape (no rows or columns, more than GDAL takes, a cell size that
  // is not positive and finite, an origin that is not finite), a driver other
  // than GTiff or COG, a creation option that is not NAME=VALUE or that the
  // driver rejects, or a WKT GDAL cannot read; IOError when GDAL cannot create
  // the file.
  static Status Open(const std::string& path, const RasterShape& shape,
                     const RasterFormat& format,
                     std::unique_ptr<RasterWriter>* writer);

  ~RasterWriter();
  RasterWriter(const RasterWriter&) = delete;
  RasterWriter& operator=(const RasterWriter&) = delete;

  // Writes rows first_row .. first_row + rows - 1: `values` holds rows x
  // width values, row by row, west to east. Rows may come in any order.
  // InvalidArgument when they fall outside the raster or `values` has
  // another size; IOError when GDAL fails; FailedPrecondition after
  // Close().
  Status WriteRows(uint32_t first_row, uint32_t rows,
                   std::span<const double> values);

  // Flushes and closes the file (for COG: copies the temporary GTiff to
  // `path` and removes it). IOError with GDAL's message on failure; the
  // files are then removed. FailedPrecondition when called again.
  Status Close();

  const std::string& path() const { return path_; }

 private:
  RasterWriter(std::string path, uint32_t width, uint32_t height);

  // Closes the open dataset (if any) and removes every file written.
  void Discard();

  const std::string path_;
  const uint32_t width_;
  const uint32_t height_;
  // COG: Close() copies the rows to `path_` with these creation options.
  bool copy_to_cog_ = false;
  std::vector<std::string> cog_options_;
  // Where the rows go: `path_` itself, or the temporary GTiff for COG.
  std::string rows_path_;
  GDALDataset* rows_ = nullptr;  // owned; null once closed
  bool closed_ = false;
};

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_RASTER_WRITER_H_
