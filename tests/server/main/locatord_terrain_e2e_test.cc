// locatord end to end on terrain as it comes: the ground of LAS 1.2 and LAS
// 1.4 tiles written at test time (ground, vegetation, water and withheld
// points; the CRS as GeoTIFF keys in one and as WKT in the other) served
// with ?classes=2, and a GeoTIFF DEM served with ?max_error=. Only class-2
// points become vertices; both CRSs are reported and lon/lat queries get the
// ground's heights; GetStats carries the DEM's certificate; a restart with
// --mesh-cache maps the DEM's mesh by its file's identity without reading
// the raster (the raster is garbage by then, so a read would fail), and a
// raster touched since is read again; .laz files and bad rasters stop the
// start with their reason.

#include <fcntl.h>
#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "tests/common/gis/gis_fixtures.h"
#include "tests/common/gis/las_writer.h"
#include "tests/common/gis/raster_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

using gis::testing::LasPoint;
using ::testing::HasSubstr;

constexpr int kSide = 20;  // ground points per side, 5 m apart
constexpr double kSpacing = 5;
constexpr double kMaxError = 0.25;
constexpr std::chrono::seconds kExitTimeout{30};

double Ground(double x, double y) {
  return 300 + 0.02 * (x - 500000) + 0.5 * std::sin((y - 5500000) / 17);
}

// The tile: a grid of ground points; inside each cell (off its diagonals) a
// vegetation point (the first of two returns) 12 m above the ground, and on
// every seventh cell a withheld ground point and a water point instead.
std::vector<LasPoint> Tile() {
  std::vector<LasPoint> points;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      const double x = 500000 + i * kSpacing, y = 5500000 + j * kSpacing;
      points.push_back({x, y, Ground(x, y), 2, 1, 1, false});
      if (i + 1 == kSide || j + 1 == kSide) continue;
      const double cx = x + 1.3, cy = y + 3.1;
      if ((i * kSide + j) % 7 == 0) {
        points.push_back({cx, cy, Ground(cx, cy) + 40, 2, 1, 1, true});
        points.push_back({cx, cy, Ground(cx, cy) - 1, 9, 1, 1, false});
      } else {
        points.push_back({cx, cy, Ground(cx, cy) + 12, 5, 1, 2, false});
      }
    }
  }
  return points;
}

class LocatordTerrainTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new ScratchDir();
    gis::testing::LasFileOptions v12;
    v12.minor_version = 2;
    v12.point_format = 1;
    v12.offset = {500000, 5500000, 0};
    v12.geo_keys = gis::testing::ProjectedGeoKeys(32633);
    gis::testing::WriteLasFile(Path("tile12.las"), Tile(), v12);
    gis::testing::LasFileOptions v14 = v12;
    v14.minor_version = 4;
    v14.point_format = 6;
    v14.geo_keys.clear();
    v14.wkt = gis::testing::EpsgWkt2(32633);
    gis::testing::WriteLasFile(Path("tile14.las"), Tile(), v14);
    dem_ = new gis::testing::DemFixture(gis::testing::HillDem(40, 30, 30));
    gis::testing::PunchHole(dem_, 12, 10, 16, 14);
    gis::testing::WriteDem(Path("dem.tif"), *dem_);
    const Status started = StartLocatord(
        "ground12=" + Path("tile12.las") + "?classes=2",
        {"--dataset", "ground14=las:" + Path("tile14.las") + "?classes=2",
         "--dataset", "dem=" + DemSpec(Path("dem.tif"))},
        &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
  }
  static void TearDownTestSuite() {
    server_.reset();
    delete dem_;
    delete dir_;
  }
  void SetUp() override {
    ASSERT_NE(server_, nullptr);
    stub_ = NewStub(*server_);
  }

  static std::string Path(const std::string& name) {
    return dir_->path() + "/" + name;
  }
  static std::string DemSpec(const std::string& path) {
    return path + "?max_error=" + std::to_string(kMaxError);
  }
  // The centre of DEM pixel (col, row) and its value.
  static Point2 PixelCentre(uint32_t col, uint32_t row) {
    const auto& gt = dem_->geotransform;
    return {gt[0] + (col + 0.5) * gt[1], gt[3] + (row + 0.5) * gt[5]};
  }
  static double PixelValue(uint32_t col, uint32_t row) {
    return dem_->values[size_t{row} * dem_->width + col];
  }

  static ScratchDir* dir_;
  static gis::testing::DemFixture* dem_;
  static std::unique_ptr<ServerProcess> server_;
  std::unique_ptr<v1::Locator::Stub> stub_;
};

