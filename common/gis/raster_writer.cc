#include "common/gis/raster_writer.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>
#include <unistd.h>

#include <cmath>
#include <limits>
#include <utility>

#include "common/gis/gdal_support.h"
#include "common/status_macros.h"

namespace locator::gis {
namespace {

constexpr char kGTiff[] = "GTiff";
constexpr char kCog[] = "COG";

// Tiles of the GTiff written in place, and of COG's temporary GTiff.
constexpr char kTileSize[] = "256";

Status CheckShape(const std::string& path, const RasterShape& shape) {
  const auto bad = [&](const std::string& what) {
    return Status::InvalidArgument(path + ": " + what);
  };
  if (shape.width == 0 || shape.height == 0) {
    return bad("a raster needs at least one row and one column, not " +
               std::to_string(shape.width) + " x " +
               std::to_string(shape.height));
  }
  constexpr uint32_t kGdalMaxSize = std::numeric_limits<int>::max();
  if (shape.width > kGdalMaxSize || shape.height > kGdalMaxSize) {
    return bad("GDAL takes at most " + std::to_string(kGdalMaxSize) +
               " rows and columns, not " + std::to_string(shape.width) + " x " +
               std::to_string(shape.height));
  }
  if (!std::isfinite(shape.cell_width) || !(shape.cell_width > 0) ||
      !std::isfinite(shape.cell_height) || !(shape.cell_height > 0)) {
    return bad("the cell size must be positive and finite");
  }
  if (!std::isfinite(shape.box.min_x) || !std::isfinite(shape.box.max_y)) {
    return bad("the raster's origin (min_x, max_y) must be finite");
  }
  return Status::OK();
}

// `user` over `defaults`: an option the user gives replaces the default of
// the same name. InvalidArgument for an option that is not NAME=VALUE.
Status MergeOptions(const std::vector<std::string>& user,
                    const CPLStringList& defaults, CPLStringList* merged) {
  *merged = defaults;
  for (const std::string& option : user) {
    const size_t equals = option.find('=');
    if (equals == 0 || equals == std::string::npos) {
      return Status::InvalidArgument("creation option '" + option +
                                     "' is not NAME=VALUE");
    }
    merged->SetNameValue(option.substr(0, equals).c_str(),
                         option.substr(equals + 1).c_str());
  }
  return Status::OK();
}

// GDAL's driver `name`, which must be one RasterWriter writes.
Status FindDriver(const std::string& name, GDALDriver** driver) {
  if (name != kGTiff && name != kCog) {
    return Status::InvalidArgument("unknown raster format '" + name +
                                   "': GTiff or COG");
  }
  *driver = GetGDALDriverManager()->GetDriverByName(name.c_str());
  if (*driver == nullptr) {
    return Status::InvalidArgument("this GDAL has no " + name + " driver");
  }
  return Status::OK();
}

// InvalidArgument naming the first of `options` that `driver` rejects.
Status ValidateOptions(GDALDriver* driver, const std::string& name,
                       const CPLStringList& options) {
  CPLErrorReset();
  if (GDALValidateCreationOptions(driver, options.List())) return Status::OK();
  return Status::InvalidArgument("bad " + name +
                                 " creation option: " + LastGdalError());
}

// The GTiff options of the rows' file: tiled.
CPLStringList TiledOptions() {
  CPLStringList options;
  options.SetNameValue("TILED", "YES");
  options.SetNameValue("BLOCKXSIZE", kTileSize);
  options.SetNameValue("BLOCKYSIZE", kTileSize);
  return options;
}

// The driver `format` names and its creation options: the user's, over the
// tiling defaults for GTiff.
Status ResolveFormat(const RasterFormat& format, GDALDriver** driver,
                     CPLStringList* options) {
  RegisterGdalDrivers();
  RETURN_IF_ERROR(FindDriver(format.driver, driver));
  const CPLStringList defaults =
      format.driver == kGTiff ? TiledOptions() : CPLStringList();
  RETURN_IF_ERROR(MergeOptions(format.creation_options, defaults, options));
  return ValidateOptions(*driver, format.driver, *options);
}

Status SetGeoreferencing(const std::string& path, const RasterShape& shape,
                         GDALDataset* dataset) {
  double transform[6] = {
      shape.box.min_x,   shape.cell_width, 0, shape.box.max_y, 0,
      -shape.cell_height};
  CPLErrorReset();
  if (dataset->SetGeoTransform(transform) != CE_None) {
    return Status::IOError(path +
                           ": cannot set the geotransform: " + LastGdalError());
  }
  if (!shape.crs_wkt.empty()) {
    OGRSpatialReference crs;
    crs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (crs.importFromWkt(shape.crs_wkt.c_str()) != OGRERR_NONE) {
      return Status::InvalidArgument(
          path + ": the CRS is not WKT GDAL reads: " + LastGdalError());
    }
    if (dataset->SetSpatialRef(&crs) != CE_None) {
      return Status::IOError(path + ": cannot set the CRS: " + LastGdalError());
    }
  }
  if (dataset->GetRasterBand(1)->SetNoDataValue(shape.nodata) != CE_None) {
    return Status::IOError(path +
                           ": cannot set the nodata value: " + LastGdalError());
  }
  return Status::OK();
}

// Closes `dataset`; IOError with GDAL's message if flushing it failed.
Status CloseDataset(const std::string& path, GDALDataset* dataset) {
  CPLErrorReset();
  GDALClose(dataset);
  if (CPLGetLastErrorType() == CE_Failure) {
    return Status::IOError(path + ": writing failed: " + LastGdalError());
  }
  return Status::OK();
}

}  // namespace

std::string DefaultRasterDriver() {
  RegisterGdalDrivers();
  return GetGDALDriverManager()->GetDriverByName(kCog) != nullptr ? kCog
                                                                  : kGTiff;
}

Status CheckRasterFormat(const RasterFormat& format) {
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  GDALDriver* driver = nullptr;
  CPLStringList options;
  return ResolveFormat(format, &driver, &options);
}

Status RasterWriter::Open(const std::string& path, const RasterShape& shape,
                          const RasterFormat& format,
                          std::unique_ptr<RasterWriter>* writer) {
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  RETURN_IF_ERROR(CheckShape(path, shape));
  GDALDriver* driver = nullptr;
  CPLStringList output_options;
  RETURN_IF_ERROR(ResolveFormat(format, &driver, &output_options));

  std::unique_ptr<RasterWriter> opened(
      new RasterWriter(path, shape.width, shape.height));
  CPLStringList rows_options;
  if (format.driver == kCog) {
    opened->cog_options_ = format.creation_options;
    opened->copy_to_cog_ = true;
    opened->rows_path_ = path + "." + std::to_string(getpid()) + ".tmp.tif";
    rows_options = TiledOptions();
    // Only temporary: as large as it may need to be.
    rows_options.SetNameValue("BIGTIFF", "IF_SAFER");
  } else {
    opened->rows_path_ = path;
    rows_options = output_options;
  }
  GDALDriver* rows_driver = GetGDALDriverManager()->GetDriverByName(kGTiff);
  CPLErrorReset();
  opened->rows_ = rows_driver->Create(
      opened->rows_path_.c_str(), static_cast<int>(shape.width),
      static_cast<int>(shape.height), 1, GDT_Float64, rows_options.List());
  if (opened->rows_ == nullptr) {
    return Status::IOError(path + ": cannot create: " + LastGdalError());
  }
  if (Status status = SetGeoreferencing(path, shape, opened->rows_);
      !status.ok()) {
    return status;  // `opened` removes the file
  }
  *writer = std::move(opened);
  return Status::OK();
}

RasterWriter::RasterWriter(std::string path, uint32_t width, uint32_t height)
    : path_(std::move(path)), width_(width), height_(height) {}

RasterWriter::~RasterWriter() {
  if (!closed_) Discard();
}

Status RasterWriter::WriteRows(uint32_t first_row, uint32_t rows,
                               std::span<const double> values) {
  if (rows_ == nullptr) {
    return Status::FailedPrecondition(path_ + ": the raster is closed");
  }
  if (first_row >= height_ || rows > height_ - first_row) {
    return Status::InvalidArgument(
        path_ + ": rows " + std::to_string(first_row) + " + " +
        std::to_string(rows) + " outside the raster's " +
        std::to_string(height_));
  }
  if (values.size() != uint64_t{rows} * width_) {
    return Status::InvalidArgument(
        path_ + ": " + std::to_string(values.size()) + " values for " +
        std::to_string(rows) + " rows of " + std::to_string(width_));
  }
  if (rows == 0) return Status::OK();
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  CPLErrorReset();
  const CPLErr written = rows_->GetRasterBand(1)->RasterIO(
      GF_Write, 0, static_cast<int>(first_row), static_cast<int>(width_),
      static_cast<int>(rows), const_cast<double*>(values.data()),
      static_cast<int>(width_), static_cast<int>(rows), GDT_Float64, 0, 0,
      nullptr);
  if (written != CE_None) {
    return Status::IOError(path_ + ": writing rows failed: " + LastGdalError());
  }
  return Status::OK();
}

Status RasterWriter::Close() {
  if (rows_ == nullptr) {
    return Status::FailedPrecondition(path_ + ": the raster is closed");
  }
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  Status status;
  if (copy_to_cog_) {
    rows_->FlushCache();
    CPLStringList options;
    for (const std::string& option : cog_options_) {
      options.AddString(option.c_str());
    }
    GDALDriver* cog = GetGDALDriverManager()->GetDriverByName(kCog);
    CPLErrorReset();
    GDALDataset* copied =
        cog->CreateCopy(path_.c_str(), rows_, /*bStrict=*/FALSE, options.List(),
                        nullptr, nullptr);
    if (copied == nullptr) {
      status =
          Status::IOError(path_ + ": cannot write the COG: " + LastGdalError());
    } else {
      status = CloseDataset(path_, copied);
    }
  }
  GDALDataset* rows = std::exchange(rows_, nullptr);
  const Status closed = CloseDataset(path_, rows);
  if (status.ok()) status = closed;
  if (copy_to_cog_) VSIUnlink(rows_path_.c_str());
  if (!status.ok()) {
    Discard();
    return status;
  }
  closed_ = true;
  return Status::OK();
}

void RasterWriter::Discard() {
  CPLErrorHandlerPusher quiet(CPLQuietErrorHandler);
  if (rows_ != nullptr) GDALClose(std::exchange(rows_, nullptr));
  VSIUnlink(rows_path_.c_str());
  if (rows_path_ != path_) VSIUnlink(path_.c_str());
  closed_ = true;
}

}  // namespace locator::gis
