// ReloadPolicy: the configured dataset always; generator specs and files
// inside --reload-dir only with one; every other spec refused alike.

#include "server/datasets/reload_policy.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/common/gis/las_writer.h"
#include "tests/common/gis/raster_fixtures.h"
#include "tests/core/scratch_dir.h"

namespace locator {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;
using ::testing::HasSubstr;

// A reload dir holding points.csv, a subdirectory with more.csv, and next to
// it (outside) secret.csv; links inside point in and out.
class ReloadPolicyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = root_.path() + "/reload";
    fs::create_directories(dir_ + "/sub");
    std::ofstream(dir_ + "/points.csv") << "0,0\n1,0\n0,1\n";
    std::ofstream(dir_ + "/sub/more.csv") << "0,0\n1,0\n0,1\n";
    secret_ = root_.path() + "/secret.csv";
    std::ofstream(secret_) << "0,0\n1,0\n0,1\n";
    fs::create_symlink(secret_, dir_ + "/escape.csv");
    fs::create_symlink(root_.path(), dir_ + "/up");
    fs::create_symlink(dir_ + "/points.csv", dir_ + "/alias.csv");
  }

  // What Resolve() makes of `requested` under policy_; "denied" if refused.
  std::string Resolved(const ReloadPolicy& policy,
                       const std::string& requested) {
    const StatusOr<std::string> spec = policy.Resolve(requested);
    if (spec.ok()) return *spec;
    EXPECT_EQ(spec.status().code(), Status::Code::kPermissionDenied)
        << requested;
    return "denied";
  }

  std::string Canonical(const std::string& path) {
    return fs::canonical(path).string();
  }

  ScratchDir root_;
  std::string dir_;
  std::string secret_;
};

TEST_F(ReloadPolicyTest, TheConfiguredDatasetIsAlwaysAllowed) {
  const ReloadPolicy without_dir("uniform:300:7", "");
  EXPECT_EQ(Resolved(without_dir, ""), "");
  EXPECT_EQ(Resolved(without_dir, "uniform:300:7"), "");
  const ReloadPolicy with_dir(secret_, dir_);
  EXPECT_EQ(Resolved(with_dir, secret_), "");
  EXPECT_EQ(Resolved(ReloadPolicy(), ""), "");
}

TEST_F(ReloadPolicyTest, WithoutAReloadDirEverythingElseIsDenied) {
  const ReloadPolicy policy("uniform:300:7", "");
  for (const std::string& requested :
       {secret_, root_.path() + "/missing.csv", std::string("uniform:500:1"),
        std::string("clusters:500:2"), dir_ + "/points.csv"}) {
    EXPECT_EQ(Resolved(policy, requested), "denied") << requested;
  }
  EXPECT_THAT(policy.Resolve(secret_).status().message(),
              HasSubstr("--reload-dir"));
}

TEST_F(ReloadPolicyTest, FilesInsideTheReloadDirResolveToTheirRealPath) {
  const ReloadPolicy policy("uniform:300:7", dir_);
  const std::string points = Canonical(dir_ + "/points.csv");
  EXPECT_EQ(Resolved(policy, "points.csv"), points);
  EXPECT_EQ(Resolved(policy, "./points.csv"), points);
  EXPECT_EQ(Resolved(policy, dir_ + "/points.csv"), points);
  EXPECT_EQ(Resolved(policy, "sub/more.csv"),
            Canonical(dir_ + "/sub/more.csv"));
  // A link that stays inside is followed.
  EXPECT_EQ(Resolved(policy, "alias.csv"), points);
}

TEST_F(ReloadPolicyTest, OptionsOfEveryKindRideAlongWithTheirFile) {
  const ReloadPolicy policy("uniform:300:7", dir_);
  gis::testing::DemFixture dem = gis::testing::HillDem(4, 3, 30);
  dem.bands = 2;
  gis::testing::WriteDem(dir_ + "/dem.tif", dem);
  gis::testing::WriteDem(dir_ + "/dem.bin", dem);
  gis::testing::WriteLasFile(dir_ + "/tile.bin", {{.x = 1, .y = 2, .z = 3}});
  EXPECT_EQ(
      Resolved(policy, "dem.tif?max_error=0.5&band=2"),
      Canonical(dir_ + "/dem.tif") + "?max_error=0.5&band=2&driver=GTiff");
  EXPECT_EQ(Resolved(policy, "las:tile.bin?classes=2&returns=last"),
            "las:" + Canonical(dir_ + "/tile.bin") + "?classes=2&returns=last");
  EXPECT_EQ(
      Resolved(policy, "raster:dem.bin?max_points=10"),
      "raster:" + Canonical(dir_ + "/dem.bin") + "?max_points=10&driver=GTiff");
  EXPECT_EQ(Resolved(policy, "points.csv?max_points=100"),
            Canonical(dir_ + "/points.csv") + "?max_points=100");
  // The options never name the file.
  EXPECT_EQ(Resolved(policy, "missing.tif?a_srs=" + dir_ + "/dem.tif"),
            "denied");
  EXPECT_EQ(Resolved(policy, "las:" + secret_ + "?classes=2"), "denied");
}

