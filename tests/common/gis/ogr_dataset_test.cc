#include "common/gis/ogr_dataset.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "common/gis/crs_info.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"

namespace locator::gis {
namespace {

using ::testing::AllOf;
using testing::GeometriesGeoJson;
using ::testing::HasSubstr;
using testing::Ogr2Ogr;
using testing::PointsGeoJson;
using testing::PointZ;
using testing::WriteFile;

const std::vector<PointZ> kPoints = {
    {500000, 5500000, 410.5}, {500100, 5500000, 420.25},
    {500000, 5500100, 430},   {500100, 5500100, 440.125},
    {500050, 5500050, 455},
};

using Triple = std::tuple<double, double, double>;

// The points and values of `d`, sorted (FlatGeobuf reorders features).
std::vector<Triple> SortedTriples(const Dataset& d) {
  std::vector<Triple> out;
  for (size_t i = 0; i < d.points.size(); ++i) {
    out.emplace_back(d.points[i].x, d.points[i].y,
                     d.has_values() ? d.values[i] : -1.0);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Triple> Expected(bool with_values) {
  std::vector<Triple> out;
  for (const PointZ& p : kPoints) {
    out.emplace_back(p.x, p.y, with_values ? p.z : -1.0);
  }
  std::sort(out.begin(), out.end());
  return out;
}

int EpsgOf(const Dataset& d) {
  const StatusOr<CrsInfo> info = DescribeCrs(d.crs);
  EXPECT_TRUE(info.ok()) << d.crs;
  return info.ok() ? info->epsg_code : 0;
}

class OgrDatasetTest : public ::testing::Test {
 protected:
  void SetUp() override {
    geojson_ = Path("pts.geojson");
    WriteFile(geojson_, PointsGeoJson(kPoints));
  }

  std::string Path(const std::string& name) const {
    return dir_.path() + "/" + name;
  }

  // A GeoPackage with layers points (32633), lines and area.
  std::string MultiLayerGeoPackage(const std::string& lines_crs) {
    const std::string gpkg = Path("multi.gpkg");
    Ogr2Ogr({"-f", "GPKG", gpkg, geojson_, "-nln", "points", "-a_srs",
             "EPSG:32633"});
    const std::string lines = Path("lines.geojson");
    WriteFile(lines,
              GeometriesGeoJson(
                  {R"({"type":"LineString","coordinates":[[500000,5500000,1],)"
                   R"([500050,5500050,2],[500100,5500100,3]]})",
                   R"({"type":"MultiLineString","coordinates":[)"
                   R"([[500000,5500100,4],[500050,5500060,5]],)"
                   R"([[500100,5500000,6],[500060,5500050,7]]]})"}));
    Ogr2Ogr({"-update", "-f", "GPKG", gpkg, lines, "-nln", "lines", "-a_srs",
             lines_crs});
    const std::string area = Path("area.geojson");
    WriteFile(area,
              GeometriesGeoJson(
                  {R"({"type":"Polygon","coordinates":[)"
                   R"([[499990,5499990],[500110,5499990],[500110,5500110],)"
                   R"([499990,5500110],[499990,5499990]],)"
                   R"([[500040,5500040],[500060,5500040],[500060,5500060],)"
                   R"([500040,5500040]]]})",
                   R"({"type":"MultiPolygon","coordinates":[)"
                   R"([[[0,0],[1,0],[1,1],[0,0]]],)"
                   R"([[[2,2],[3,2],[3,3],[2,2]]]]})"}));
    Ogr2Ogr({"-update", "-f", "GPKG", gpkg, area, "-nln", "area", "-a_srs",
             "EPSG:32633"});
    return gpkg;
  }

  Status Load(const std::string& spec, Dataset* out,
              const DatasetLimits& limits = DatasetLimits()) {
    return LoadOgrDataset(spec, out, limits);
  }

  test::ScratchDir dir_;
  std::string geojson_;
};

TEST_F(OgrDatasetTest, GeoPackageWithPointZAndCrs) {
  const std::string gpkg = Path("pts.gpkg");
  Ogr2Ogr({"-f", "GPKG", gpkg, geojson_, "-a_srs", "EPSG:32633"});
  Dataset d;
  ASSERT_TRUE(Load(gpkg, &d).ok());
  EXPECT_EQ(SortedTriples(d), Expected(true));
  EXPECT_EQ(d.source, gpkg);
  EXPECT_EQ(EpsgOf(d), 32633);
  EXPECT_TRUE(d.constraints.empty());
}

TEST_F(OgrDatasetTest, ShapefileWithZFromAnAttribute) {
  const std::string shp = Path("pts.shp");
  Ogr2Ogr({"-f", "ESRI Shapefile", shp, geojson_, "-dim", "XY", "-a_srs",
           "EPSG:32633"});
  Dataset d;
  ASSERT_TRUE(Load(shp + "?z=height", &d).ok());
  EXPECT_EQ(SortedTriples(d), Expected(true));
  EXPECT_EQ(EpsgOf(d), 32633);
  // Without z= a 2D layer has no values.
  ASSERT_TRUE(Load(shp, &d).ok());
  EXPECT_EQ(SortedTriples(d), Expected(false));
}

TEST_F(OgrDatasetTest, GeoJsonReadDirectly) {
  Dataset d;
  ASSERT_TRUE(Load(geojson_, &d).ok());
  EXPECT_EQ(SortedTriples(d), Expected(true));
}

TEST_F(OgrDatasetTest, FlatGeobuf) {
  const std::string fgb = Path("pts.fgb");
  Ogr2Ogr({"-f", "FlatGeobuf", fgb, geojson_, "-a_srs", "EPSG:32633"});
  Dataset d;
  ASSERT_TRUE(Load(fgb, &d).ok());
  EXPECT_EQ(SortedTriples(d), Expected(true));
  EXPECT_EQ(EpsgOf(d), 32633);
}

TEST_F(OgrDatasetTest, CsvWithXyColumnsThroughOpenOptions) {
  std::string csv = "id,x,y,height\n";
  for (size_t i = 0; i < kPoints.size(); ++i) {
    csv += std::to_string(i) + "," + std::to_string(kPoints[i].x) + "," +
           std::to_string(kPoints[i].y) + "," + std::to_string(kPoints[i].z) +
           "\n";
  }
  WriteFile(Path("pts.csv"), csv);
  Dataset d;
  const Status status = Load("ogr:" + Path("pts.csv") +
                                 "?oo=X_POSSIBLE_NAMES=x&oo=Y_POSSIBLE_NAMES=y"
                                 "&z=height&a_srs=EPSG:32633",
                             &d);
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_EQ(SortedTriples(d), Expected(true));
  EXPECT_EQ(EpsgOf(d), 32633);
}

TEST_F(OgrDatasetTest, WhereFiltersThePointsLayer) {
  Dataset d;
  ASSERT_TRUE(Load(geojson_ + "?where=height%20%3E%20425", &d).ok());
  EXPECT_EQ(d.points.size(), 3u);
  for (double value : d.values) EXPECT_GT(value, 425);
}

TEST_F(OgrDatasetTest, MultiPointsBecomePoints) {
  const std::string path = Path("multi.geojson");
  WriteFile(path, GeometriesGeoJson(
                      {R"({"type":"MultiPoint","coordinates":[[0,0],[1,0]]})",
                       R"({"type":"Point","coordinates":[0,1]})"}));
  Dataset d;
  ASSERT_TRUE(Load(path, &d).ok());
  EXPECT_EQ(d.points.size(), 3u);
  EXPECT_FALSE(d.has_values());
}

TEST_F(OgrDatasetTest, BreaklinesAndDomainLayers) {
  const std::string gpkg = MultiLayerGeoPackage("EPSG:32633");
  Dataset d;
  const Status status =
      Load(gpkg + "?layer=points&breaklines=lines&domain=area", &d);
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_EQ(d.points.size(), kPoints.size());
  const auto& breaklines = d.constraints.breaklines;
  ASSERT_EQ(breaklines.size(), 3u);  // a LineString and 2 MultiLineString parts
  EXPECT_EQ(breaklines[0].points.size(), 3u);
  EXPECT_EQ(breaklines[0].values, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(breaklines[2].points[1].x, 500060);
  const auto& rings = d.constraints.rings;
  ASSERT_EQ(rings.size(), 4u);            // exterior + hole, then 2 polygons
  EXPECT_EQ(rings[0].points.size(), 4u);  // the closing point is dropped
  EXPECT_EQ(rings[1].points.size(), 3u);
  EXPECT_EQ(rings[1].points[0].x, 500040);
  EXPECT_EQ(rings[3].points[0].x, 2);
  EXPECT_EQ(EpsgOf(d), 32633);
}

TEST_F(OgrDatasetTest, AssignedCrsOverridesTheSource) {
  const std::string gpkg = Path("pts.gpkg");
  Ogr2Ogr({"-f", "GPKG", gpkg, geojson_, "-a_srs", "EPSG:32633"});
  Dataset d;
  ASSERT_TRUE(Load(gpkg + "?a_srs=EPSG:32632", &d).ok());
  EXPECT_EQ(EpsgOf(d), 32632);
  ASSERT_TRUE(
      Load(gpkg + "?a_srs=%2Bproj%3Dutm%20%2Bzone%3D34%20%2Bdatum%3DWGS84", &d)
          .ok());
  EXPECT_THAT(d.crs, HasSubstr("UTM zone 34N"));
}

// Every error names the source and, where one is to blame, the layer and
// the feature.
class OgrDatasetErrorTest : public OgrDatasetTest {
 protected:
  void ExpectError(const std::string& spec, Status::Code code,
                   const std::string& message,
                   const DatasetLimits& limits = DatasetLimits()) {
    Dataset d;
    const Status status = Load(spec, &d, limits);
    EXPECT_EQ(status.code(), code) << spec << ": " << status.ToString();
    EXPECT_THAT(status.message(), HasSubstr(message)) << spec;
  }
};

TEST_F(OgrDatasetErrorTest, MissingAndUnreadableSources) {
  ExpectError(Path("nope.gpkg"), Status::Code::kNotFound,
              Path("nope.gpkg") + ": no such file");
  WriteFile(Path("bad.gpkg"), "this is not a GeoPackage\n");
  ExpectError(Path("bad.gpkg"), Status::Code::kInvalidArgument,
              Path("bad.gpkg") + ": not a readable OGR vector source");
  ExpectError(Path("pts.geojson?colour=red"), Status::Code::kInvalidArgument,
              "unknown option 'colour'");
}

TEST_F(OgrDatasetErrorTest, MissingLayerAndField) {
  const std::string gpkg = MultiLayerGeoPackage("EPSG:32633");
  ExpectError(gpkg + "?layer=nope", Status::Code::kNotFound,
              gpkg + ": no layer 'nope' (layers: 'points', 'lines', 'area')");
  ExpectError(gpkg + "?layer=points&domain=nope", Status::Code::kNotFound,
              "no layer 'nope'");
  ExpectError(gpkg, Status::Code::kInvalidArgument,
              "3 layers ('points', 'lines', 'area'); name one with ?layer=");
  ExpectError(gpkg + "?layer=points&z=nope", Status::Code::kNotFound,
              gpkg + ": layer 'points': no field 'nope'");
}

TEST_F(OgrDatasetErrorTest, GeometriesOfTheWrongKind) {
  const std::string gpkg = MultiLayerGeoPackage("EPSG:32633");
  ExpectError(gpkg + "?layer=lines", Status::Code::kInvalidArgument,
              gpkg +
                  ": layer 'lines': feature 0: a LINESTRING where points "
                  "are expected");
  ExpectError(gpkg + "?layer=points&breaklines=area",
              Status::Code::kInvalidArgument,
              "layer 'area': feature 0: a POLYGON where breaklines");
  ExpectError(gpkg + "?layer=points&domain=lines",
              Status::Code::kInvalidArgument,
              "layer 'lines': feature 0: a LINESTRING where domain polygons");
}

TEST_F(OgrDatasetErrorTest, LayersInDifferentCrss) {
  const std::string gpkg = MultiLayerGeoPackage("EPSG:32632");
  ExpectError(gpkg + "?layer=points&breaklines=lines",
              Status::Code::kInvalidArgument,
              "layer 'lines' is in CRS 'WGS 84 / UTM zone 32N' but layer "
              "'points' is in 'WGS 84 / UTM zone 33N'");
  // a_srs assigns one CRS to all layers.
  Dataset d;
  EXPECT_TRUE(
      Load(gpkg + "?layer=points&breaklines=lines&a_srs=EPSG:32633", &d).ok());
}

TEST_F(OgrDatasetErrorTest, EmptyLayers) {
  const std::string gpkg = Path("empty.gpkg");
  Ogr2Ogr({"-f", "GPKG", gpkg, geojson_, "-where", "id < 0"});
  ExpectError(gpkg, Status::Code::kInvalidArgument,
              gpkg + ": layer 'pts' has no features");
  ExpectError(geojson_ + "?where=id%3E99", Status::Code::kInvalidArgument,
              "layer 'pts' has no features matching where 'id>99'");
}

TEST_F(OgrDatasetErrorTest, NullEmptyAndNonFiniteGeometries) {
  const std::string path = Path("geoms.geojson");
  WriteFile(path, GeometriesGeoJson(
                      {R"({"type":"Point","coordinates":[0,0]})", "null"}));
  ExpectError(path, Status::Code::kInvalidArgument,
              "layer 'geoms': feature 1: no geometry");
  WriteFile(path,
            GeometriesGeoJson({R"({"type":"Point","coordinates":[0,0]})",
                               R"({"type":"MultiPoint","coordinates":[]})"}));
  ExpectError(path, Status::Code::kInvalidArgument,
              "feature 1: empty geometry");
  WriteFile(Path("inf.csv"), "x,y\n0,0\n1e999,1\n");
  ExpectError(
      "ogr:" + Path("inf.csv") + "?oo=X_POSSIBLE_NAMES=x&oo=Y_POSSIBLE_NAMES=y",
      Status::Code::kInvalidArgument,
      "layer 'inf': feature 2: non-finite coordinate");
}

TEST_F(OgrDatasetErrorTest, NullAndNonNumericValues) {
  const std::string path = Path("z.geojson");
  WriteFile(path, R"({"type":"FeatureCollection","features":[)"
                  R"({"type":"Feature","properties":{"h":1},)"
                  R"("geometry":{"type":"Point","coordinates":[0,0]}},)"
                  R"({"type":"Feature","properties":{"h":null},)"
                  R"("geometry":{"type":"Point","coordinates":[1,0]}}]})");
  ExpectError(path + "?z=h", Status::Code::kInvalidArgument,
              "layer 'z': feature 1: field 'h' is null");
  WriteFile(Path("words.csv"), "x,y,h\n0,0,1\n1,0,high\n");
  ExpectError("ogr:" + Path("words.csv") +
                  "?oo=X_POSSIBLE_NAMES=x&oo=Y_POSSIBLE_NAMES=y&z=h",
              Status::Code::kInvalidArgument,
              "layer 'words': feature 2: field 'h' is 'high', not a number");
}

TEST_F(OgrDatasetErrorTest, BadWhereUnknownCrsAndTooManyPoints) {
  ExpectError(geojson_ + "?where=nosuchcolumn%3D1",
              Status::Code::kInvalidArgument,
              "layer 'pts': bad where 'nosuchcolumn=1'");
  ExpectError(geojson_ + "?a_srs=EPSG:999999", Status::Code::kInvalidArgument,
              "unknown CRS 'EPSG:999999' (a_srs)");
  DatasetLimits limits;
  limits.max_points = 4;
  ExpectError(geojson_, Status::Code::kResourceExhausted,
              "layer 'pts': more than 4 points (max_points limit)", limits);
}

// A GeoPackage with a corrupt page in the middle of its points: GDAL reads
// the features before it, reports the corruption and ends the layer there.
// The load fails naming the file, the layer and the feature; nothing of the
// layer is served.
TEST_F(OgrDatasetErrorTest, ACorruptGeoPackageFailsNamingTheFeature) {
  const std::string gpkg = testing::UtmHillGeoPackage(45, dir_.path());
  Dataset intact;
  ASSERT_TRUE(Load(gpkg, &intact).ok());
  ASSERT_EQ(intact.points.size(), 45u * 45u);
  ASSERT_GT(testing::CorruptMiddleDataPage(gpkg), 0);
  Dataset d;
  const Status status = Load(gpkg, &d);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << status.ToString();
  EXPECT_THAT(status.message(),
              AllOf(HasSubstr(gpkg + ": layer 'hill': feature number "),
                    HasSubstr(" (the one after FID "),
                    HasSubstr("database disk image is malformed")));
  EXPECT_TRUE(d.points.empty());
}

// What a spec names, and the text of a field, is quoted short
// (QuotedInput: 80 bytes and the size), however long.
TEST_F(OgrDatasetErrorTest, LongNamesAndValuesAreQuotedShort) {
  const std::string long_name(4000, 'n');
  const std::string quoted = "'" + std::string(80, 'n') + "...' (4000 bytes)";
  const std::string gpkg = MultiLayerGeoPackage("EPSG:32633");
  const struct {
    std::string spec;
    Status::Code code;
    std::string message;
  } kCases[] = {
      {gpkg + "?layer=" + long_name, Status::Code::kNotFound,
       gpkg + ": no layer " + quoted + " (layers: 'points', "},
      {gpkg + "?layer=points&z=" + long_name, Status::Code::kNotFound,
       "layer 'points': no field " + quoted},
      {geojson_ + "?where=" + long_name + "%3D1",
       Status::Code::kInvalidArgument,
       "layer 'pts': bad where '" + std::string(80, 'n') + "...' (4002 bytes)"},
      {geojson_ + "?a_srs=" + long_name, Status::Code::kInvalidArgument,
       ": unknown CRS " + quoted + " (a_srs)"},
      {geojson_ + "?driver=" + long_name, Status::Code::kInvalidArgument,
       ": no GDAL driver " + quoted + " (driver=)"},
  };
  for (const auto& c : kCases) {
    Dataset d;
    const Status status = Load(c.spec, &d);
    EXPECT_EQ(status.code(), c.code) << status.ToString().substr(0, 300);
    EXPECT_THAT(status.message(), HasSubstr(c.message));
    EXPECT_LT(status.message().size(), 600u) << status.message();
  }
  WriteFile(Path("words.csv"), "x,y,h\n0,0," + long_name + "\n");
  Dataset d;
  const Status status =
      Load("ogr:" + Path("words.csv") +
               "?oo=X_POSSIBLE_NAMES=x&oo=Y_POSSIBLE_NAMES=y&z=h",
           &d);
  EXPECT_THAT(status.message(),
              HasSubstr("layer 'words': feature 1: field 'h' is " + quoted +
                        ", not a number"));
}

TEST_F(OgrDatasetErrorTest, TheDriverOptionOpensWithThatDriverOnly) {
  Dataset d;
  ASSERT_TRUE(Load(geojson_ + "?driver=GeoJSON", &d).ok());
  EXPECT_EQ(d.points.size(), kPoints.size());
  ExpectError(
      geojson_ + "?driver=GPKG", Status::Code::kInvalidArgument,
      geojson_ + ": not a readable OGR vector source for driver 'GPKG'");
  ExpectError(geojson_ + "?driver=Nonesuch", Status::Code::kInvalidArgument,
              geojson_ + ": no GDAL driver 'Nonesuch' (driver=)");
}

}  // namespace
}  // namespace locator::gis
