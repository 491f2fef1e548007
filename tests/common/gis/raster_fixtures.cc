#include "tests/common/gis/raster_fixtures.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>

namespace locator::gis::testing {

void WriteDem(const std::string& path, const DemFixture& dem) {
  GDALAllRegister();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName("GTiff");
  ASSERT_NE(driver, nullptr);
  const GDALDataType type = GDALGetDataTypeByName(dem.type.c_str());
  ASSERT_NE(type, GDT_Unknown) << dem.type;
  ASSERT_EQ(dem.values.size(), size_t{dem.width} * dem.height);
  GDALDatasetUniquePtr out(driver->Create(path.c_str(), dem.width, dem.height,
                                          dem.bands, type, nullptr));
  ASSERT_NE(out, nullptr) << path;
  // AREA_OR_POINT first: the GTiff driver stores the geotransform as a
  // PixelIsPoint tie point when it is "Point".
  if (!dem.area_or_point.empty()) {
    out->SetMetadataItem("AREA_OR_POINT", dem.area_or_point.c_str());
  }
  double gt[6];
  std::copy(dem.geotransform.begin(), dem.geotransform.end(), gt);
  ASSERT_EQ(out->SetGeoTransform(gt), CE_None);
  if (!dem.crs.empty()) {
    OGRSpatialReference srs;
    ASSERT_EQ(srs.SetFromUserInput(dem.crs.c_str()), OGRERR_NONE) << dem.crs;
    ASSERT_EQ(out->SetSpatialRef(&srs), CE_None);
  }
  for (int b = 1; b <= dem.bands; ++b) {
    GDALRasterBand* band = out->GetRasterBand(b);
    if (dem.has_nodata) {
      ASSERT_EQ(band->SetNoDataValue(dem.nodata), CE_None);
    }
    if (dem.scale != 1) {
      ASSERT_EQ(band->SetScale(dem.scale), CE_None);
    }
    if (dem.offset != 0) {
      ASSERT_EQ(band->SetOffset(dem.offset), CE_None);
    }
    std::vector<double> values = dem.values;
    for (double& v : values) {
      if (!(dem.has_nodata && v == dem.nodata)) v += 1000.0 * (b - 1);
    }
    ASSERT_EQ(
        band->RasterIO(GF_Write, 0, 0, dem.width, dem.height, values.data(),
                       dem.width, dem.height, GDT_Float64, 0, 0, nullptr),
        CE_None);
  }
  if (!dem.mask.empty()) {
    ASSERT_EQ(dem.mask.size(), dem.values.size());
    ASSERT_EQ(out->CreateMaskBand(GMF_PER_DATASET), CE_None);
    std::vector<GByte> mask(dem.mask.size());
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = dem.mask[i] ? 255 : 0;
    ASSERT_EQ(out->GetRasterBand(1)->GetMaskBand()->RasterIO(
                  GF_Write, 0, 0, dem.width, dem.height, mask.data(), dem.width,
                  dem.height, GDT_Byte, 0, 0, nullptr),
              CE_None);
  }
  out.reset();  // flushes and closes
}

DemFixture HillDem(uint32_t width, uint32_t height, double cell) {
  DemFixture dem;
  dem.width = width;
  dem.height = height;
  const double min_x = 500000 - 0.5 * width * cell;
  const double max_y = 5500000 + 0.5 * height * cell;
  dem.geotransform = {min_x, cell, 0, max_y, 0, -cell};
  dem.crs = "EPSG:32633";
  dem.has_nodata = true;
  dem.nodata = -9999;
  const double sigma = width * cell / 3;
  dem.values.resize(size_t{width} * height);
  for (uint32_t row = 0; row < height; ++row) {
    for (uint32_t col = 0; col < width; ++col) {
      const double x = min_x + (col + 0.5) * cell - 500000;
      const double y = max_y - (row + 0.5) * cell - 5500000;
      const double r2 = x * x + y * y;
      const double z = 400 + 300 * std::exp(-r2 / (2 * sigma * sigma)) +
                       4 * std::sin(x / (7 * cell)) * std::cos(y / (5 * cell));
      // Float32 values, so that the file holds exactly what is expected.
      dem.values[size_t{row} * width + col] = static_cast<float>(z);
    }
  }
  return dem;
}

void PunchHole(DemFixture* dem, uint32_t col0, uint32_t row0, uint32_t col1,
               uint32_t row1) {
  ASSERT_TRUE(dem->has_nodata);
  for (uint32_t row = row0; row < row1; ++row) {
    for (uint32_t col = col0; col < col1; ++col) {
      dem->values[size_t{row} * dem->width + col] = dem->nodata;
    }
  }
}

}  // namespace locator::gis::testing