TEST_F(ReloadPolicyTest, AMeshIsAllowedOnlyWithItsNodeFileInside) {
  const ReloadPolicy policy("uniform:300:7", dir_);
  std::ofstream(dir_ + "/mesh.ele") << "1 3 0\n1 1 2 3\n";
  // Without its .node the .ele is refused like a missing file.
  EXPECT_EQ(Resolved(policy, "mesh.ele"), "denied");
  std::ofstream(dir_ + "/mesh.node") << "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n";
  EXPECT_EQ(Resolved(policy, "mesh.ele"), Canonical(dir_ + "/mesh.ele"));
  // A .node that links outside takes the .ele with it.
  std::ofstream(dir_ + "/leak.ele") << "1 3 0\n1 1 2 3\n";
  std::ofstream(root_.path() + "/leak.node") << "3 2 0 0\n";
  fs::create_symlink(root_.path() + "/leak.node", dir_ + "/leak.node");
  EXPECT_EQ(Resolved(policy, "leak.ele"), "denied");
}

TEST_F(ReloadPolicyTest, PointsPlusWktNeedBothInside) {
  const ReloadPolicy policy("uniform:300:7", dir_);
  std::ofstream(dir_ + "/lake.wkt") << "POLYGON ((0 0, 1 0, 0 1, 0 0))\n";
  std::ofstream(root_.path() + "/outside.wkt") << "LINESTRING (0 0, 1 1)\n";
  const std::string lake = Canonical(dir_ + "/lake.wkt");
  EXPECT_EQ(Resolved(policy, "points.csv+lake.wkt"),
            Canonical(dir_ + "/points.csv") + "+" + lake);
  EXPECT_EQ(Resolved(policy, "uniform:500:1+lake.wkt"),
            "uniform:500:1+" + lake);
  EXPECT_EQ(Resolved(policy, "points.csv+../outside.wkt"), "denied");
  EXPECT_EQ(Resolved(policy, "points.csv+" + root_.path() + "/outside.wkt"),
            "denied");
  EXPECT_EQ(Resolved(policy, secret_ + "+lake.wkt"), "denied");
  EXPECT_EQ(Resolved(policy, "points.csv+missing.wkt"), "denied");
}

TEST_F(ReloadPolicyTest, GeneratorSpecsNeedAReloadDir) {
  const ReloadPolicy policy("uniform:300:7", dir_);
  EXPECT_EQ(Resolved(policy, "uniform:500:1"), "uniform:500:1");
  EXPECT_EQ(Resolved(policy, "clusters:500:3:2"), "clusters:500:3:2");
}

TEST_F(ReloadPolicyTest, NoEscapeByDotDotOrSymlinks) {
  const ReloadPolicy policy("uniform:300:7", dir_);
  // ".." is refused even where it would land inside again.
  EXPECT_EQ(Resolved(policy, "../secret.csv"), "denied");
  EXPECT_EQ(Resolved(policy, "sub/../points.csv"), "denied");
  EXPECT_EQ(Resolved(policy, dir_ + "/../secret.csv"), "denied");
  EXPECT_EQ(Resolved(policy, "escape.csv"), "denied");
  EXPECT_EQ(Resolved(policy, "up/secret.csv"), "denied");
  EXPECT_EQ(Resolved(policy, secret_), "denied");
  EXPECT_EQ(Resolved(policy, "/etc/passwd"), "denied");
}

