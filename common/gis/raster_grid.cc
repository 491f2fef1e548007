#include "common/gis/raster_grid.h"

#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <memory>
#include <utility>

#include "common/gis/gdal_support.h"
#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator::gis {
namespace {

// Bytes of values read per strip (plus a byte per pixel of mask).
constexpr size_t kStripBytes = 16 << 20;
// Extensions whose files are often x,y,z text rather than rasters.
constexpr std::array<std::string_view, 1> kAmbiguousExtensions = {".asc"};

struct GdalCloser {
  void operator()(GDALDataset* dataset) const { GDALClose(dataset); }
};

// Reads the rows of `band` into grid->values, a strip of blocks at a time,
// as described in raster_grid.h; counts the valid pixels.
class BandReader {
 public:
  BandReader(const std::string& source, int band_number, GDALRasterBand& band)
      : source_(source), number_(band_number), band_(band) {}

  Status Read(ElevationGrid* grid, uint64_t* valid) {
    const uint32_t width = grid->width;
    const uint32_t height = grid->height;
    int block_x = 0, block_y = 0;
    band_.GetBlockSize(&block_x, &block_y);
    // Whole blocks per strip, as many as ~kStripBytes holds (at least one).
    const size_t row_bytes = size_t{width} * (sizeof(double) + 1);
    const uint32_t block_rows = static_cast<uint32_t>(std::max(block_y, 1));
    const uint32_t strip_rows = std::max<uint32_t>(
        block_rows,
        static_cast<uint32_t>(kStripBytes / row_bytes / block_rows) *
            block_rows);
    const int mask_flags = band_.GetMaskFlags();
    GDALRasterBand* mask =
        mask_flags == GMF_ALL_VALID ? nullptr : band_.GetMaskBand();
    int has_scale = 0, has_offset = 0;
    const double scale = band_.GetScale(&has_scale);
    const double offset = band_.GetOffset(&has_offset);
    const double a = has_scale ? scale : 1;
    const double b = has_offset ? offset : 0;

    std::vector<double> values(size_t{width} * std::min(strip_rows, height));
    std::vector<GByte> valid_mask(mask == nullptr ? 0 : values.size());
    *valid = 0;
    for (uint32_t row = 0; row < height; row += strip_rows) {
      const uint32_t rows = std::min(strip_rows, height - row);
      RETURN_IF_ERROR(
          ReadRows(band_, row, width, rows, GDT_Float64, values.data()));
      if (mask != nullptr) {
        RETURN_IF_ERROR(
            ReadRows(*mask, row, width, rows, GDT_Byte, valid_mask.data()));
      }
      for (size_t i = 0; i < size_t{width} * rows; ++i) {
        float* out = &grid->values[size_t{row} * width + i];
        const double raw = values[i];
        if (std::isnan(raw) || (mask != nullptr && valid_mask[i] == 0)) {
          *out = NAN;
          continue;
        }
        const double value = raw * a + b;
        if (!std::isfinite(value) || std::abs(value) > FLT_MAX) {
          return BadPixel(static_cast<uint32_t>(i % width),
                          row + static_cast<uint32_t>(i / width), raw, value);
        }
        *out = static_cast<float>(value);
        ++*valid;
      }
      // Read-only blocks are only dropped: the cache stays at one strip.
      band_.FlushCache(false);
      if (mask != nullptr) mask->FlushCache(false);
    }
    return Status::OK();
  }

 private:
  Status ReadRows(GDALRasterBand& band, uint32_t row, uint32_t width,
                  uint32_t rows, GDALDataType type, void* out) const {
    CPLErrorReset();
    if (band.RasterIO(GF_Read, 0, static_cast<int>(row),
                      static_cast<int>(width), static_cast<int>(rows), out,
                      static_cast<int>(width), static_cast<int>(rows), type, 0,
                      0, nullptr) != CE_None) {
      return Status::IOError(source_ + ": band " + std::to_string(number_) +
                             ": cannot read rows " + std::to_string(row) +
                             " to " + std::to_string(row + rows - 1) + ": " +
                             LastGdalError());
    }
    return Status::OK();
  }

  Status BadPixel(uint32_t col, uint32_t row, double raw, double value) const {
    const std::string where = source_ + ": band " + std::to_string(number_) +
                              " pixel (" + std::to_string(col) + ", " +
                              std::to_string(row) + ")";
    if (std::isinf(raw)) {
      return Status::InvalidArgument(
          where + " is " + NumberText(raw) +
          ", which is no elevation; if it marks nodata, declare it: "
          "gdal_edit.py -a_nodata " +
          NumberText(raw) + " FILE");
    }
    return Status::InvalidArgument(where + " is " + NumberText(value) +
                                   " after scale and offset, beyond a "
                                   "float's range");
  }