ScratchDir* LocatordTerrainTest::dir_ = nullptr;
gis::testing::DemFixture* LocatordTerrainTest::dem_ = nullptr;
std::unique_ptr<ServerProcess> LocatordTerrainTest::server_;

TEST_F(LocatordTerrainTest, OnlyGroundPointsOfBothLasVersionsAreVertices) {
  const std::vector<LasPoint> tile = Tile();
  for (const std::string name : {"ground12", "ground14"}) {
    SCOPED_TRACE(name);
    const v1::DatasetStats stats = GetStats(*stub_, name).dataset();
    EXPECT_EQ(stats.input_points(), uint64_t{kSide * kSide});
    EXPECT_EQ(stats.vertices(), uint64_t{kSide * kSide});
    EXPECT_EQ(stats.crs().epsg_code(), 32633u);
    EXPECT_TRUE(stats.has_values());
    EXPECT_FALSE(stats.has_simplification());
    size_t ground = 0, others = 0;
    for (const LasPoint& p : tile) {
      v1::LocateResponse response;
      ASSERT_TRUE(LocateOne(*stub_, {p.x, p.y}, &response, name).ok());
      if (p.classification == 2 && !p.withheld) {
        ++ground;
        EXPECT_EQ(response.type(), v1::LOCATION_TYPE_VERTEX)
            << p.x << " " << p.y;
        // The file holds z in centimetres.
        EXPECT_NEAR(response.value(), p.z, 0.005 + 1e-9);
      } else {
        // Vegetation, water and withheld points sit inside a ground cell.
        ++others;
        EXPECT_EQ(response.type(), v1::LOCATION_TYPE_FACE) << p.x << " " << p.y;
        EXPECT_NEAR(response.value(), Ground(p.x, p.y), 0.1);
      }
    }
    EXPECT_EQ(ground, size_t{kSide * kSide});
    EXPECT_GT(others, 300u);
  }
}

TEST_F(LocatordTerrainTest, LonLatQueriesGetTheGroundsHeights) {
  const std::vector<Point2> utm = {{500012.5, 5500031.25}, {500040, 5500070}};
  const std::vector<Point2> lon_lat =
      gis::testing::Cs2cs(utm, "EPSG:32633", "EPSG:4326", dir_->path());
  ASSERT_EQ(lon_lat.size(), utm.size());
  for (const std::string name : {"ground12", "ground14", "dem"}) {
    for (size_t i = 0; i < utm.size(); ++i) {
      v1::LocateRequest request = LocateRequestFor(lon_lat[i], name);
      request.set_crs("EPSG:4326");
      v1::LocateResponse in_lon_lat, in_utm;
      grpc::ClientContext context;
      ASSERT_TRUE(stub_->Locate(&context, request, &in_lon_lat).ok());
      ASSERT_TRUE(LocateOne(*stub_, utm[i], &in_utm, name).ok());
      ASSERT_TRUE(in_utm.has_value()) << name;
      EXPECT_NEAR(in_lon_lat.value(), in_utm.value(), 1e-3) << name << " " << i;
    }
  }
}

TEST_F(LocatordTerrainTest, TheDemsCertificateIsInItsStats) {
  const v1::DatasetStats stats = GetStats(*stub_, "dem").dataset();
  ASSERT_TRUE(stats.has_simplification());
  const v1::SimplificationStats& s = stats.simplification();
  EXPECT_EQ(s.source_samples(), 40u * 30 - 16);
  EXPECT_EQ(s.unserved_samples(), 0u);
  EXPECT_LE(s.max_error(), kMaxError);
  EXPECT_EQ(s.target_error(), kMaxError);
  EXPECT_EQ(s.max_points(), 0u);
  EXPECT_LT(s.vertices(), s.source_samples());
  EXPECT_EQ(stats.vertices(), s.vertices());
  EXPECT_EQ(stats.triangles(), s.triangles());
  EXPECT_EQ(stats.crs().epsg_code(), 32633u);
  EXPECT_EQ(stats.holes(), 1u);
  EXPECT_EQ(stats.source(), DemSpec(Path("dem.tif")));
  // Every pixel centre answers within the certificate, or outside the domain
  // in the hole.
  for (uint32_t row = 0; row < dem_->height; ++row) {
    for (uint32_t col = 0; col < dem_->width; ++col) {
      v1::LocateResponse response;
      ASSERT_TRUE(
          LocateOne(*stub_, PixelCentre(col, row), &response, "dem").ok());
      if (PixelValue(col, row) == dem_->nodata) {
        EXPECT_EQ(response.type(), v1::LOCATION_TYPE_OUTSIDE_DOMAIN)
            << col << " " << row;
      } else {
        ASSERT_TRUE(response.has_value()) << col << " " << row;
        EXPECT_LE(std::abs(response.value() - PixelValue(col, row)),
                  s.max_error() + 1e-9)
            << col << " " << row;
      }
    }
  }
}

