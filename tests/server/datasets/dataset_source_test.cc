// LoadServedDataset (server/datasets/dataset_source.h): each spec's kind, its
// parts for the reload policy, the files each kind reports for the mesh cache's
// source keys, the options each kind takes and refuses, a raster always
// simplified and a point dataset simplified when asked (with the
// certificate and progress), and a file whose name holds '?' refused.

#include "server/datasets/dataset_source.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/common/gis/gis_fixtures.h"
#include "tests/common/gis/las_writer.h"
#include "tests/common/gis/raster_fixtures.h"
#include "tests/core/scratch_dir.h"

namespace locator {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(DatasetSourceTest, KindsFollowPrefixesThenExtensions) {
  EXPECT_EQ(DatasetKindOf("points.csv"), DatasetKind::kText);
  EXPECT_EQ(DatasetKindOf("mesh.ele?max_error=1"), DatasetKind::kText);
  EXPECT_EQ(DatasetKindOf("survey.xyz+lakes.wkt"), DatasetKind::kText);
  EXPECT_EQ(DatasetKindOf("uniform:1000:2"), DatasetKind::kGenerator);
  EXPECT_EQ(DatasetKindOf("uniform:1000+lakes.wkt"), DatasetKind::kGenerator);
  EXPECT_EQ(DatasetKindOf("hill.gpkg?layer=a"), DatasetKind::kOgr);
  EXPECT_EQ(DatasetKindOf("ogr:pts.csv"), DatasetKind::kOgr);
  EXPECT_EQ(DatasetKindOf("ogr:dem.tif"), DatasetKind::kOgr);
  EXPECT_EQ(DatasetKindOf("DEM.TIF?band=2"), DatasetKind::kRaster);
  EXPECT_EQ(DatasetKindOf("raster:dem.png"), DatasetKind::kRaster);
  EXPECT_EQ(DatasetKindOf("tile.las?classes=2"), DatasetKind::kLas);
  EXPECT_EQ(DatasetKindOf("tile.laz"), DatasetKind::kLas);
  EXPECT_EQ(DatasetKindOf("las:tile.bin"), DatasetKind::kLas);
}

TEST(DatasetSourceTest, SplitsEveryKindIntoPrefixSourceAndOptions) {
  const auto parts = [](std::string_view spec) {
    const gis::SpecParts p = SplitServedSpec(spec);
    return std::vector<std::string>{
        std::string(p.prefix), std::string(p.source), std::string(p.options)};
  };
  EXPECT_THAT(parts("dem.tif?max_error=0.5"),
              ElementsAre("", "dem.tif", "?max_error=0.5"));
  EXPECT_THAT(parts("raster:dem.png?band=2"),
              ElementsAre("raster:", "dem.png", "?band=2"));
  EXPECT_THAT(parts("las:a.bin?classes=2"),
              ElementsAre("las:", "a.bin", "?classes=2"));
  EXPECT_THAT(parts("ogr:p.csv?oo=X=x"),
              ElementsAre("ogr:", "p.csv", "?oo=X=x"));
  EXPECT_THAT(parts("pts.csv?max_points=100"),
              ElementsAre("", "pts.csv", "?max_points=100"));
  EXPECT_THAT(parts("pts.csv"), ElementsAre("", "pts.csv", ""));
}

class DatasetSourceLoadTest : public ::testing::Test {
 protected:
  std::string Path(const std::string& name) const {
    return dir_.path() + "/" + name;
  }
  Status Load(const std::string& spec, ServedDataset* out,
              ServedLoadOptions options = ServedLoadOptions()) const {
    return LoadServedDataset(spec, options, out);
  }

  test::ScratchDir dir_;
};

TEST_F(DatasetSourceLoadTest, TextFilesReportEveryFileTheyRead) {
  gis::testing::WriteFile(Path("pts.csv"), "0,0,1\n1,0,2\n0,1,3\n1,1,4\n");
  gis::testing::WriteFile(Path("lake.wkt"), "LINESTRING (0.2 0.2, 0.8 0.8)");
  ServedDataset served;
  ASSERT_TRUE(Load(Path("pts.csv") + "+" + Path("lake.wkt"), &served).ok());
  EXPECT_THAT(served.files, ElementsAre(Path("pts.csv"), Path("lake.wkt")));
  EXPECT_FALSE(served.simplification.has_value());
  EXPECT_EQ(served.dataset.source, Path("pts.csv") + "+" + Path("lake.wkt"));
  ASSERT_TRUE(Load("uniform:100:2", &served).ok());
  EXPECT_TRUE(served.files.empty());
}

TEST_F(DatasetSourceLoadTest, TextAndGeneratorSpecsTakeOnlyTheSimplifyOptions) {
  gis::testing::WriteFile(Path("pts.csv"), "0,0,1\n1,0,2\n0,1,3\n");
  ServedDataset served;
  Status status = Load(Path("pts.csv") + "?band=2", &served);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(),
              HasSubstr("unknown option 'band' (known: max_error, "
                        "max_points)"));
  status = Load("uniform:100?layer=x", &served);
  EXPECT_THAT(status.message(), HasSubstr("unknown option 'layer'"));
  // A file named with a '?' is refused, saying why.
  gis::testing::WriteFile(Path("odd?name.csv"), "0,0\n1,0\n0,1\n");
  status = Load(Path("odd?name.csv"), &served);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(),
              HasSubstr("names a file, but a dataset spec's options begin at "
                        "its first '?'"));
}

