#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>

#include "locator/dataset_sources.h"

namespace locator {
namespace {

// The message of `s`, which must be OK ("") or InvalidArgument.
std::string InvalidArgumentMessage(const Status& s) {
  if (!s.ok()) {
    EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
  }
  return s.message();
}

std::string XyzError(std::string_view text) {
  return InvalidArgumentMessage(ParseXyzText(text, "pts.csv").status());
}

std::string NodeError(std::string_view text) {
  return InvalidArgumentMessage(ParseNodeText(text, "pts.node").status());
}

std::string SpecError(const std::string& spec) {
  return InvalidArgumentMessage(LoadDataset(spec).status());
}

bool SamePoints(const Dataset& a, const Dataset& b) {
  if (a.points.size() != b.points.size()) return false;
  for (size_t i = 0; i < a.points.size(); ++i) {
    if (a.points[i].x != b.points[i].x || a.points[i].y != b.points[i].y) {
      return false;
    }
  }
  return true;
}

// Writes `contents` to a fresh file in the test temp dir; returns its path.
std::string WriteTempFile(const std::string& name,
                          const std::string& contents) {
  const std::string path = testing::TempDir() + "/dataset_test_" + name;
  std::ofstream(path, std::ios::binary) << contents;
  return path;
}

TEST(ParseXyzTextTest, TwoColumns) {
  StatusOr<Dataset> ds = ParseXyzText("1,2\n3.5,-4\n5e1,6", "pts.csv");
  ASSERT_TRUE(ds.ok());
  ASSERT_EQ(ds->points.size(), 3u);
  EXPECT_EQ(ds->points[1].x, 3.5);
  EXPECT_EQ(ds->points[1].y, -4);
  EXPECT_EQ(ds->points[2].x, 50);
  EXPECT_FALSE(ds->has_values());
}

TEST(ParseXyzTextTest, ThreeColumnsFillValues) {
  StatusOr<Dataset> ds = ParseXyzText("1,2,10\n3,4,20\n", "pts.csv");
  ASSERT_TRUE(ds.ok());
  ASSERT_EQ(ds->points.size(), 2u);
  ASSERT_EQ(ds->values.size(), 2u);
  EXPECT_EQ(ds->values[0], 10);
  EXPECT_EQ(ds->values[1], 20);
}

TEST(ParseXyzTextTest, SeparatorsCommentsBlankLinesCrlf) {
  const char* text =
      "# full-line comment\r\n"
      "\r\n"
      "1 2\t3\r\n"
      "  4 ,\t5,6   # trailing comment\r\n"
      "\t\n"
      "7\t\t8 , 9#tight comment\n"
      "+1e1 -2 1e-400\n";
  const StatusOr<Dataset> ds = ParseXyzText(text, "pts.csv");
  ASSERT_TRUE(ds.ok());
  ASSERT_EQ(ds->points.size(), 4u);
  EXPECT_EQ(ds->points[1].x, 4);
  EXPECT_EQ(ds->points[1].y, 5);
  EXPECT_EQ(ds->values[1], 6);
  EXPECT_EQ(ds->points[2].x, 7);
  EXPECT_EQ(ds->values[2], 9);
  EXPECT_EQ(ds->points[3].x, 10);  // leading '+'
  EXPECT_EQ(ds->values[3], 0);     // underflow is zero, not an error
}

TEST(ParseXyzTextTest, HeaderOnlyAsFirstContentLine) {
  StatusOr<Dataset> ds = ParseXyzText("# c\n\nx,y,z\n1,2,3\n", "pts.csv");
  ASSERT_TRUE(ds.ok());
  EXPECT_EQ(ds->points.size(), 1u);
  EXPECT_EQ(XyzError("x,y\nx,y\n1,2\n"), "pts.csv:2: 'x' is not a number");
  EXPECT_EQ(XyzError("1,2\nabc,3\n"), "pts.csv:2: 'abc' is not a number");
  // The first field decides: a number there makes it a data row.
  EXPECT_EQ(XyzError("1,y\n"), "pts.csv:1: 'y' is not a number");
}

TEST(ParseXyzTextTest, NotANumber) {
  EXPECT_EQ(XyzError("1,2\n3,4\n5,6\n7,8\n9,10\n11,12\n1.5x,2\n"),
            "pts.csv:7: '1.5x' is not a number");
  EXPECT_EQ(XyzError("1,2\n3,0x10\n"), "pts.csv:2: '0x10' is not a number");
}

TEST(ParseXyzTextTest, NonFinite) {
  EXPECT_EQ(XyzError("1,2\nnan,3\n"), "pts.csv:2: non-finite coordinate 'nan'");
  EXPECT_EQ(XyzError("1,inf\n"), "pts.csv:1: non-finite coordinate 'inf'");
  EXPECT_EQ(XyzError("1,2\n\n-inf,3\n"),
            "pts.csv:3: non-finite coordinate '-inf'");
  EXPECT_EQ(XyzError("1e400,2\n"), "pts.csv:1: non-finite coordinate '1e400'");
  EXPECT_EQ(XyzError("1,2,NaN\n"), "pts.csv:1: non-finite value 'NaN'");
}

TEST(ParseXyzTextTest, ColumnCounts) {
  EXPECT_EQ(XyzError("1,2\n3\n"), "pts.csv:2: expected 2 or 3 columns, got 1");
  EXPECT_EQ(XyzError("1 2 3 4 5\n"),
            "pts.csv:1: expected 2 or 3 columns, got 5");
  EXPECT_EQ(XyzError("x,y\n1,2\n3,4\n5,6,7\n"),
            "pts.csv:4: expected 2 columns like line 2, got 3");
  EXPECT_EQ(XyzError("1,2,3\n# c\n4,5\n"),
            "pts.csv:3: expected 3 columns like line 1, got 2");
}

TEST(ParseXyzTextTest, EmptyFields) {
  EXPECT_EQ(XyzError("1,,2\n"), "pts.csv:1: empty field");
  EXPECT_EQ(XyzError("1,2\n1,2,\n"), "pts.csv:2: empty field");
  EXPECT_EQ(XyzError(",1,2\n"), "pts.csv:1: empty field");
}

TEST(ParseXyzTextTest, EmptyDataset) {
  EXPECT_EQ(XyzError(""), "pts.csv: empty dataset (no points)");
  EXPECT_EQ(XyzError("# only\n\n  \n"), "pts.csv: empty dataset (no points)");
  EXPECT_EQ(XyzError("x,y,z\n"), "pts.csv: empty dataset (no points)");
}

TEST(ParseXyzTextTest, FewPointsAreNotTheParsersBusiness) {
  StatusOr<Dataset> ds = ParseXyzText("1,2\n", "pts.csv");
  EXPECT_TRUE(ds.ok());
  EXPECT_EQ(ds->points.size(), 1u);
}

TEST(ParseXyzTextTest, MaxPoints) {
  const DatasetLimits limits{.max_points = 2};
  EXPECT_TRUE(ParseXyzText("1,2\n3,4\n", "pts.csv", limits).ok());
  const Status s = ParseXyzText("1,2\n3,4\n5,6\n", "pts.csv", limits).status();
  EXPECT_EQ(s.code(), Status::Code::kResourceExhausted);
  EXPECT_EQ(s.message(), "pts.csv:3: more than 2 points (max_points limit)");
}

TEST(ParseNodeTextTest, Plain) {
  StatusOr<Dataset> ds = ParseNodeText(
      "# triangle\n3 2 0 0\n1 0 0\n2 1.5 0\n"
      "3 0 1 # last\n",
      "pts.node");
  ASSERT_TRUE(ds.ok());
  ASSERT_EQ(ds->points.size(), 3u);
  EXPECT_EQ(ds->points[1].x, 1.5);
  EXPECT_EQ(ds->points[2].y, 1);
  EXPECT_FALSE(ds->has_values());
}

TEST(ParseNodeTextTest, FirstAttributeIsValueMarkersIgnored) {
  StatusOr<Dataset> ds = ParseNodeText(
      "3 2 2 1\n0 0 0 5.5 9 1\n1 1 0 6.5 9 0\n"
      "2 0 1 7.5 9 1\n",
      "pts.node");
  ASSERT_TRUE(ds.ok());
  ASSERT_EQ(ds->values.size(), 3u);
  EXPECT_EQ(ds->values[0], 5.5);
  EXPECT_EQ(ds->values[2], 7.5);
  ds = ParseNodeText("2 2 0 1\n1 0 0 1\n2 1 1 0\n", "pts.node");
  ASSERT_TRUE(ds.ok());
  EXPECT_EQ(ds->points.size(), 2u);
  EXPECT_FALSE(ds->has_values());
}

TEST(ParseNodeTextTest, HeaderErrors) {
  EXPECT_EQ(NodeError("3 2 0\n"),
            "pts.node:1: expected header '<#points> <dim> <#attributes> "
            "<#markers>'");
  EXPECT_EQ(NodeError("# c\n3 3 0 0\n"),
            "pts.node:2: dimension must be 2, got 3");
  EXPECT_EQ(NodeError("3 2 0 2\n"),
            "pts.node:1: boundary marker count must be 0 or 1, got 2");
  EXPECT_EQ(NodeError("3 2 x 0\n"),
            "pts.node:1: 'x' is not a non-negative integer");
  EXPECT_EQ(NodeError("-3 2 0 0\n"),
            "pts.node:1: '-3' is not a non-negative integer");
  EXPECT_EQ(NodeError("0 2 0 0\n"), "pts.node: empty dataset (no points)");
  EXPECT_EQ(NodeError("# nothing\n"), "pts.node: empty dataset (no points)");
}

TEST(ParseNodeTextTest, PointErrors) {
  EXPECT_EQ(NodeError("3 2 1 0\n1 0 0 5\n2 1 0\n"),
            "pts.node:3: expected 4 fields (index x y, 1 attribute(s), 0 "
            "marker(s)) as declared on line 1, got 3");
  EXPECT_EQ(NodeError("3 2 0 0\n1 0 0\n2 1 0\n"),
            "pts.node:3: found only 2 of the 3 points declared on line 1");
  EXPECT_EQ(NodeError("2 2 0 0\n1 0 0\n2 1 0\n\n3 0 1\n"),
            "pts.node:5: more than the 2 points declared on line 1");
  EXPECT_EQ(NodeError("2 2 0 0\n1 0 0\n2 inf 0\n"),
            "pts.node:3: non-finite coordinate 'inf'");
  EXPECT_EQ(NodeError("1 2 1 0\n1 0 0 nan\n"),
            "pts.node:2: non-finite value 'nan'");
  EXPECT_EQ(NodeError("1 2 0 0\n1 0 y\n"), "pts.node:2: 'y' is not a number");
  EXPECT_EQ(NodeError("1 2 0 0\na 0 0\n"),
            "pts.node:2: 'a' is not an integer index");
}

TEST(ParseNodeTextTest, MaxPointsCheckedAgainstHeader) {
  const Status s = ParseNodeText("1000000000 2 0 0\n", "pts.node",
                                 DatasetLimits{.max_points = 10})
                       .status();
  EXPECT_EQ(s.code(), Status::Code::kResourceExhausted);
  EXPECT_EQ(s.message(), "pts.node:1: more than 10 points (max_points limit)");
}

TEST(LoadDatasetTest, CsvFile) {
  const std::string path = WriteTempFile("pts.csv", "x,y,z\n1,2,3\n4,5,6\n");
  StatusOr<Dataset> ds = LoadDataset(path);
  ASSERT_TRUE(ds.ok());
  EXPECT_EQ(ds->source, path);
  ASSERT_EQ(ds->points.size(), 2u);
  EXPECT_EQ(ds->points[1].x, 4);
  EXPECT_EQ(ds->values[1], 6);
}

TEST(LoadDatasetTest, NodeFileBySuffix) {
  // As CSV, "3 2 0 0" would be a 4-column error.
  const std::string path =
      WriteTempFile("pts.node", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n");
  StatusOr<Dataset> ds = LoadDataset(path);
  ASSERT_TRUE(ds.ok());
  EXPECT_EQ(ds->points.size(), 3u);
}

TEST(LoadDatasetTest, ParseErrorNamesThePath) {
  const std::string path = WriteTempFile("bad.csv", "1,2\n3,abc\n");
  EXPECT_EQ(SpecError(path), path + ":2: 'abc' is not a number");
}

TEST(LoadDatasetTest, MissingFileAndDirectory) {
  const std::string missing = testing::TempDir() + "/no_such_dataset.csv";
  Status s = LoadDataset(missing).status();
  EXPECT_EQ(s.code(), Status::Code::kNotFound);
  EXPECT_NE(s.message().find("'" + missing + "'"), std::string::npos)
      << s.message();

  const std::string dir = testing::TempDir() + "/dataset_test_dir";
  std::filesystem::create_directories(dir);
  s = LoadDataset(dir).status();
  EXPECT_EQ(s.code(), Status::Code::kIOError);
  EXPECT_NE(s.message().find("'" + dir + "'"), std::string::npos)
      << s.message();
}

TEST(LoadDatasetTest, GeneratorSpecs) {
  StatusOr<Dataset> ds = LoadDataset("uniform:100:7");
  ASSERT_TRUE(ds.ok());
  EXPECT_EQ(ds->source, "uniform:100:7");
  EXPECT_TRUE(SamePoints(*ds, GenerateUniform(100, 7)));
  ds = LoadDataset("uniform:50");
  ASSERT_TRUE(ds.ok());
  EXPECT_EQ(ds->points.size(), 50u);
  ds = LoadDataset("clusters:100:3:5");
  ASSERT_TRUE(ds.ok());
  EXPECT_EQ(ds->source, "clusters:100:3:5");
  EXPECT_TRUE(SamePoints(*ds, GenerateClusters(100, 3, 5)));
  ds = LoadDataset("clusters:100:4");
  ASSERT_TRUE(ds.ok());
  EXPECT_EQ(ds->points.size(), 100u);
}

TEST(LoadDatasetTest, BadSpecs) {
  EXPECT_EQ(SpecError("uniform:abc"),
            "bad dataset spec 'uniform:abc': N must be a positive integer");
  EXPECT_EQ(SpecError("uniform:0"),
            "bad dataset spec 'uniform:0': N must be a positive integer");
  EXPECT_EQ(SpecError("uniform:-3"),
            "bad dataset spec 'uniform:-3': N must be a positive integer");
  EXPECT_EQ(SpecError("uniform:1:2:3"),
            "bad dataset spec 'uniform:1:2:3': expected uniform:N[:SEED]");
  EXPECT_EQ(SpecError("uniform:10:x"),
            "bad dataset spec 'uniform:10:x': SEED must be an unsigned 64-bit "
            "integer");
  EXPECT_EQ(SpecError("clusters:10"),
            "bad dataset spec 'clusters:10': expected clusters:N:K[:SEED]");
  EXPECT_EQ(SpecError("clusters:10:0"),
            "bad dataset spec 'clusters:10:0': K must be a positive integer");
  EXPECT_EQ(SpecError("clusters:5:6"),
            "bad dataset spec 'clusters:5:6': K must not exceed N");
}

TEST(LoadDatasetTest, GeneratorMaxPoints) {
  const Status s =
      LoadDataset("uniform:1000", DatasetLimits{.max_points = 10}).status();
  EXPECT_EQ(s.code(), Status::Code::kResourceExhausted);
  EXPECT_EQ(s.message(),
            "uniform:1000: more than 10 points (max_points limit)");
}

TEST(GenerateUniformTest, DeterministicAndPortable) {
  const Dataset a = GenerateUniform(1000, 42);
  EXPECT_TRUE(SamePoints(a, GenerateUniform(1000, 42)));
  EXPECT_FALSE(SamePoints(a, GenerateUniform(1000, 43)));
  // mt19937_64's sequence is fixed by the standard and the mapping is exact,
  // so this holds on every platform.
  EXPECT_EQ(a.points[0].x, 0.75515553295453897);
  EXPECT_EQ(a.points[0].y, 0.63903139385469743);
  EXPECT_EQ(a.source, "uniform:1000:42");
  EXPECT_FALSE(a.has_values());
  for (const Point2& p : a.points) {
    ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1);
  }
}

TEST(GenerateClustersTest, DeterministicClusteredInUnitSquare) {
  const Dataset a = GenerateClusters(20000, 3, 9);
  EXPECT_TRUE(SamePoints(a, GenerateClusters(20000, 3, 9)));
  EXPECT_FALSE(SamePoints(a, GenerateClusters(20000, 3, 10)));
  EXPECT_EQ(a.source, "clusters:20000:3:9");
  EXPECT_FALSE(a.has_values());
  ASSERT_EQ(a.points.size(), 20000u);
  // Three blobs of sigma <= 0.06 touch far fewer of the 100 cells of a 10x10
  // grid than uniform points, which touch them all.
  std::set<std::pair<int, int>> cells;
  for (const Point2& p : a.points) {
    ASSERT_TRUE(p.x >= 0 && p.x <= 1 && p.y >= 0 && p.y <= 1);
    cells.insert({static_cast<int>(p.x * 10), static_cast<int>(p.y * 10)});
  }
  EXPECT_LT(cells.size(), 50u);
}

}  // namespace
}  // namespace locator