TEST_F(ReloadPolicyTest, MissingAndExistingFilesAreDeniedAlike) {
  const ReloadPolicy policy("uniform:300:7", dir_);
  const Status missing = policy.Resolve(root_.path() + "/x.csv").status();
  fs::rename(secret_, root_.path() + "/x.csv");
  const Status existing = policy.Resolve(root_.path() + "/x.csv").status();
  EXPECT_EQ(missing.code(), Status::Code::kPermissionDenied);
  EXPECT_EQ(existing.code(), Status::Code::kPermissionDenied);
  EXPECT_EQ(missing.message(), existing.message());
  // Inside the dir, too: a missing file says nothing more than a forbidden
  // one.
  EXPECT_EQ(Resolved(policy, "missing.csv"), "denied");
  // The dir itself and subdirectories are not datasets.
  EXPECT_EQ(Resolved(policy, "sub"), "denied");
  EXPECT_EQ(Resolved(policy, "."), "denied");
}

// GIS specs: the file must be inside, the options ones a request may use,
// and the load may use only the driver that identified the file.
class ReloadPolicyGisTest : public ReloadPolicyTest {
 protected:
  void SetUp() override {
    ReloadPolicyTest::SetUp();
    std::ofstream(dir_ + "/pts.geojson")
        << R"({"type":"FeatureCollection","features":[{"type":"Feature",)"
           R"("properties":{"h":1},"geometry":{"type":"Point",)"
           R"("coordinates":[0,0]}}]})";
    std::ofstream(dir_ + "/view.vrt")
        << "<OGRVRTDataSource><OGRVRTLayer name=\"x\"><SrcDataSource>"
        << secret_ << "</SrcDataSource></OGRVRTLayer></OGRVRTDataSource>";
  }

  // The refusal of `requested`, which must be PERMISSION_DENIED.
  std::string Denial(const std::string& requested) {
    const StatusOr<std::string> spec =
        ReloadPolicy("uniform:300:7", dir_).Resolve(requested);
    EXPECT_EQ(spec.status().code(), Status::Code::kPermissionDenied)
        << requested << " resolved to " << (spec.ok() ? *spec : "");
    return spec.status().message();
  }
};

TEST_F(ReloadPolicyGisTest, ASpecIsResolvedWithItsDriver) {
  const ReloadPolicy policy("uniform:300:7", dir_);
  const std::string geojson = Canonical(dir_ + "/pts.geojson");
  EXPECT_EQ(Resolved(policy, "pts.geojson"), geojson + "?driver=GeoJSON");
  EXPECT_EQ(Resolved(policy, "pts.geojson?z=h&where=h%20%3E%200"),
            geojson + "?z=h&where=h%20%3E%200&driver=GeoJSON");
  EXPECT_EQ(Resolved(policy, "pts.geojson?driver=GeoJSON"),
            geojson + "?driver=GeoJSON");
  // The options every kind takes pass as well.
  EXPECT_EQ(Resolved(policy, "pts.geojson?max_error=0.5&z=h"),
            geojson + "?max_error=0.5&z=h&driver=GeoJSON");
  EXPECT_EQ(Resolved(policy, "ogr:points.csv?oo=X_POSSIBLE_NAMES=x"),
            "ogr:" + Canonical(dir_ + "/points.csv") +
                "?oo=X_POSSIBLE_NAMES=x&driver=CSV");
}

TEST_F(ReloadPolicyGisTest, OptionsThatRunSqlOrReachOtherFilesAreDenied) {
  const struct {
    std::string requested;
    std::string message;
  } kCases[] = {
      {"pts.geojson?oo=PRELUDE_STATEMENTS=ATTACH%20DATABASE%20'" + secret_ +
           "'%20AS%20x",
       "oo=PRELUDE_STATEMENTS: not an open option a Reload may set"},
      {"pts.geojson?oo=PRELUDE_STATEMENTS=VACUUM%20INTO%20'%2Ftmp%2Fout.db'",
       "oo=PRELUDE_STATEMENTS"},
      {"pts.geojson?where=h%20%3D%20(SELECT%20count(*)%20FROM%20x.t)",
       "where=: at byte 12, expected ')', found 'count(*) FROM x.t)'"},
      {"pts.geojson?where=length(BlobFromFile('%2Fetc%2Fpasswd'))%20%3E%200",
       "where=: at byte 6"},
      {"pts.geojson?a_srs=%2Bproj%3Dlonglat%20%2Bnadgrids%3D%2Fdev%2Fptmx",
       "a_srs=: CRS '+proj=longlat +nadgrids=/dev/ptmx' names a file PROJ "
       "may not open here"},
      {"pts.geojson?driver=OGR_VRT", "driver='OGR_VRT': a Reload may read only"},
      {"ogr:view.vrt", "not a format a Reload may read"},
      {"ogr:points.csv?driver=GML", "driver='GML'"},
  };
  for (const auto& c : kCases) {
    EXPECT_THAT(Denial(c.requested), HasSubstr(c.message)) << c.requested;
  }
}