  const std::string& source_;
  const int number_;
  GDALRasterBand& band_;
};

Status CheckGeoTransform(const std::string& source, const double gt[6]) {
  if (gt[2] != 0 || gt[4] != 0) {
    return Status::InvalidArgument(
        source + " has a rotated geotransform (row rotation " +
        NumberText(gt[2]) + ", column rotation " + NumberText(gt[4]) +
        "); locator serves north-up grids: warp it first, e.g. "
        "gdalwarp " +
        source + " north_up.tif");
  }
  for (const int i : {0, 1, 3, 5}) {
    if (!std::isfinite(gt[i]) || ((i == 1 || i == 5) && gt[i] == 0)) {
      return Status::InvalidArgument(
          source + " has a degenerate geotransform (" + NumberText(gt[0]) +
          ", " + NumberText(gt[1]) + ", " + NumberText(gt[2]) + ", " +
          NumberText(gt[3]) + ", " + NumberText(gt[4]) + ", " +
          NumberText(gt[5]) +
          "): the origin must be finite and the pixel size finite and "
          "not zero");
    }
  }
  return Status::OK();
}

Status OpenRaster(const RasterDatasetSpec& spec,
                  std::unique_ptr<GDALDataset, GdalCloser>* out) {
  RegisterGdalDrivers();
  VSIStatBufL stat;
  if (VSIStatL(spec.source.c_str(), &stat) != 0) {
    return Status::NotFound(spec.source + ": no such file or directory");
  }
  if (!spec.driver.empty() &&
      GDALGetDriverByName(spec.driver.c_str()) == nullptr) {
    return Status::InvalidArgument(spec.source + ": no GDAL driver " +
                                   QuotedInput(spec.driver) + " (driver=)");
  }
  const char* const only_driver[] = {spec.driver.c_str(), nullptr};
  CPLErrorReset();
  std::unique_ptr<GDALDataset, GdalCloser> dataset(GDALDataset::Open(
      spec.source.c_str(),
      GDAL_OF_RASTER | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR,
      spec.driver.empty() ? nullptr : only_driver));
  if (dataset == nullptr) {
    std::string message =
        spec.source + ": GDAL cannot open it as a raster" +
        (spec.driver.empty() ? "" : " with driver " + spec.driver) + ": " +
        LastGdalError();
    if (SourceHasExtension(spec.source, kAmbiguousExtensions)) {
      message += " (x,y,z text is read when the file is named .xyz or .csv)";
    }
    return Status::InvalidArgument(message);
  }
  *out = std::move(dataset);
  return Status::OK();
}

}  // namespace

Status ReadElevationGrid(const std::string& spec, const DatasetLimits& limits,
                         ElevationGrid* out, std::vector<std::string>* files) {
  ASSIGN_OR_RETURN(const RasterDatasetSpec parsed,
                   ParseRasterDatasetSpec(spec));
  std::unique_ptr<GDALDataset, GdalCloser> dataset;
  RETURN_IF_ERROR(OpenRaster(parsed, &dataset));
  const std::string& source = parsed.source;
  const int bands = dataset->GetRasterCount();
  if (parsed.band > bands) {
    return Status::InvalidArgument(
        source + ": band " + std::to_string(parsed.band) +
        " is out of range: it has " + std::to_string(bands) +
        (bands == 1 ? " band" : " bands"));
  }
  GDALRasterBand& band = *dataset->GetRasterBand(parsed.band);
  const GDALDataType type = band.GetRasterDataType();
  if (type == GDT_Unknown || GDALDataTypeIsComplex(type)) {
    return Status::InvalidArgument(
        source + ": band " + std::to_string(parsed.band) + " holds " +
        GDALGetDataTypeName(type) +
        " values; an elevation band must be real (integer or float)");
  }
  double gt[6];
  // Without one GDAL gives (0, 1, 0, 0, 0, 1): pixel/line coordinates.
  dataset->GetGeoTransform(gt);
  RETURN_IF_ERROR(CheckGeoTransform(source, gt));

  ElevationGrid grid;
  grid.width = static_cast<uint32_t>(dataset->GetRasterXSize());
  grid.height = static_cast<uint32_t>(dataset->GetRasterYSize());
  if (grid.samples() > limits.max_points) {
    return Status::ResourceExhausted(
        source + ": " + std::to_string(grid.width) + " x " +
        std::to_string(grid.height) + " = " + std::to_string(grid.samples()) +
        " pixels, more than " + std::to_string(limits.max_points) +
        " points (max_points limit)");
  }
  grid.origin_x = gt[0] + 0.5 * gt[1];
  grid.origin_y = gt[3] + 0.5 * gt[5];
  grid.step_x = gt[1];
  grid.step_y = gt[5];
  if (!parsed.assigned_crs.empty()) {
    StatusOr<std::string> wkt = UserCrsToWkt(parsed.assigned_crs);
    if (!wkt.ok()) {
      return Status::InvalidArgument(source +
                                     ": a_srs: " + wkt.status().message());
    }
    grid.crs = *std::move(wkt);
  } else if (const OGRSpatialReference* srs = dataset->GetSpatialRef()) {
    grid.crs = SpatialRefToWkt(*srs);
  }
  grid.values.resize(grid.samples());
  uint64_t valid = 0;
  BandReader reader(source, parsed.band, band);
  RETURN_IF_ERROR(reader.Read(&grid, &valid));
  if (valid == 0) {
    return Status::InvalidArgument(source + ": band " +
                                   std::to_string(parsed.band) +
                                   " has no valid pixel (all nodata)");
  }
  if (files != nullptr) *files = GdalFileList(*dataset);
  grid.source = spec;
  *out = std::move(grid);
  return Status::OK();
}

}  // namespace locator::gis
