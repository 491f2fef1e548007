#include "common/gis/crs_info.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace locator::gis {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(CrsInfoTest, UtmZone33NorthAndWgs84) {
  const struct {
    const char* crs;
    const char* name;
    int epsg_code;
    const char* unit;
  } kCases[] = {{"EPSG:32633", "WGS 84 / UTM zone 33N", 32633, "metre"},
                {"EPSG:4326", "WGS 84", 4326, "degree"}};
  for (const auto& c : kCases) {
    const StatusOr<CrsInfo> info = DescribeCrs(c.crs);
    ASSERT_TRUE(info.ok()) << c.crs;
    EXPECT_EQ(info->name, c.name);
    EXPECT_EQ(info->epsg_code, c.epsg_code);
    EXPECT_THAT(info->axis_units, ElementsAre(c.unit, c.unit)) << c.crs;
  }
}

TEST(CrsInfoTest, ProjStringAndUsFeet) {
  StatusOr<CrsInfo> info = DescribeCrs("+proj=utm +zone=33 +datum=WGS84");
  ASSERT_TRUE(info.ok());
  EXPECT_THAT(info->axis_units, ElementsAre("metre", "metre"));
  // NAD83 / Texas South Central (ftUS).
  info = DescribeCrs("EPSG:2278");
  ASSERT_TRUE(info.ok());
  EXPECT_EQ(info->epsg_code, 2278);
  EXPECT_THAT(info->axis_units,
              ElementsAre("US survey foot", "US survey foot"));
}

TEST(CrsInfoTest, WktWithoutAnIdIsIdentified) {
  // EPSG:32633 as WKT1 without AUTHORITY nodes.
  const char* kWkt =
      R"(PROJCS["WGS 84 / UTM zone 33N",GEOGCS["WGS 84",DATUM["WGS_1984",)"
      R"(SPHEROID["WGS 84",6378137,298.257223563]],PRIMEM["Greenwich",0],)"
      R"(UNIT["degree",0.0174532925199433]],PROJECTION["Transverse_Mercator"],)"
      R"(PARAMETER["latitude_of_origin",0],PARAMETER["central_meridian",15],)"
      R"(PARAMETER["scale_factor",0.9996],PARAMETER["false_easting",500000],)"
      R"(PARAMETER["false_northing",0],UNIT["metre",1],AXIS["Easting",EAST],)"
      R"(AXIS["Northing",NORTH]])";
  const StatusOr<CrsInfo> info = DescribeCrs(kWkt);
  ASSERT_TRUE(info.ok()) << info.status().ToString();
  EXPECT_EQ(info->name, "WGS 84 / UTM zone 33N");
  EXPECT_EQ(info->epsg_code, 32633);
}

TEST(CrsInfoTest, UnknownCrsIsInvalidArgumentNamingIt) {
  for (const char* crs : {"EPSG:999999", "not a crs", "", "+proj=nope"}) {
    const Status status = DescribeCrs(crs).status();
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << crs;
    EXPECT_THAT(status.message(),
                HasSubstr("unknown CRS '" + std::string(crs) + "'"));
  }
  // A coordinate operation (the UTM zone 33N conversion) is not a CRS.
  const Status status =
      DescribeCrs("urn:ogc:def:coordinateOperation:EPSG::16033").status();
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("not a coordinate reference system"));
}

}  // namespace
}  // namespace locator::gis
