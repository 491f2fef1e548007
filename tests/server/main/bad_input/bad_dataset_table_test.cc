// The bad-input table, part 2: datasets (the harness is dataset_table.h).
// One row per kind of point file, limit and GIS source an operator can hand
// locatord; domains and meshes are bad_domain_table_test.cc, requests part 1
// (bad_input_table_test.cc). All the GIS sources' errors are in
// tests/common/gis/ogr_dataset_test.cc.
//
// 10^7 points: with the default --max-dataset-points (10^7) locatord serves
// uniform:10000000 in ~40 s and ~1.8 GB resident on the 2-core CI machine,
// too slow and large for CI. The rows below exercise the limit itself
// (refused before anything is generated or triangulated, naming count and
// limit) and the memory accounting on 2*10^5 points.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/dataset/dataset_fingerprint.h"
#include "server/core/mesh/mesh_cache.h"
#include "server/core/mesh/mesh_file.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/server/main/bad_input/dataset_table.h"

namespace locator::test {
namespace {

// The corners of a tiny 5x5 grid at the origin (spacing 1e-300), points
// 1e300 away in every direction and a few in between: triangles whose sides
// differ by 600 orders of magnitude.
std::string HugeRangeCsv() {
  std::ostringstream csv;
  csv.precision(17);
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) csv << i * 1e-300 << "," << j * 1e-300 << "\n";
  }
  for (const double far : {1e300, -1e300}) {
    csv << far << ",0\n0," << far << "\n" << far << "," << far << "\n";
    csv << far << "," << -far << "\n";
  }
  csv << "1,1\n-2,3\n1e150,-3e150\n7e-150,5e-151\n";
  return csv.str();
}

// Queries at every scale of HugeRangeCsv, inside and outside its hull:
// located exactly (as CGAL does: Epick's predicates are exact for any
// finite doubles). Barycentric coordinates must be finite and sum to 1, even
// in needle triangles such as (1e150, -3e150), (7e-150, 5e-151), (4e-300,
// 0), whose area long double cannot resolve (Barycentric() then computes
// them exactly).
void ExpectHugeRangeAnswersAgreeWithCgal(const ServerProcess& server,
                                         const std::string& dataset) {
  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(dataset, &reference).ok());
  auto stub = NewStub(server);
  std::vector<Point2> queries;
  for (const double scale : {1e-300, 3e-200, 1e-100, 1.0, 1e100, 7e299}) {
    for (const Point2& unit : std::vector<Point2>{
             {0.5, 0.5}, {1.5, 2.5}, {-0.7, 0.2}, {3.0, -1.0}, {0.0, 0.0}}) {
      queries.push_back({unit.x * scale, unit.y * scale});
    }
  }
  queries.push_back({2e300, 2e300});
  queries.push_back({-1.5e308, 0});
  for (const Point2& q : queries) {
    v1::LocateResponse response;
    const grpc::Status status = LocateOne(*stub, q, &response);
    ASSERT_TRUE(status.ok()) << status.error_message();
    const LocateResult got = FromLocateResponse(response);
    const LocateResult want = reference->Locate(q);
    EXPECT_EQ(got.type, want.type) << q.x << ", " << q.y;
    EXPECT_TRUE(reference->Agrees(q, got, want)) << q.x << ", " << q.y;
    if (got.type == LocationType::kOutsideConvexHull) continue;
    const double sum =
        got.barycentric[0] + got.barycentric[1] + got.barycentric[2];
    EXPECT_NEAR(sum, 1, 1e-9) << q.x << ", " << q.y;
  }
}

void ExpectDuplicatesMerged(const ServerProcess& server,
                            const std::string& /*dataset*/) {
  auto stub = NewStub(server);
  const v1::GetStatsResponse stats = GetStats(*stub);
  EXPECT_EQ(stats.dataset().input_points(), 7u);
  EXPECT_EQ(stats.dataset().vertices(), 4u);
  EXPECT_EQ(stats.dataset().duplicates_merged(), 3u);
}

