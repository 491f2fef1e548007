// What a request's (a Reload's) OGR spec may ask for: a few drivers, the
// harmless open options, a plain where clause, an a_srs under the request
// CRS policy; everything else is refused naming the option.

#include "common/gis/untrusted_ogr_spec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"

namespace locator::gis {
namespace {

using ::testing::HasSubstr;

Status CheckSpec(const std::string& text) {
  const StatusOr<OgrDatasetSpec> spec = ParseOgrDatasetSpec(text);
  if (!spec.ok()) return spec.status();
  return CheckUntrustedOgrOptions(*spec);
}

TEST(UntrustedOgrSpecTest, HarmlessOptionsPass) {
  for (const char* spec : {
           "a.gpkg?layer=hill&z=height&where=id%20%25%2015%20%3E%3D%207"
           "&breaklines=ridges&domain=shore&a_srs=EPSG:32632",
           "ogr:a.csv?oo=X_POSSIBLE_NAMES=x&oo=y_possible_names=y"
           "&oo=Z_POSSIBLE_NAMES=z&oo=HEADERS=YES&oo=AUTODETECT_TYPE=YES",
           "a.shp?oo=ENCODING=CP1252&driver=ESRI%20Shapefile",
           "a.gpkg?oo=LIST_ALL_TABLES=NO&driver=GPKG",
       }) {
    const Status status = CheckSpec(spec);
    EXPECT_TRUE(status.ok()) << spec << ": " << status.ToString();
  }
}

TEST(UntrustedOgrSpecTest, OptionsThatRunSqlOrNameFilesAreRefused) {
  const struct {
    const char* spec;
    const char* message;
  } kCases[] = {
      {"a.gpkg?oo=PRELUDE_STATEMENTS=ATTACH%20DATABASE%20'%2Ftmp%2Fs.db'"
       "%20AS%20x",
       "oo=PRELUDE_STATEMENTS: not an open option a Reload may set"},
      {"a.gpkg?oo=prelude_statements=VACUUM%20INTO%20'%2Ftmp%2Fout.db'",
       "oo=PRELUDE_STATEMENTS: not an open option"},
      {"a.json?oo=FEATURE_SERVER_PAGING=YES", "oo=FEATURE_SERVER_PAGING"},
      {"a.gml?oo=XSD=%2Fetc%2Fschema.xsd", "oo=XSD"},
      {"a.gpkg?where=(SELECT%201)%20%3D%201",
       "where=: at byte 8, expected ')'"},
      {"a.gpkg?a_srs=%2Bproj%3Dlonglat%20%2Bellps%3DWGS84%20%2Bnadgrids%3D"
       "%2Fdev%2Fptmx",
       "a_srs=: CRS '+proj=longlat +ellps=WGS84 +nadgrids=/dev/ptmx' names "
       "a file PROJ may not open here: '/dev/ptmx' (outside PROJ's data "
       "directories)"},
      {"a.gpkg?driver=OGR_VRT", "driver='OGR_VRT': a Reload may read only"},
      {"a.sqlite?driver=SQLite", "driver='SQLite'"},
  };
  for (const auto& c : kCases) {
    const Status status = CheckSpec(c.spec);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << c.spec;
    EXPECT_THAT(status.message(), HasSubstr(c.message)) << c.spec;
  }
}

TEST(UntrustedOgrSpecTest, TheDriverIsOneThatReadsOnlyTheFile) {
  test::ScratchDir dir;
  const std::string gpkg = testing::UtmHillGeoPackage(3, dir.path());
  const std::string geojson = dir.path() + "/hill.geojson";
  // An OGR VRT names other files; a .csv that holds one is read as CSV.
  const std::string vrt_as_csv = dir.path() + "/points.csv";
  testing::WriteFile(vrt_as_csv,
                     "<OGRVRTDataSource><OGRVRTLayer name=\"x\"><SrcDataSource>"
                     "/etc/passwd</SrcDataSource></OGRVRTLayer>"
                     "</OGRVRTDataSource>");
  const std::string vrt = dir.path() + "/points.vrt";
  testing::WriteFile(vrt, "<OGRVRTDataSource/>");
  const std::string sqlite = dir.path() + "/hill.sqlite";
  testing::Ogr2Ogr({"-f", "SQLite", sqlite, gpkg});
  const struct {
    std::string path;
    std::string driver;
  } kCases[] = {{gpkg, "GPKG"},
                {geojson, "GeoJSON"},
                {vrt_as_csv, "CSV"},
                {vrt, ""},
                {sqlite, ""}};
  for (const auto& c : kCases) {
    std::string driver;
    const Status status = UntrustedOgrDriver(OgrDatasetSpec(), c.path, &driver);
    if (c.driver.empty()) {
      EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << c.path;
      EXPECT_THAT(status.message(),
                  HasSubstr("not a format a Reload may read (GPKG, ESRI "
                            "Shapefile, GeoJSON, GeoJSONSeq, FlatGeobuf, CSV, "
                            "KML, GPX)"));
    } else {
      EXPECT_TRUE(status.ok()) << c.path << ": " << status.ToString();
      EXPECT_EQ(driver, c.driver) << c.path;
    }
  }
}

}  // namespace
}  // namespace locator::gis
