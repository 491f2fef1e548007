// The bad-input table, part 3: breaklines, domains and meshes (the harness
// is dataset_table.h). Every invalid domain or mesh is refused with a message
// that names the file and line (a parse error), or the dataset and the ring,
// hole point, triangle or edge at fault (a domain or mesh that cannot be
// served as given); a valid one is served with its holes answering
// OUTSIDE_DOMAIN.

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "tests/server/main/bad_input/dataset_table.h"

namespace locator::test {
namespace {

// A 5x5 grid of points on [0, 4]^2 with values TestValue (2x + 3y + 1,
// which linear interpolation reproduces exactly).
std::string GridCsv() {
  return Lines(25, [](int i) {
    const int x = i % 5;
    const int y = i / 5;
    return std::to_string(x) + "," + std::to_string(y) + "," +
           std::to_string(2 * x + 3 * y + 1);
  });
}

// The square [0, 4]^2 as a .poly outline with the given hole section
// ("<#holes>" and its rows).
std::string SquarePoly(const std::string& holes) {
  return "4 2 1 0\n1 0 0 1\n2 4 0 9\n3 4 4 21\n4 0 4 13\n"
         "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n" +
         holes;
}

// Terrain: the square [0, 4]^2 with a square lake (1.5, 1.5)-(2.5, 2.5)
// bounded by segments and marked by a hole point; values TestValue.
constexpr char kTerrainPoly[] =
    "8 2 1 0\n"
    "1 0 0 1\n2 4 0 9\n3 4 4 21\n4 0 4 13\n"
    "5 1.5 1.5 8.5\n6 2.5 1.5 10.5\n7 2.5 2.5 13.5\n8 1.5 2.5 11.5\n"
    "8 0\n"
    "1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
    "5 5 6\n6 6 7\n7 7 8\n8 8 5\n"
    "1\n1 2 2\n";

// The same lake as a WKT polygon with z, and a breakline along y = 1.
constexpr char kLakeWkt[] =
    "POLYGON Z ((0 0 1, 4 0 9, 4 4 21, 0 4 13, 0 0 1),\n"
    "  (1.5 1.5 8.5, 2.5 1.5 10.5, 2.5 2.5 13.5, 1.5 2.5 11.5, "
    "1.5 1.5 8.5))\n"
    "LINESTRING (0 1, 4 1)\n";

// Every answer on a 0.25 grid over [-0.5, 4.5]^2 agrees with CGAL's
// locate() on the same constrained triangulation, the lake answers
// OUTSIDE_DOMAIN without a value, and GetStats counts the lake.
void ExpectLakeAnswersAgreeWithCgal(const ServerProcess& server,
                                    const std::string& dataset) {
  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(dataset, &reference).ok());
  auto stub = NewStub(server);
  std::vector<Point2> queries;
  std::vector<LocateResult> answers;
  for (double x = -0.5; x <= 4.5; x += 0.25) {
    for (double y = -0.5; y <= 4.5; y += 0.25) {
      v1::LocateResponse response;
      const grpc::Status status = LocateOne(*stub, {x, y}, &response);
      ASSERT_TRUE(status.ok()) << status.error_message();
      queries.push_back({x, y});
      answers.push_back(FromLocateResponse(response));
    }
  }
  EXPECT_EQ(reference->Disagreements(queries, answers, true), "");
  v1::LocateResponse lake;
  ASSERT_TRUE(LocateOne(*stub, {2, 2.2}, &lake).ok());
  EXPECT_EQ(lake.type(), v1::LOCATION_TYPE_OUTSIDE_DOMAIN);
  EXPECT_FALSE(lake.has_value());
  const v1::GetStatsResponse stats = GetStats(*stub);
  EXPECT_EQ(stats.dataset().holes(), 1u);
  EXPECT_GE(stats.dataset().constraints(), 8u);
}

// What locatord says of a dataset it parsed but cannot serve.
std::string CannotServe(const std::string& spec, const std::string& problem) {
  return "cannot serve dataset '" + spec + "': INVALID_ARGUMENT: " + problem;
}

// An OFF mesh of the points (0, 0), (1, 0), (0, 1), (2, 0) and the faces
// "3 0 1 2" and `second_face`.
std::string OffWithSecondFace(const std::string& second_face) {
  return "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n2 0 0\n3 0 1 2\n" + second_face +
         "\n";
}

std::vector<DatasetRow> DomainRows() {
  return {
      {.name = "SelfIntersectingBoundary",
       .input = "a bow-tie polygon as the domain",
       .file_name = "grid.csv",
       .contents = GridCsv(),
       .exit_code = 1,
       .message = CannotServe("{file}+{dir}/bowtie.wkt",
                              "segment 0 of the exterior ring at "
                              "{dir}/bowtie.wkt:2 and segment 2 of the "
                              "exterior ring at {dir}/bowtie.wkt:2 cross at "
                              "(2, 2): a domain boundary must not intersect "
                              "itself"),
       .more_files = {{"bowtie.wkt",
                       "\nPOLYGON ((0 0, 4 4, 4 0, 0 4, 0 0))\n"}},
       .spec = "{file}+{dir}/bowtie.wkt"},
      {.name = "SelfIntersectingPoly",
       .input = "a .poly whose segments 1 and 3 cross",
       .file_name = "bowtie.poly",
       .contents = "4 2 1 0\n1 0 0 1\n2 4 4 21\n3 4 0 9\n4 0 4 13\n"
                   "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n",
       .exit_code = 1,
       .message = CannotServe("{file}",
                              "segment 1 at {file}:7 and segment 3 at "
                              "{file}:9 cross at (2, 2): a domain boundary "
                              "must not intersect itself")},
      {.name = "PolyDiagonalsCrossAtAPoint",
       .input = "a .poly square with diagonals, numbered 9 and 10, crossing "
                "at a node",
       .file_name = "diagonals.poly",
       .contents = "# a square and its centre\n"
                   "5 2 1 0\n1 0 0 1\n2 4 0 9\n3 4 4 21\n4 0 4 13\n"
                   "5 2 2 11\n"
                   "6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
                   "# the diagonals\n"
                   "9 1 3\n10 2 4\n0\n",
       .exit_code = 1,
       .message = CannotServe("{file}",
                              "segment 9 at {file}:14 and segment 10 at "
                              "{file}:15 cross at (2, 2): a domain boundary "
                              "must not intersect itself")},
      {.name = "HoleOutsideBoundary",
       .input = "a polygon whose hole is outside its exterior ring",
       .file_name = "grid.csv",
       .contents = GridCsv(),
       .exit_code = 1,
       .message = "{dir}/lake.wkt:2: interior ring 1 (a hole) is not inside "
                  "the exterior ring: its point 0 is outside",
       .more_files = {{"lake.wkt",
                       "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0),\n"
                       "  (5 5, 6 5, 6 6, 5 5))\n"}},
       .spec = "{file}+{dir}/lake.wkt"},
      {.name = "HolePointOutsideEveryRing",
       .input = "a .poly hole point outside the boundary",
       .file_name = "far_hole.poly",
       .contents = SquarePoly("1\n1 9 9\n"),
       .exit_code = 1,
       .message = CannotServe("{file}",
                              "hole point 0 (9, 9) is outside every region "
                              "bounded by the rings and segments")},
      {.name = "EleMissingNodeFile",
       .input = "a .ele without its .node",
       .file_name = "mesh.ele",
       .contents = "1 3 0\n1 1 2 3\n",
       .exit_code = 1,
       .message = "cannot open node file of '{file}' '{dir}/mesh.node'"},
      {.name = "EleMissingNode",
       .input = "a .ele triangle naming a node the .node does not have",
       .file_name = "mesh.ele",
       .contents = "1 3 0\n1 1 2 4\n",
       .exit_code = 1,
       .message = "{file}:2: triangle 0 refers to node 4, which is not among "
                  "the 3 nodes numbered from 1 in {dir}/mesh.node",
       .more_files = {{"mesh.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"}}},
      {.name = "NonManifoldMesh",
       .input = "an OFF mesh with three triangles on one edge",
       .file_name = "fan.off",
       .contents = "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 2 0\n"
                   "3 0 1 2\n3 0 1 3\n3 0 1 4\n",
       .exit_code = 1,
       .message = CannotServe("{file}",
                              "mesh edge (0 1) is shared by triangles 0, 1 "
                              "and 2 (not a manifold)")},
      {.name = "OverlappingMesh",
       .input = "an OFF mesh whose two triangles overlap",
       .file_name = "overlap.off",
       .contents = "OFF\n6 2 0\n0 0 0\n2 0 0\n0 2 0\n1 -1 0\n1 1.5 0\n3 1 0\n"
                   "3 0 1 2\n3 3 5 4\n",
       .exit_code = 1,
       .message = CannotServe("{file}",
                              "mesh edge (0 1) of triangle 0 and mesh edge "
                              "(3 4) of triangle 1 cross at (1, 0): the "
                              "mesh's triangles overlap")},
      {.name = "MeshRepeatedCorners",
       .input = "an OFF mesh with a triangle naming one vertex twice",
       .file_name = "repeated.off",
       .contents = OffWithSecondFace("3 0 0 1"),
       .exit_code = 1,
       .message = CannotServe("{file}",
                              "mesh triangle 1 (0 0 1) has repeated corners")},
      {.name = "MeshCollinearCorners",
       .input = "an OFF mesh with a triangle on three collinear vertices",
       .file_name = "collinear.off",
       .contents = OffWithSecondFace("3 0 1 3"),
       .exit_code = 1,
       .message = CannotServe("{file}",
                              "mesh triangle 1 (0 1 3) has collinear corners")},
      {.name = "MeshIndexOutOfRange",
       .input = "an OFF face naming a vertex the file does not have",
       .file_name = "out_of_range.off",
       .contents = OffWithSecondFace("3 0 1 7"),
       .exit_code = 1,
       .message = "{file}:8: face 1 refers to vertex 7, which is not among "
                  "the 4 vertices numbered from 0"},
      {.name = "EmptyDomain",
       .input = "a .poly whose only region is a hole",
       .file_name = "all_hole.poly",
       .contents = SquarePoly("1\n1 2 2\n"),
       .exit_code = 1,
       .message = CannotServe(
           "{file}",
           "the domain is empty: no triangle is inside its boundary")},
      {.name = "WktSyntax",
       .input = "a WKT file with a word for a coordinate",
       .file_name = "grid.csv",
       .contents = GridCsv(),
       .exit_code = 1,
       .message = "{dir}/lines.wkt:2: expected ',' or ')' after a point, "
                  "found 'x'",
       .more_files = {{"lines.wkt",
                       "LINESTRING (0 0, 1 1)\nLINESTRING (0 1 x)\n"}},
       .spec = "{file}+{dir}/lines.wkt"},
      {.name = "TerrainPolyServed",
       .input = "a .poly terrain with a lake (served)",
       .file_name = "terrain.poly",
       .contents = kTerrainPoly,
       .exit_code = 0,
       .check = ExpectLakeAnswersAgreeWithCgal},
      {.name = "PointsPlusWktServed",
       .input = "points plus a WKT lake and breakline (served)",
       .file_name = "grid.csv",
       .contents = GridCsv(),
       .exit_code = 0,
       .check = ExpectLakeAnswersAgreeWithCgal,
       .more_files = {{"lake.wkt", kLakeWkt}},
       .spec = "{file}+{dir}/lake.wkt"},
  };
}

TEST_P(DatasetTableTest, RefusedNamingTheProblemOrServed) {
  RunRow(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Domains, DatasetTableTest,
                         ::testing::ValuesIn(DomainRows()), RowName);

}  // namespace
}  // namespace locator::test
