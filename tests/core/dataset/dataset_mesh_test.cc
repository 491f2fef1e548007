// Meshes served as given: OFF and Triangle's .ele + .node, parsed exactly as
// written, every error naming its file and line, and served with exactly the
// given triangles in the domain.

#include <gtest/gtest.h>

#include <array>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "locator/dataset_sources.h"
#include "server/core/cgal/triangulation.h"
#include "tests/core/scratch_dir.h"

namespace locator {
namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

// A fan of three triangles around (0, 0), covering a pentagon.
constexpr std::string_view kLOff =
    "OFF\n"
    "# a fan\n"
    "5 3 0\n"
    "0 0 10\n"
    "2 0 20\n"
    "0 2 30\n"
    "2 1 40\n"
    "1 2 50\n"
    "3 0 1 3\n"
    "3 0 3 4\n"
    "3 0 4 2\n";

std::string OffError(std::string_view text) {
  const Status s = ParseOffText(text, "m.off").status();
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
  return s.message();
}

TEST(ParseOffTextTest, VerticesValuesAndFacesAsWritten) {
  const StatusOr<Dataset> parsed = ParseOffText(kLOff, "m.off");
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  const Dataset& ds = *parsed;
  ASSERT_EQ(ds.points.size(), 5u);
  EXPECT_EQ(ds.points[3].x, 2);
  EXPECT_EQ(ds.points[3].y, 1);
  EXPECT_EQ(ds.values, (std::vector<double>{10, 20, 30, 40, 50}));
  EXPECT_EQ(ds.constraints.triangles,
            (Triangles{{0, 1, 3}, {0, 3, 4}, {0, 4, 2}}));
}

TEST(ParseOffTextTest, CountsOnTheHeaderLineAndFaceColours) {
  const StatusOr<Dataset> parsed = ParseOffText(
      "OFF 3 1 3\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n", "m.off");
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  const Dataset& ds = *parsed;
  EXPECT_EQ(ds.values, (std::vector<double>{0, 0, 0}));
  EXPECT_EQ(ds.constraints.triangles, (Triangles{{0, 1, 2}}));
}

TEST(ParseOffTextTest, ErrorsNameFileAndLine) {
  const std::string kTriangle = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  EXPECT_EQ(OffError("PLY\n3 1 0\n"), "m.off:1: expected the header 'OFF'");
  EXPECT_EQ(OffError("OFF\n3 1\n"),
            "m.off:2: expected counts '<#vertices> <#faces> <#edges>'");
  EXPECT_EQ(OffError(kTriangle + "4 0 1 2 0\n"),
            "m.off:6: only triangles are served; face 0 has 4 corners");
  EXPECT_EQ(OffError(kTriangle + "3 0 1 3\n"),
            "m.off:6: face 0 refers to vertex 3, which is not among the 3 "
            "vertices numbered from 0");
  EXPECT_EQ(OffError(kTriangle + "3 0 1\n"),
            "m.off:6: face 0 lists 2 of its 3 corners");
  EXPECT_EQ(OffError(kTriangle), "m.off:5: missing face 0");
  EXPECT_EQ(OffError("OFF\n3 1 0\n0 0 0\n1 nan 0\n"),
            "m.off:4: non-finite coordinate 'nan'");
  EXPECT_EQ(OffError("OFF\n3 1 0\n0 0 0\n1 0\n"),
            "m.off:4: expected 3 fields for vertex 1 'x y z', got 2");
  EXPECT_EQ(OffError(kTriangle + "3 0 1 2\n3 0 1 2\n"),
            "m.off:7: unexpected line after the 1 faces");
  EXPECT_EQ(OffError(""), "m.off: empty dataset (no points)");
}

// The fan as Triangle writes it: nodes numbered from 1, one attribute (the
// value) and a boundary marker; the .ele with 6 nodes per triangle (only the
// corners count) and one attribute.
constexpr std::string_view kLNode =
    "5 2 1 1\n"
    "1 0 0 10 1\n"
    "2 2 0 20 1\n"
    "3 0 2 30 1\n"
    "4 2 1 40 1\n"
    "5 1 2 50 1\n";
constexpr std::string_view kLEle =
    "3 6 1\n"
    "1 1 2 4 9 9 9 0.5\n"
    "2 1 4 5 9 9 9 0.5\n"
    "3 1 5 3 9 9 9 0.5\n";

std::string EleError(std::string_view ele) {
  const Status s = ParseEleText(ele, "m.ele", kLNode, "m.node").status();
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << s.ToString();
  return s.message();
}

TEST(ParseEleTextTest, TrianglesNumberedLikeTheNodeFile) {
  const StatusOr<Dataset> parsed =
      ParseEleText(kLEle, "m.ele", kLNode, "m.node");
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  const Dataset& ds = *parsed;
  EXPECT_EQ(ds.points.size(), 5u);
  EXPECT_EQ(ds.values, (std::vector<double>{10, 20, 30, 40, 50}));
  EXPECT_EQ(ds.constraints.triangles,
            (Triangles{{0, 1, 3}, {0, 3, 4}, {0, 4, 2}}));
}

TEST(ParseEleTextTest, ErrorsNameFileAndLine) {
  EXPECT_EQ(EleError("1 3 0\n1 1 2 812\n"),
            "m.ele:2: triangle 0 refers to node 812, which is not among the 5 "
            "nodes numbered from 1 in m.node");
  EXPECT_EQ(EleError("1 4 0\n"),
            "m.ele:1: nodes per triangle must be 3 or 6, got 4");
  EXPECT_EQ(EleError("1 3\n"),
            "m.ele:1: expected header '<#triangles> <nodes per triangle> "
            "<#attributes>'");
  EXPECT_EQ(EleError("2 3 0\n1 1 2 4\n"), "m.ele:2: missing triangle 1");
  EXPECT_EQ(EleError("1 3 1\n1 1 2 4\n"),
            "m.ele:2: expected 5 fields (index, 3 nodes, 1 attribute(s)) as "
            "declared on line 1, got 4");
  EXPECT_EQ(EleError("1 3 0\n1 1 2 4\n2 1 4 5\n"),
            "m.ele:3: unexpected line after the 1 triangles");
  const Status node_error = ParseEleText("1 3 0\n1 1 2 3\n", "m.ele",
                                         "3 2 0 0\n1 0 0\n2 1 0\n", "m.node")
                                .status();
  EXPECT_EQ(node_error.message(),
            "m.node:3: found only 2 of the 3 points "
            "declared on line 1");
}

void WriteFile(const std::string& path, std::string_view text) {
  std::ofstream(path) << text;
}

TEST(LoadDatasetTest, EleReadsTheNodeFileBesideIt) {
  test::ScratchDir dir;
  WriteFile(dir.path() + "/l.ele", kLEle);
  const Status missing = LoadDataset(dir.path() + "/l.ele").status();
  EXPECT_EQ(missing.code(), Status::Code::kNotFound);
  EXPECT_NE(missing.message().find("node file of '" + dir.path() + "/l.ele' '" +
                                   dir.path() + "/l.node'"),
            std::string::npos)
      << missing.message();
  WriteFile(dir.path() + "/l.node", kLNode);
  const StatusOr<Dataset> ds = LoadDataset(dir.path() + "/l.ele");
  ASSERT_TRUE(ds.ok()) << ds.status().ToString();
  EXPECT_EQ(ds->constraints.triangles.size(), 3u);
  EXPECT_EQ(ds->source, dir.path() + "/l.ele");
}

// Writes `off` to a scratch file and builds its triangulation.
StatusOr<std::unique_ptr<Triangulation>> BuildOff(std::string_view off) {
  test::ScratchDir dir;
  const std::string path = dir.path() + "/mesh.off";
  WriteFile(path, off);
  const StatusOr<Dataset> loaded = LoadDataset(path);
  if (!loaded.ok()) return loaded.status();
  return Triangulation::Build(*loaded);
}

TEST(LoadDatasetTest, OffMeshIsServedAsGiven) {
  // An L of four triangles around (0, 0); its notch x > 1, y > 1 is inside
  // the convex hull (bounded by the edge (2 1)-(1 2)) but in no triangle.
  const StatusOr<std::unique_ptr<Triangulation>> built = BuildOff(
      "OFF\n6 4 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n"
      "3 0 1 2\n3 0 2 3\n3 0 3 4\n3 0 4 5\n");
  ASSERT_TRUE(built.ok()) << built.status().ToString();
  const Triangulation* t = built->get();
  EXPECT_EQ(t->num_triangles(), 4u);
  EXPECT_EQ(t->ReferenceLocate({1.4, 1.4}).type, LocationType::kOutsideDomain);
  EXPECT_EQ(t->ReferenceLocate({1.0, 0.25}).type, LocationType::kFace);
  EXPECT_EQ(t->ReferenceLocate({2, 1}).type, LocationType::kVertex);
}

TEST(LoadDatasetTest, NonManifoldOffIsRefused) {
  // Three triangles on the edge 0-1.
  const Status s = BuildOff(
                       "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 2 0\n"
                       "3 0 1 2\n3 0 1 3\n3 0 1 4\n")
                       .status();
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(s.message().find("mesh edge (0 1) is shared by triangles 0, 1 "
                             "and 2 (not a manifold)"),
            std::string::npos)
      << s.message();
}

}  // namespace
}  // namespace locator