// An option is refused before the file is looked at: the refusal is the
// same for a file that exists and one that does not.
TEST_F(ReloadPolicyGisTest, AnOptionIsDeniedAlikeWhateverTheFile) {
  const std::string option = "?oo=PRELUDE_STATEMENTS=SELECT%201";
  const std::string existing = Denial("pts.geojson" + option);
  const std::string missing = Denial("missing.gpkg" + option);
  EXPECT_EQ(existing.substr(existing.find("': ")),
            missing.substr(missing.find("': ")));
  EXPECT_THAT(Denial("missing.gpkg"), HasSubstr("is not a file in"));
}

TEST_F(ReloadPolicyGisTest, MalformedOptionsAreInvalidArgument) {
  const Status status = ReloadPolicy("uniform:300:7", dir_)
                            .Resolve("pts.geojson?colour=red")
                            .status();
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("unknown option 'colour'"));
}

// Rasters: only drivers that read no file the raster names, an a_srs that
// passes the request CRS policy; LAS files: classes= and returns=.
TEST_F(ReloadPolicyGisTest, ARasterIsReadOnlyByADriverThatOpensNoOtherFile) {
  gis::testing::WriteDem(dir_ + "/dem.tif", gis::testing::HillDem(4, 3, 30));
  gis::testing::WriteDem(secret_ + ".tif", gis::testing::HillDem(4, 3, 30));
  const std::string vrt =
      "<VRTDataset rasterXSize=\"4\" rasterYSize=\"3\"><VRTRasterBand "
      "dataType=\"Float32\" band=\"1\"><SimpleSource><SourceFilename>" +
      secret_ +
      ".tif</SourceFilename><SourceBand>1</SourceBand>"
      "</SimpleSource></VRTRasterBand></VRTDataset>";
  std::ofstream(dir_ + "/mosaic.vrt") << vrt;
  // A VRT by another name is still a VRT to GDAL.
  std::ofstream(dir_ + "/looks.tif") << vrt;
  const struct {
    std::string requested;
    std::string message;
  } kCases[] = {
      {"mosaic.vrt", "not a raster format a Reload may read (GTiff, AAIGrid"},
      {"looks.tif?max_error=1", "not a raster format a Reload may read"},
      {"raster:mosaic.vrt?driver=VRT", "driver='VRT': a Reload may read only"},
      {"dem.tif?driver=HFA", "driver='HFA'"},
      {"dem.tif?a_srs=%2Bproj%3Dlonglat%20%2Bnadgrids%3D%2Fdev%2Fptmx",
       "a_srs=: CRS '+proj=longlat +nadgrids=/dev/ptmx' names a file PROJ "
       "may not open here"},
      {"missing.tif?driver=VRT", "driver='VRT'"},
  };
  for (const auto& c : kCases) {
    EXPECT_THAT(Denial(c.requested), HasSubstr(c.message)) << c.requested;
  }
  const ReloadPolicy policy("uniform:300:7", dir_);
  EXPECT_EQ(Resolved(policy, "dem.tif?a_srs=EPSG:32633&driver=GTiff"),
            Canonical(dir_ + "/dem.tif") + "?a_srs=EPSG:32633&driver=GTiff");
}

TEST_F(ReloadPolicyGisTest, MalformedRasterAndLasOptionsAreInvalidArgument) {
  gis::testing::WriteDem(dir_ + "/dem.tif", gis::testing::HillDem(4, 3, 30));
  gis::testing::WriteLasFile(dir_ + "/tile.las", {{.x = 1, .y = 2, .z = 3}});
  const struct {
    std::string requested;
    std::string message;
  } kCases[] = {
      {"dem.tif?band=0", "option 'band' must be an integer from 1"},
      {"dem.tif?oo=X=1", "unknown option 'oo'"},
      {"dem.tif?max_error=-1", "option 'max_error' must be a finite number"},
      {"tile.las?classes=2,300", "option 'classes' must be"},
      {"tile.las?band=1", "unknown option 'band'"},
      {"points.csv?z=h", "unknown option 'z'"},
  };
  for (const auto& c : kCases) {
    const Status status =
        ReloadPolicy("uniform:300:7", dir_).Resolve(c.requested).status();
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << c.requested;
    EXPECT_THAT(status.message(), HasSubstr(c.message)) << c.requested;
  }
}

}  // namespace
}  // namespace locator
