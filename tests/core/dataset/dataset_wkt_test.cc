// Constraints from WKT: a points file plus a WKT file of LINESTRING,
// POLYGON and MULTIPOLYGON geometries ("points.xyz+constraints.wkt"), parsed
// exactly as written, every error naming its file and line, and served with
// the polygons' holes out of the domain.

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/cgal/triangulation.h"
#include "tests/core/scratch_dir.h"

namespace locator {
namespace {

std::vector<double> Xs(const Polyline& line) {
  std::vector<double> xs;
  for (const Point2& p : line.points) xs.push_back(p.x);
  return xs;
}

std::string WktError(std::string_view text) {
  const Status s = ParseWktConstraints(text, "c.wkt").status();
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
  return s.message();
}

TEST(ParseWktConstraintsTest, LinesBecomeBreaklinesAndRingsDropTheirClosure) {
  const StatusOr<DatasetConstraints> parsed = ParseWktConstraints(
      "LINESTRING (0 0, 1 1, 2 0)\n"
      "polygon ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 2 1, 2 2, 1 1));\n"
      "MULTIPOLYGON (((10 10, 11 10, 11 11, 10 10)),"
      " ((20 20, 21 20, 21 21, 20 20)))\n"
      "MULTILINESTRING ((5 5, 6 6), (7 7, 8 8))\n"
      "GEOMETRYCOLLECTION (LINESTRING (9 9, 9.5 9), POLYGON EMPTY)\n"
      "LINESTRING EMPTY\n",
      "c.wkt");
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  const DatasetConstraints& c = *parsed;
  ASSERT_EQ(c.breaklines.size(), 4u);
  EXPECT_EQ(Xs(c.breaklines[0]), (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(Xs(c.breaklines[3]), (std::vector<double>{9, 9.5}));
  EXPECT_TRUE(c.breaklines[0].values.empty());
  ASSERT_EQ(c.rings.size(), 4u);
  EXPECT_EQ(Xs(c.rings[0]), (std::vector<double>{0, 4, 4, 0}));
  EXPECT_EQ(Xs(c.rings[1]), (std::vector<double>{1, 2, 2}));
  EXPECT_EQ(Xs(c.rings[3]), (std::vector<double>{20, 21, 21}));
  EXPECT_TRUE(c.segments.empty());
  EXPECT_TRUE(c.triangles.empty());
}

TEST(ParseWktConstraintsTest, ZIsTheValueAlongTheLine) {
  const StatusOr<DatasetConstraints> parsed = ParseWktConstraints(
      "LINESTRING Z (0 0 5, 1 1 6)\n"
      "LINESTRING (0 1 7, 1 0 8)\n",
      "c.wkt");
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  const DatasetConstraints& c = *parsed;
  EXPECT_EQ(c.breaklines[0].values, (std::vector<double>{5, 6}));
  EXPECT_EQ(c.breaklines[1].values, (std::vector<double>{7, 8}));
}

TEST(ParseWktConstraintsTest, ErrorsNameFileAndLine) {
  EXPECT_EQ(WktError(""), "c.wkt: no geometries");
  EXPECT_EQ(WktError("\n\nPOINT (1 2)"),
            "c.wkt:3: POINT is not a constraint: expected LINESTRING, "
            "MULTILINESTRING, POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION");
  EXPECT_EQ(WktError("LINESTRING (0 0,\n 1 x)"),
            "c.wkt:2: expected a coordinate, found 'x'");
  EXPECT_EQ(WktError("LINESTRING (0 0, 1 nan)"),
            "c.wkt:1: non-finite coordinate 'nan'");
  EXPECT_EQ(WktError("LINESTRING (0 0, 1 1e999)"),
            "c.wkt:1: non-finite coordinate '1e999'");
  EXPECT_EQ(WktError("LINESTRING (0 0)"),
            "c.wkt:1: a LINESTRING needs at least 2 points");
  EXPECT_EQ(WktError("LINESTRING (0 0, 1 1 1)"),
            "c.wkt:1: a point with 3 coordinates among points with 2");
  EXPECT_EQ(WktError("LINESTRING Z (0 0, 1 1)"),
            "c.wkt:1: a point with 2 coordinates among points with 3");
  EXPECT_EQ(WktError("LINESTRING M (0 0 1, 1 1 1)"),
            "c.wkt:1: LINESTRING M: only 2D and Z coordinates are supported");
  EXPECT_EQ(WktError("LINESTRING (0 0, 1 1"),
            "c.wkt:1: expected ',' or ')' after a point, found the end of "
            "the file");
  EXPECT_EQ(WktError("POLYGON ((0 0, 1 0, 1 1, 0 1))"),
            "c.wkt:1: the exterior ring is not closed: its last point "
            "differs from its first");
  EXPECT_EQ(WktError("POLYGON ((0 0, 1 0, 0 0))"),
            "c.wkt:1: the exterior ring has 3 point(s); a ring needs at least "
            "4 (the first repeated last)");
  EXPECT_EQ(WktError("POLYGON ((0 0, 4 0, 4 4, 0 0),\n"
                     "         (5 5, 6 5, 6 6, 5 5))"),
            "c.wkt:2: interior ring 1 (a hole) is not inside the exterior "
            "ring: its point 0 is outside");
  EXPECT_EQ(WktError("LINESTRING (0 0, 1 1)\n(2 2)"),
            "c.wkt:2: expected a geometry (LINESTRING, POLYGON, "
            "MULTIPOLYGON, ...), found '('");
  EXPECT_EQ(WktError("LINESTRING (0 0, 1 1) junk"),
            "c.wkt:1: junk is not a constraint: expected LINESTRING, "
            "MULTILINESTRING, POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION");
}

TEST(SplitWktConstraintsSpecTest, SplitsAtTheLastPlus) {
  std::string_view points;
  std::string_view wkt;
  ASSERT_TRUE(
      SplitWktConstraintsSpec("/d/a+b/pts.xyz+lakes.wkt", &points, &wkt));
  EXPECT_EQ(points, "/d/a+b/pts.xyz");
  EXPECT_EQ(wkt, "lakes.wkt");
  EXPECT_FALSE(SplitWktConstraintsSpec("lakes.wkt", &points, &wkt));
  EXPECT_FALSE(SplitWktConstraintsSpec("a+b.csv", &points, &wkt));
  EXPECT_FALSE(SplitWktConstraintsSpec("pts.xyz+.wkt", &points, &wkt));
}

void WriteFile(const std::string& path, std::string_view text) {
  std::ofstream(path) << text;
}

// A 5x5 grid of points with values x + y, and a lake: the square
// (1.5, 1.5)-(2.5, 2.5) as a hole of the grid's outline.
TEST(LoadDatasetTest, PointsPlusWktServeTheLakeAsAHole) {
  test::ScratchDir dir;
  std::string grid;
  for (int x = 0; x <= 4; ++x) {
    for (int y = 0; y <= 4; ++y) {
      grid += std::to_string(x) + "," + std::to_string(y) + "," +
              std::to_string(x + y) + "\n";
    }
  }
  WriteFile(dir.path() + "/grid.csv", grid);
  WriteFile(dir.path() + "/lake.wkt",
            "POLYGON Z ((0 0 0, 4 0 4, 4 4 8, 0 4 4, 0 0 0),\n"
            "  (1.5 1.5 3, 2.5 1.5 4, 2.5 2.5 5, 1.5 2.5 4, 1.5 1.5 3))\n");
  const std::string spec = dir.path() + "/grid.csv+" + dir.path() + "/lake.wkt";
  const StatusOr<Dataset> loaded = LoadDataset(spec);
  ASSERT_TRUE(loaded.ok()) << loaded.status().ToString();
  const Dataset& ds = *loaded;
  EXPECT_EQ(ds.source, spec);
  EXPECT_EQ(ds.points.size(), 25u);
  EXPECT_EQ(ds.constraints.rings.size(), 2u);
  const StatusOr<std::unique_ptr<Triangulation>> built =
      Triangulation::Build(ds);
  ASSERT_TRUE(built.ok()) << built.status().ToString();
  const Triangulation* t = built->get();
  EXPECT_EQ(t->ReferenceLocate({2, 2}).type, LocationType::kOutsideDomain);
  const LocateResult land = t->ReferenceLocate({0.5, 0.25});
  ASSERT_EQ(land.type, LocationType::kFace);
  EXPECT_NEAR(land.value, 0.75, 1e-12);
  // On the lake shore: a vertex of the ring, with its z.
  const LocateResult shore = t->ReferenceLocate({1.5, 1.5});
  EXPECT_EQ(shore.type, LocationType::kVertex);
  EXPECT_EQ(shore.value, 3);
}

TEST(LoadDatasetTest, MissingWktFileIsNamed) {
  const Status s = LoadDataset("uniform:100:1+/no/such/lake.wkt").status();
  EXPECT_EQ(s.code(), Status::Code::kNotFound) << s.ToString();
  EXPECT_NE(s.message().find("constraints '/no/such/lake.wkt'"),
            std::string::npos)
      << s.message();
}

}  // namespace
}  // namespace locator