// Writes `size` zero bytes over the file at `path` in place (same inode, same
// size) and puts its modification time back.
void GarbleKeepingIdentity(const std::string& path) {
  struct stat before;
  ASSERT_EQ(::stat(path.c_str(), &before), 0);
  const int fd = ::open(path.c_str(), O_WRONLY);
  ASSERT_GE(fd, 0);
  const std::vector<char> zeros(static_cast<size_t>(before.st_size), 0);
  ASSERT_EQ(::pwrite(fd, zeros.data(), zeros.size(), 0),
            static_cast<ssize_t>(zeros.size()));
  const struct timespec times[2] = {before.st_atim, before.st_mtim};
  ASSERT_EQ(::futimens(fd, times), 0);
  ::close(fd);
}

TEST_F(LocatordTerrainTest, ARestartMapsTheDemsMeshWithoutReadingTheRaster) {
  ScratchDir own, cache;
  const std::string dem = own.path() + "/dem.tif";
  gis::testing::WriteDem(dem, *dem_);
  const std::vector<std::string> flags = {"--mesh-cache", cache.path()};
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(StartLocatord(DemSpec(dem), flags, &server).ok());
  const v1::DatasetStats first = GetStats(*NewStub(*server)).dataset();
  EXPECT_FALSE(first.mesh_cache().mapped());
  ASSERT_TRUE(first.has_simplification());
  server->SendSignal(SIGTERM);
  ASSERT_EQ(server->WaitForExit(kExitTimeout), 0);

  // Same inode, size and mtime, but no raster any more: reading it fails.
  GarbleKeepingIdentity(dem);
  ASSERT_TRUE(StartLocatord(DemSpec(dem), flags, &server).ok());
  auto stub = NewStub(*server);
  const v1::DatasetStats mapped = GetStats(*stub).dataset();
  EXPECT_TRUE(mapped.mesh_cache().mapped());
  EXPECT_EQ(mapped.simplification().SerializeAsString(),
            first.simplification().SerializeAsString());
  EXPECT_EQ(mapped.crs().epsg_code(), 32633u);
  EXPECT_EQ(mapped.vertices(), first.vertices());
  EXPECT_THAT(server->StderrText(),
              HasSubstr("found the mesh of " + DemSpec(dem) +
                        " by the identity of its files, without reading "
                        "them"));
  EXPECT_THAT(server->StderrText(),
              ::testing::Not(HasSubstr("loading dataset")));
  v1::LocateResponse response;
  ASSERT_TRUE(LocateOne(*stub, PixelCentre(20, 20), &response).ok());
  EXPECT_NEAR(response.value(), PixelValue(20, 20), kMaxError);
  server->SendSignal(SIGTERM);
  ASSERT_EQ(server->WaitForExit(kExitTimeout), 0);

  // Touched: the key no longer applies, the raster is read, and it is
  // garbage now.
  ASSERT_EQ(::utimensat(AT_FDCWD, dem.c_str(), nullptr, 0), 0);
  ASSERT_TRUE(ServerProcess::Spawn(LOCATORD_PATH,
                                   {"--dataset", DemSpec(dem), "--mesh-cache",
                                    cache.path(), "--listen", "127.0.0.1:0"},
                                   &server)
                  .ok());
  EXPECT_EQ(server->WaitForExit(kExitTimeout), 1);
  EXPECT_THAT(server->StderrText(),
              HasSubstr("not mapping the cached mesh of " + DemSpec(dem) +
                        ": " + dem + " changed since the mesh was built"));
  EXPECT_THAT(server->StderrText(),
              HasSubstr(dem + ": GDAL cannot open it as a raster"));
}