namespace locator {
namespace {

// A square with a square hole, numbered from 1, with a regional attribute.
constexpr char kSquareWithHole[] =
    "# outer square, inner square\n"
    "8 2 1 0\n"
    "1 0 0 10\n2 4 0 10\n3 4 4 10\n4 0 4 10\n"
    "5 1 1 20\n6 3 1 20\n7 3 3 20\n8 1 3 20\n"
    "8 0\n"
    "1 1 2\n2 2 3\n3 3 4\n4 4 1\n"
    "5 5 6\n6 6 7\n7 7 8\n8 8 5\n"
    "1\n"
    "1 2 2\n"
    "1\n"
    "1 0.5 0.5 7 0.1\n";

std::string PolyError(std::string_view text) {
  const Status s = ParsePolyText(text, "t.poly").status();
  EXPECT_FALSE(s.ok());
  return s.message();
}

TEST(ParsePolyTextTest, SegmentsHolesAndRegions) {
  const StatusOr<Dataset> ds = ParsePolyText(kSquareWithHole, "t.poly");
  ASSERT_TRUE(ds.ok()) << ds.status().ToString();
  ASSERT_EQ(ds->points.size(), 8u);
  EXPECT_EQ(ds->values[4], 20);
  ASSERT_EQ(ds->constraints.segments.size(), 8u);
  // Segment 4 is "5 5 6": points 5 and 6 numbered from 1.
  EXPECT_EQ(ds->constraints.segments[4].points[0].x, 1);
  EXPECT_EQ(ds->constraints.segments[4].points[1].x, 3);
  ASSERT_EQ(ds->constraints.hole_seeds.size(), 1u);
  EXPECT_EQ(ds->constraints.hole_seeds[0].x, 2);
  ASSERT_EQ(ds->constraints.regions.size(), 1u);
  EXPECT_EQ(ds->constraints.regions[0].attribute, 7);
}

TEST(ParsePolyTextTest, ErrorsNameFileAndLine) {
  EXPECT_EQ(PolyError("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 3\n0\n"),
            "t.poly:6: segment refers to point 3, which is not among the 3 "
            "points numbered from 0");
  EXPECT_EQ(PolyError("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n2 0\n0 0 1\n"),
            "t.poly:6: missing segment 1");
  EXPECT_EQ(PolyError("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n0 0\n1\n0 x 1\n"),
            "t.poly:7: 'x' is not a number");
  EXPECT_EQ(PolyError("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n0 0\n"),
            "t.poly:5: missing hole header '<#holes>'");
  EXPECT_EQ(PolyError("3 2 0 0\n0 0 0\n2 1 0\n2 0 1\n"),
            "t.poly:3: point index 2 out of sequence (expected 1)");
}

}  // namespace
}  // namespace locator