void ExpectMemoryAccounted(const ServerProcess& server,
                           const std::string& /*dataset*/) {
  auto stub = NewStub(server);
  const v1::GetStatsResponse stats = GetStats(*stub);
  const uint64_t points = stats.dataset().input_points();
  EXPECT_EQ(points, 200'000u);
  // The serving mesh: a point (16 bytes), its id (4), two triangles (48)
  // and a value if any (8): about 70-80 bytes.
  EXPECT_GE(stats.memory().triangulation_bytes(), 60 * points);
  EXPECT_LE(stats.memory().triangulation_bytes(), 100 * points);
  EXPECT_GT(stats.memory().tuning_bytes(), 0u);
}

// A GeoJSON FeatureCollection of one feature with `geometry`, or of none.
std::string GeoJson(const std::string& geometry) {
  std::string features;
  if (!geometry.empty()) {
    features =
        R"({"type":"Feature","properties":{},"geometry":)" + geometry + "}";
  }
  return R"({"type":"FeatureCollection","features":[)" + features + "]}";
}

// GeoJSON's CRS is WGS 84 unless the file says otherwise; with Z it is
// the 3D one, EPSG:4979, whose horizontal axes are in degrees.
void ExpectWgs84(const ServerProcess& server, const std::string& /*dataset*/) {
  auto stub = NewStub(server);
  const v1::GetStatsResponse stats = GetStats(*stub);
  EXPECT_EQ(stats.dataset().crs().epsg_code(), 4979u);
  EXPECT_EQ(stats.dataset().crs().name(), "WGS 84");
  EXPECT_THAT(stats.dataset().crs().axis_units(),
              ::testing::ElementsAre("degree", "degree"));
  EXPECT_EQ(stats.dataset().input_points(), 4u);
  EXPECT_TRUE(stats.dataset().has_values());
}

std::vector<DatasetRow> DatasetRows() {
  const auto xy = [](int i) {
    return std::to_string(i % 37) + "," + std::to_string(i / 37);
  };
  return {
      {"EmptyFile",
       "an empty file",
       "empty.csv",
       "",
       {},
       1,
       "{file}: empty dataset (no points)"},
      {"OnlyComments",
       "comments and blank lines only",
       "comments.csv",
       "# x,y\n\n   \n# nothing\n",
       {},
       1,
       "{file}: empty dataset (no points)"},
      {"Text",
       "prose instead of numbers",
       "text.csv",
       "hello world\nsome more text\n",
       {},
       1,
       "{file}:2: 'some' is not a number"},
      {"BadNumber",
       "a row with a word for a number",
       "bad_number.csv",
       "x,y\n1,2\n3,oops\n4,5\n",
       {},
       1,
       "{file}:3: 'oops' is not a number"},
      {"TooManyColumns",
       "a row of 4 columns",
       "four_columns.csv",
       "x,y\n1,2\n3,4,5,6\n",
       {},
       1,
       "{file}:3: expected 2 or 3 columns, got 4"},
      {"MixedColumns",
       "x,y,z rows, then an x,y row",
       "mixed_columns.csv",
       "1,2,3\n4,5,6\n7,8\n",
       {},
       1,
       "{file}:3: expected 3 columns like line 1, got 2"},
      {"NaNCoordinate",
       "a NaN coordinate",
       "nan.csv",
       "0,0\nnan,1\n2,2\n",
       {},
       1,
       "{file}:2: non-finite coordinate 'nan'"},
      {"OverflowingCoordinate",
       "1e309 (beyond double)",
       "overflow.csv",
       "0,0\n1e309,1\n2,2\n",
       {},
       1,
       "{file}:2: non-finite coordinate '1e309'"},
      {"TwoPoints",
       "fewer than 3 points",
       "two.csv",
       "0,0\n1,1\n",
       {},
       1,
       "'{file}': INVALID_ARGUMENT: dataset has 2 distinct point(s)"},
      {"TwoPointsRepeated",
       "5 rows, only 2 distinct points",
       "two_repeated.csv",
       "0,0\n1,1\n0,0\n1,1\n0,0\n",
       {},
       1,
       "dataset has 2 distinct point(s)"},
      {"Collinear",
       "all points on one line",
       "collinear.csv",
       "0,0\n1,1\n2,2\n3,3\n-1e6,-1e6\n",
       {},
       1,
       "'{file}': INVALID_ARGUMENT: all 5 distinct points are collinear"},
      {"NodeFileShort",
       "a .node file with fewer points than declared",
       "short.node",
       "5 2 0 0\n1 0 0\n2 1 0\n3 0 1\n",
       {},
       1,
       "{file}:4: found only 3 of the 5 points declared on line 1"},
      {"MissingFile",
       "a path that does not exist",
       "",
       "/no/such/dataset.csv",
       {},
       1,
       "cannot open dataset '/no/such/dataset.csv': No such file"},
      {"Duplicates",
       "7 rows, 4 distinct points (served, 3 merged)",
       "duplicates.csv",
       "0,0\n1,0\n0,1\n1,1\n0,0\n1,1\n1,1\n",
       {},
       0,
       "",
       ExpectDuplicatesMerged},
      {"HugeCoordinateRange",
       "points from 1e-300 apart to 1e300 away (served, exact)",
       "huge_range.csv",
       HugeRangeCsv(),
       {},
       0,
       "",
       ExpectHugeRangeAnswersAgreeWithCgal},
      {"FileOverPointLimit",
       "1001 points with --max-dataset-points 1000",
       "over_limit.csv",
       Lines(1001, xy),
       {"--max-dataset-points", "1000"},
       1,
       "{file}:1001: more than 1000 points (max_points limit) (see "
       "--max-dataset-points)"},
      {"TenMillionOverLimit",
       "uniform:10000000 with --max-dataset-points 1000000",
       "",
       "uniform:10000000:1",
       {"--max-dataset-points", "1000000"},
       1,
       "uniform:10000000:1: more than 1000000 points (max_points limit)"},
      {"GisMissingFile",
       "a GeoPackage that does not exist",
       "",
       "/nonexistent/survey.gpkg",
       {},
       1,
       "/nonexistent/survey.gpkg: no such file or directory"},
      {"GisUnreadable",
       "a .geojson file that is not GeoJSON",
       "broken.geojson",
       "{ this is not json",
       {},
       1,
       "{file}: not a readable OGR vector source"},
      {"GisLineInPointsLayer",
       "a GeoJSON LineString where points are expected",
       "line.geojson",
       GeoJson(R"({"type":"LineString","coordinates":[[0,0],[1,1]]})"),
       {},
       1,
       "'line': feature 0: a LINESTRING where points are expected (Point, "
       "MultiPoint)"},
      {"GisCorruptGeoPackage",
       "a GeoPackage of 2025 points with a corrupt page among its features",
       "hill.gpkg",
       "",
       {},
       1,
       "{file}: layer 'hill': feature number ",
       nullptr,
       {},
       "",
       [](const std::string& path) {
         gis::testing::UtmHillGeoPackage(
             45, std::filesystem::path(path).parent_path().string());
         gis::testing::CorruptMiddleDataPage(path);
       }},
      {"GisEmptyLayer",
       "a GeoJSON FeatureCollection without features",
       "empty.geojson",
       GeoJson(""),
       {},
       1,
       "'empty' has no features"},
      {"GisServedWithCrs",
       "GeoJSON points with Z (served; GetStats names its CRS, WGS 84)",
       "points.geojson",
       GeoJson(R"({"type":"MultiPoint","coordinates":[[0,0,1],[1,0,2],)"
               R"([0,1,3],[1,1,4]]})"),
       {},
       0,
       "",
       ExpectWgs84},
      {"MemoryAccounted",
       "uniform:200000 (served; GetStats has its bytes)",
       "",
       "uniform:200000:1",
       {},
       0,
       "",
       ExpectMemoryAccounted},
  };
}

// 50 points on a 7-column grid.
std::string MeshCacheCsv() {
  return Lines(50, [](int i) {
    return std::to_string(i % 7) + "," + std::to_string(i / 7);
  });
}

// The name of the mesh file of `csv` in a mesh cache.
std::string MeshFileNameOf(const std::string& csv) {
  const StatusOr<Dataset> dataset = ParseXyzText(csv, "mesh_cache.csv");
  EXPECT_TRUE(dataset.ok());
  return dataset.ok() ? MeshFilePath("", DatasetFingerprint(*dataset)) : "";
}

// A row serving MeshCacheCsv() with --mesh-cache beside a mesh file holding
// `contents`: the file is ignored for `reason`, the mesh is triangulated and
// the file written afresh.
DatasetRow BadMeshFileRow(const std::string& name, const std::string& input,
                          const std::string& contents,
                          const std::string& reason) {
  return {
      name,
      input,
      "mesh_cache.csv",
      MeshCacheCsv(),
      {"--mesh-cache", "{dir}"},
      0,
      "",
      [reason](const ServerProcess& server, const std::string&) {
        auto stub = NewStub(server);
        const v1::MeshCacheStats cache = GetStats(*stub).dataset().mesh_cache();
        EXPECT_FALSE(cache.mapped());
        EXPECT_THAT(cache.load_error(), ::testing::HasSubstr(reason));
        EXPECT_EQ(cache.save_error(), "");
        EXPECT_GT(std::filesystem::file_size(cache.path()),
                  kMeshFileHeaderBytes);
        EXPECT_THAT(server.StderrText(),
                    ::testing::HasSubstr("warning: ignoring the mesh file"));
      },
      {{MeshFileNameOf(MeshCacheCsv()), contents}}};
}

std::vector<DatasetRow> MeshCacheRows() {
  return {
      BadMeshFileRow("MeshFileTruncated", "a 10-byte mesh file", "not a mesh",
                     "shorter than the 256-byte header"),
      BadMeshFileRow("MeshFileForeign", "a file that is not a mesh file",
                     std::string(300, 'x'), "not a locator mesh file"),
  };
}

TEST_P(DatasetTableTest, RefusedNamingTheProblemOrServed) {
  RunRow(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Datasets, DatasetTableTest,
                         ::testing::ValuesIn(DatasetRows()), RowName);
INSTANTIATE_TEST_SUITE_P(MeshCache, DatasetTableTest,
                         ::testing::ValuesIn(MeshCacheRows()), RowName);

}  // namespace
}  // namespace locator::test