TEST_F(DatasetSourceLoadTest, ARasterIsAlwaysATinWithItsCertificate) {
  gis::testing::DemFixture dem = gis::testing::HillDem(30, 20, 10);
  gis::testing::PunchHole(&dem, 10, 8, 13, 11);
  gis::testing::WriteDem(Path("dem.tif"), dem);
  ServedDataset served;
  ASSERT_TRUE(Load(Path("dem.tif"), &served).ok());
  ASSERT_TRUE(served.simplification.has_value());
  EXPECT_EQ(served.simplification->target_error, 0);
  EXPECT_EQ(served.simplification->source_samples, 30u * 20 - 9);
  EXPECT_EQ(served.simplification->vertices, 30u * 20 - 9);
  EXPECT_EQ(served.dataset.points.size(), served.simplification->vertices);
  EXPECT_FALSE(served.dataset.constraints.triangles.empty());
  EXPECT_FALSE(served.dataset.crs.empty());
  EXPECT_THAT(served.files, ElementsAre(Path("dem.tif")));
  EXPECT_THAT(served.absent_files,
              ElementsAre(Path("dem.tif.aux.xml"), Path("dem.tif.msk"),
                          Path("dem.prj"), Path("dem.wld"), Path("dem.tfw")));

  // Progress reaches the caller (the server logs it), here at every step.
  std::atomic<int> progress_calls{0};
  ServedLoadOptions options;
  options.progress = [&](const TinProgress&) { ++progress_calls; };
  options.progress_interval_s = 1e-9;
  const std::string spec = Path("dem.tif") + "?max_error=0.5&max_points=200";
  ASSERT_TRUE(Load(spec, &served, options).ok());
  EXPECT_GT(progress_calls.load(), 0);
  EXPECT_EQ(served.dataset.source, spec);
  EXPECT_EQ(served.simplification->target_error, 0.5);
  EXPECT_EQ(served.simplification->max_points, 200u);
  EXPECT_LE(served.simplification->vertices, 200u);
  EXPECT_LT(served.simplification->vertices, 30u * 20 - 9);
}

TEST_F(DatasetSourceLoadTest, PointsAreThinnedOnlyWhenAsked) {
  std::string csv;
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      csv += std::to_string(i) + "," + std::to_string(j) + "," +
             std::to_string(0.5 * i + 0.25 * j + (i * j % 7 == 0 ? 0.1 : 0)) +
             "\n";
    }
  }
  gis::testing::WriteFile(Path("plane.csv"), csv);
  ServedDataset served;
  ASSERT_TRUE(Load(Path("plane.csv"), &served).ok());
  EXPECT_FALSE(served.simplification.has_value());
  EXPECT_EQ(served.dataset.points.size(), 1600u);
  ASSERT_TRUE(Load(Path("plane.csv") + "?max_error=0.2", &served).ok());
  ASSERT_TRUE(served.simplification.has_value());
  EXPECT_EQ(served.simplification->source_samples, 1600u);
  EXPECT_LE(served.simplification->max_error, 0.2);
  EXPECT_LT(served.dataset.points.size(), 100u);
  EXPECT_THAT(served.files, ElementsAre(Path("plane.csv")));
}

TEST_F(DatasetSourceLoadTest, LasFilesAreKeyedByTheirPath) {
  std::vector<gis::testing::LasPoint> points = {
      {0, 0, 1, 2}, {10, 0, 2, 2}, {0, 10, 3, 2}, {5, 5, 9, 5}};
  gis::testing::WriteLasFile(Path("tile.las"), points);
  ServedDataset served;
  ASSERT_TRUE(Load(Path("tile.las") + "?classes=2", &served).ok());
  EXPECT_EQ(served.dataset.points.size(), 3u);
  EXPECT_THAT(served.files, ElementsAre(Path("tile.las")));
  const Status status =
      Load(Path("tile.las") + "?classes=2&max_error=x", &served);
  EXPECT_THAT(status.message(),
              HasSubstr("option 'max_error' must be a finite number >= 0"));
}

}  // namespace
}  // namespace locator
