// The `locator` CLI's output formats, without a server: text, JSON and the
// CSV rows of `locator batch`.

#include "client/cli_format.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "tests/client/fake_locator_server.h"

namespace locator {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(CliFormatTest, FormatDoubleIsShortestAndReadsBackExactly) {
  EXPECT_EQ(FormatDouble(0.1), "0.1");
  EXPECT_EQ(FormatDouble(1e-07), "1e-07");
  EXPECT_EQ(FormatDouble(-2.5), "-2.5");
  EXPECT_EQ(FormatDouble(3), "3");
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> any(-1e6, 1e6);
  for (int i = 0; i < 1000; ++i) {
    const double value = any(rng);
    EXPECT_EQ(std::strtod(FormatDouble(value).c_str(), nullptr), value);
  }
}

TEST(CliFormatTest, LocationTypeNameDropsThePrefix) {
  EXPECT_EQ(LocationTypeName(v1::LOCATION_TYPE_FACE), "FACE");
  EXPECT_EQ(LocationTypeName(v1::LOCATION_TYPE_EDGE), "EDGE");
  EXPECT_EQ(LocationTypeName(v1::LOCATION_TYPE_VERTEX), "VERTEX");
  EXPECT_EQ(LocationTypeName(v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL),
            "OUTSIDE_CONVEX_HULL");
  // A value newer than this client: its number.
  EXPECT_EQ(LocationTypeName(static_cast<v1::LocationType>(77)), "77");
}

v1::LocateResponse FaceAnswer() {
  v1::LocateResponse response;
  response.set_type(v1::LOCATION_TYPE_FACE);
  response.set_triangle_id(42);
  const double corners[3][2] = {{0, 0}, {1, 0}, {0, 1}};
  for (int i = 0; i < 3; ++i) {
    response.add_vertex_ids(10 + i);
    v1::Point* vertex = response.add_vertices();
    vertex->set_x(corners[i][0]);
    vertex->set_y(corners[i][1]);
  }
  for (double b : {0.5, 0.25, 0.25}) response.add_barycentric(b);
  response.set_value(1.75);
  response.mutable_cost()->set_faces_visited(3);
  response.mutable_cost()->set_comparisons(4);
  response.mutable_cost()->set_table_lookups(1);
  response.mutable_cost()->set_total(8);
  return response;
}

TEST(CliFormatTest, FormatLocateShowsEveryPart) {
  EXPECT_EQ(FormatLocate(FaceAnswer()),
            "type         FACE\n"
            "triangle     42\n"
            "vertices     10 (0, 0)\n"
            "             11 (1, 0)\n"
            "             12 (0, 1)\n"
            "barycentric  0.5 0.25 0.25\n"
            "value        1.75\n"
            "cost         8 (3 faces visited, 4 comparisons, 1 table "
            "lookups)\n");
}

TEST(CliFormatTest, FormatLocateOutsideTheHull) {
  v1::LocateResponse response;
  response.set_type(v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL);
  response.set_triangle_id(7);
  response.add_hull_edge_vertex_ids(3);
  response.add_hull_edge_vertex_ids(4);
  const std::string text = FormatLocate(response);
  EXPECT_THAT(text, HasSubstr("type         OUTSIDE_CONVEX_HULL\n"));
  EXPECT_THAT(text, HasSubstr("hull edge    3 4\n"));
  EXPECT_THAT(text, HasSubstr("barycentric  none (outside the convex hull)\n"));
  EXPECT_THAT(text, HasSubstr("value        none\n"));
}

TEST(CliFormatTest, FormatLocateOutsideTheDomainNamesNoTriangle) {
  v1::LocateResponse response;
  response.set_type(v1::LOCATION_TYPE_OUTSIDE_DOMAIN);
  response.set_triangle_id(-1);
  for (int i = 0; i < 3; ++i) {
    response.add_vertex_ids(-1);
    response.add_vertices();
  }
  response.add_domain_edge_vertex_ids(4);
  response.add_domain_edge_vertex_ids(5);
  response.mutable_cost()->set_faces_visited(2);
  response.mutable_cost()->set_total(2);
  EXPECT_EQ(FormatLocate(response),
            "type         OUTSIDE_DOMAIN\n"
            "domain edge  4 5\n"
            "barycentric  none (outside the domain: in a hole or beyond its "
            "boundary)\n"
            "value        none\n"
            "cost         2 (2 faces visited, 0 comparisons, 0 table "
            "lookups)\n");
}

TEST(CliFormatTest, MessageToJsonUsesProtoNamesAndPrintsDefaults) {
  v1::LocateResponse response;
  response.set_triangle_id(5);
  const std::string json = MessageToJson(response);
  EXPECT_THAT(json, HasSubstr("\"triangle_id\":\"5\""));
  // Defaults too: the unset enum and the empty lists.
  EXPECT_THAT(json, HasSubstr("\"type\":\"LOCATION_TYPE_UNSPECIFIED\""));
  EXPECT_THAT(json, HasSubstr("\"vertex_ids\":[]"));
  EXPECT_EQ(json.back(), '\n');
  EXPECT_EQ(json.find('\n'), json.size() - 1);  // one line
}

TEST(CliFormatTest, FormatStatsRedactedSourceAndReloadInProgress) {
  v1::GetStatsResponse stats;
  stats.set_generation(3);
  stats.set_reload_in_progress(true);
  stats.set_strategy("self-tuning");
  stats.mutable_memory()->set_triangulation_bytes(3 * 1024 * 1024 / 2);
  const std::string text = FormatStats(stats);
  EXPECT_THAT(text, HasSubstr("dataset      (redacted)\n"));
  EXPECT_THAT(text, HasSubstr("crs          none\n"));
  EXPECT_THAT(text, HasSubstr("generation   3 (reload in progress)\n"));
  EXPECT_THAT(text, HasSubstr("strategy     self-tuning\n"));
  EXPECT_THAT(text, HasSubstr("memory       1.5 MiB triangulation, 0.0 MiB"));
}

TEST(CliFormatTest, FormatStatsNamesTheCrs) {
  v1::GetStatsResponse stats;
  stats.mutable_dataset()->mutable_crs()->set_name("WGS 84 / UTM zone 33N");
  stats.mutable_dataset()->mutable_crs()->set_epsg_code(32633);
  EXPECT_THAT(FormatStats(stats),
              HasSubstr("crs          WGS 84 / UTM zone 33N (EPSG:32633)\n"));
}

TEST(CliFormatTest, FormatStatsShowsTheSimplificationCertificate) {
  v1::GetStatsResponse stats;
  EXPECT_THAT(FormatStats(stats), Not(HasSubstr("simplified")));
  v1::SimplificationStats* s =
      stats.mutable_dataset()->mutable_simplification();
  s->set_source_samples(1000000);
  s->set_vertices(5123);
  s->set_triangles(10100);
  s->set_max_error(0.4875);
  s->set_target_error(0.5);
  s->set_build_seconds(1.25);
  EXPECT_THAT(
      FormatStats(stats),
      HasSubstr("simplified   1000000 samples to 5123 vertices, 10100 "
                "triangles in 1.25 s; max error 0.4875 (target 0.5)\n"));
  s->set_max_points(6000);
  s->set_unserved_samples(3);
  EXPECT_THAT(FormatStats(stats),
              HasSubstr("(target 0.5, max_points 6000); 3 samples outside the "
                        "domain\n"));
}

TEST(CliFormatTest, BatchCsvRowsLeaveInapplicableCellsEmpty) {
  v1::LocateBatchResponse response;
  response.add_types(v1::LOCATION_TYPE_FACE);
  response.add_types(v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL);
  response.add_triangle_ids(42);
  response.add_triangle_ids(7);
  for (int64_t id : {10, 11, 12, 3, 4, -1}) response.add_vertex_ids(id);
  for (double b : {0.5, 0.25, 0.25, 0.0, 0.0, 0.0}) response.add_barycentric(b);
  response.add_values(1.75);
  response.add_values(std::numeric_limits<double>::quiet_NaN());
  response.add_costs(8);
  response.add_costs(2);
  const std::vector<double> xs = {0.25, 5};
  const std::vector<double> ys = {0.25, -1e-07};
  std::string csv = BatchCsvHeader();
  AppendBatchCsvRows(xs, ys, response, &csv);
  EXPECT_EQ(csv,
            "x,y,type,triangle_id,v0,v1,v2,b0,b1,b2,value,cost\n"
            "0.25,0.25,FACE,42,10,11,12,0.5,0.25,0.25,1.75,8\n"
            "5,-1e-07,OUTSIDE_CONVEX_HULL,7,3,4,-1,,,,,2\n");
}

TEST(CliFormatTest, FormatFixedAndProfilePointKindName) {
  EXPECT_EQ(FormatFixed(0.4249, 2), "0.42");
  EXPECT_EQ(FormatFixed(12, 1), "12.0");
  EXPECT_EQ(FormatFixed(1e300, 2), "1e+300");  // too long: the shortest form
  EXPECT_EQ(ProfilePointKindName(v1::PROFILE_POINT_KIND_LINE_VERTEX),
            "LINE_VERTEX");
  EXPECT_EQ(ProfilePointKindName(v1::PROFILE_POINT_KIND_EDGE_CROSSING),
            "EDGE_CROSSING");
  EXPECT_EQ(ProfilePointKindName(v1::PROFILE_POINT_KIND_MESH_VERTEX),
            "MESH_VERTEX");
  EXPECT_EQ(ProfilePointKindName(v1::PROFILE_POINT_KIND_SAMPLE), "SAMPLE");
  EXPECT_EQ(ProfilePointKindName(static_cast<v1::ProfilePointKind>(9)), "9");
}

TEST(CliFormatTest, FormatDatasetsIsOneLinePerDataset) {
  // terrain (default, EPSG:32633) and bedrock (loading), then two more.
  v1::ListDatasetsResponse response = test::FakeDatasetList();
  v1::DatasetEntry* plain = response.add_datasets();
  plain->set_name("plain");
  plain->set_serving(true);
  plain->mutable_stats()->set_input_points(1000000);
  plain->mutable_stats()->set_triangles(1999980);
  v1::DatasetEntry* custom = response.add_datasets();
  custom->set_name("custom");
  custom->set_serving(true);
  custom->mutable_stats()->mutable_crs()->set_name("unnamed");
  EXPECT_EQ(FormatDatasets(response),
            "name     default  serving       points   triangles  crs\n"
            "terrain  *        yes           225      416        WGS 84 / UTM "
            "zone 33N (EPSG:32633)\n"
            "bedrock           no (loading)  -        -          -\n"
            "plain             yes           1000000  1999980    none\n"
            "custom            yes           0        0          unnamed\n");
  EXPECT_EQ(FormatDatasets(v1::ListDatasetsResponse()),
            "name  default  serving  points  triangles  crs\n");
}

// A line from (0, 0) to (30, 0): a breakpoint at 10, a gap from 20 on.
v1::ProfileResponse TestProfile(bool with_samples) {
  v1::ProfileResponse response;
  response.set_length(30);
  response.set_crossings(2);
  const auto add = [](google::protobuf::RepeatedPtrField<v1::ProfilePoint>* to,
                      v1::ProfilePointKind kind, double distance,
                      std::optional<double> value, int64_t triangle) {
    v1::ProfilePoint* point = to->Add();
    point->set_kind(kind);
    point->mutable_point()->set_x(distance);
    point->set_distance(distance);
    if (value.has_value()) point->set_value(*value);
    point->set_triangle_id(triangle);
  };
  add(response.mutable_breakpoints(), v1::PROFILE_POINT_KIND_LINE_VERTEX, 0,
      1.5, 4);
  add(response.mutable_breakpoints(), v1::PROFILE_POINT_KIND_EDGE_CROSSING, 10,
      2.25, 5);
  add(response.mutable_breakpoints(), v1::PROFILE_POINT_KIND_EDGE_CROSSING, 20,
      3, -1);
  add(response.mutable_breakpoints(), v1::PROFILE_POINT_KIND_LINE_VERTEX, 30,
      std::nullopt, -1);
  response.mutable_breakpoints(3)->set_segment(0);
  if (with_samples) {
    add(response.mutable_samples(), v1::PROFILE_POINT_KIND_SAMPLE, 0, 1.5, 4);
    add(response.mutable_samples(), v1::PROFILE_POINT_KIND_SAMPLE, 15, 2.625,
        5);
    add(response.mutable_samples(), v1::PROFILE_POINT_KIND_SAMPLE, 30,
        std::nullopt, -1);
  }
  v1::ProfileGap* gap = response.add_gaps();
  gap->set_from_distance(20);
  gap->set_to_distance(30);
  gap->set_reason(v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL);
  return response;
}

TEST(CliFormatTest, FormatProfileTablesBreakpointsSamplesAndGaps) {
  EXPECT_EQ(FormatProfile(TestProfile(/*with_samples=*/true)),
            "length       30\n"
            "crossings    2\n"
            "breakpoints  4\n"
            "  distance  x   y  z     triangle  kind\n"
            "  0         0   0  1.5   4         LINE_VERTEX\n"
            "  10        10  0  2.25  5         EDGE_CROSSING\n"
            "  20        20  0  3     -1        EDGE_CROSSING\n"
            "  30        30  0  none  -1        LINE_VERTEX\n"
            "samples  3\n"
            "  distance  x   y  z      triangle\n"
            "  0         0   0  1.5    4\n"
            "  15        15  0  2.625  5\n"
            "  30        30  0  none   -1\n"
            "gaps  1\n"
            "  from  to  reason\n"
            "  20    30  OUTSIDE_CONVEX_HULL\n");
  v1::ProfileResponse no_gaps = TestProfile(/*with_samples=*/false);
  no_gaps.clear_gaps();
  const std::string text = FormatProfile(no_gaps);
  EXPECT_THAT(text, ::testing::EndsWith("LINE_VERTEX\ngaps  none\n"));
  EXPECT_THAT(text, ::testing::Not(HasSubstr("samples")));
}

TEST(CliFormatTest, ProfileCsvMergesBreakpointsAndSamplesByDistance) {
  EXPECT_EQ(ProfileCsv(TestProfile(/*with_samples=*/true)),
            "kind,distance,x,y,z,triangle_id,segment\n"
            "LINE_VERTEX,0,0,0,1.5,4,0\n"
            "SAMPLE,0,0,0,1.5,4,0\n"
            "EDGE_CROSSING,10,10,0,2.25,5,0\n"
            "SAMPLE,15,15,0,2.625,5,0\n"
            "EDGE_CROSSING,20,20,0,3,-1,0\n"
            "LINE_VERTEX,30,30,0,,-1,0\n"
            "SAMPLE,30,30,0,,-1,0\n");
}

}  // namespace
}  // namespace locator