// A Reload may load a raster or a LAS file of the reload dir with their
// harmless options, and is refused a raster that names other files (a VRT,
// even under a .tif name) or a driver that may.
TEST(LocatordTerrainReloadTest, RastersAndLasFilesReloadUnderThePolicy) {
  ScratchDir reload, outside;
  gis::testing::DemFixture dem = gis::testing::HillDem(12, 10, 30);
  gis::testing::WriteDem(reload.path() + "/dem.tif", dem);
  gis::testing::WriteDem(outside.path() + "/secret.tif", dem);
  const std::string vrt =
      "<VRTDataset rasterXSize=\"12\" rasterYSize=\"10\"><VRTRasterBand "
      "dataType=\"Float32\" band=\"1\"><SimpleSource><SourceFilename>" +
      outside.path() +
      "/secret.tif</SourceFilename><SourceBand>1</SourceBand>"
      "</SimpleSource></VRTRasterBand></VRTDataset>";
  gis::testing::WriteFile(reload.path() + "/mosaic.vrt", vrt);
  gis::testing::WriteFile(reload.path() + "/mosaic.tif", vrt);
  gis::testing::LasFileOptions las;
  las.offset = {500000, 5500000, 0};
  gis::testing::WriteLasFile(reload.path() + "/tile.las", Tile(), las);
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(
      StartLocatord("uniform:300:7", {"--reload-dir", reload.path()}, &server)
          .ok());
  auto stub = NewStub(*server);

  v1::ReloadResponse response;
  grpc::Status status = Reload(*stub, "dem.tif?max_error=0.5", &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_TRUE(response.dataset().has_simplification());
  EXPECT_LE(response.dataset().simplification().max_error(), 0.5);
  EXPECT_EQ(response.dataset().simplification().source_samples(), 120u);
  EXPECT_EQ(response.dataset().crs().epsg_code(), 32633u);

  status = Reload(*stub, "tile.las?classes=2&returns=last", &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.dataset().input_points(), uint64_t{kSide * kSide});

  for (const std::string refused :
       {"mosaic.vrt", "mosaic.tif", "raster:mosaic.vrt?driver=VRT",
        "dem.tif?driver=VRT"}) {
    status = Reload(*stub, refused, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::PERMISSION_DENIED)
        << refused;
    EXPECT_THAT(status.error_message(), HasSubstr("a Reload may read"))
        << refused;
  }
  // The LAS ground is still what is served.
  EXPECT_EQ(GetStats(*stub).dataset().input_points(), uint64_t{kSide * kSide});
}

TEST(LocatordTerrainStartupTest, CompressedLasAndBadRastersStopTheStart) {
  ScratchDir dir;
  const std::string laz = dir.path() + "/tile.laz";
  gis::testing::WriteFile(laz, "LASF");
  gis::testing::DemFixture rotated = gis::testing::HillDem(8, 8, 10);
  rotated.geotransform[2] = 0.5;
  const std::string turned = dir.path() + "/rotated.tif";
  gis::testing::WriteDem(turned, rotated);
  const struct {
    std::string spec;
    std::string message;
  } rows[] = {
      {laz + "?classes=2",
       "FAILED_PRECONDITION: " + laz + ": a compressed LAS file (LAZ)"},
      {turned, turned + " has a rotated geotransform"},
      {turned + "?max_error=-1", "option 'max_error' must be a finite number"},
      {dir.path() + "/pts.csv?classes=2",
       "unknown option 'classes' (known: max_error, max_points)"},
  };
  for (const auto& row : rows) {
    std::unique_ptr<ServerProcess> server;
    ASSERT_TRUE(ServerProcess::Spawn(
                    LOCATORD_PATH,
                    {"--dataset", row.spec, "--listen", "127.0.0.1:0"}, &server)
                    .ok());
    EXPECT_EQ(server->WaitForExit(kExitTimeout), 1) << row.spec;
    EXPECT_THAT(server->StderrText(), HasSubstr(row.message)) << row.spec;
  }
}

}  // namespace
}  // namespace locator::test
