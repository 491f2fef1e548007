// Which datasets a Reload RPC may load, end to end: the configured one
// always; without --reload-dir nothing else (PERMISSION_DENIED, the same for
// a file that exists and one that does not); with it, files inside the
// directory and generator specs bounded by --max-dataset-points, but no
// escape by ".." or a symlink.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "tests/common/gis/gis_fixtures.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;
using ::testing::HasSubstr;

grpc::Status Reload(v1::Locator::Stub& stub, const std::string& dataset,
                    v1::ReloadResponse* response = nullptr) {
  grpc::ClientContext context;
  v1::ReloadRequest request;
  request.set_dataset(dataset);
  v1::ReloadResponse ignored;
  return stub.Reload(&context, request, response ? response : &ignored);
}

// Three points as CSV at `path`.
void WriteTriangle(const std::string& path) {
  std::ofstream(path) << "x,y\n0,0\n4,0\n0,3\n";
}

TEST(LocatordReloadPolicyTest, WithoutAReloadDirOnlyTheConfiguredDataset) {
  const TestDatasetFile configured;
  ScratchDir dir;
  const std::string readable = dir.path() + "/readable.csv";
  WriteTriangle(readable);
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(StartLocatord(configured.path(), {}, &server).ok());
  auto stub = NewStub(*server);

  // An existing, readable, valid file and a missing one: the same answer.
  const grpc::Status existing = Reload(*stub, readable);
  const grpc::Status missing = Reload(*stub, dir.path() + "/missing.csv");
  EXPECT_EQ(existing.error_code(), grpc::StatusCode::PERMISSION_DENIED);
  EXPECT_EQ(missing.error_code(), grpc::StatusCode::PERMISSION_DENIED);
  EXPECT_EQ(existing.error_message(), missing.error_message());
  EXPECT_THAT(existing.error_message(), HasSubstr("--reload-dir"));
  // A generator is refused before anything is built.
  EXPECT_EQ(Reload(*stub, "uniform:10000000").error_code(),
            grpc::StatusCode::PERMISSION_DENIED);
  EXPECT_EQ(GetStats(*stub).generation(), 1u);

  // The configured dataset, by default or by its spec.
  v1::ReloadResponse response;
  ASSERT_TRUE(Reload(*stub, "", &response).ok());
  EXPECT_EQ(response.generation(), 2u);
  ASSERT_TRUE(Reload(*stub, configured.path(), &response).ok());
  EXPECT_EQ(response.generation(), 3u);
  EXPECT_EQ(response.dataset().source(), configured.path());
}

TEST(LocatordReloadPolicyTest,
     WithAReloadDirFilesInsideItAndBoundedGenerators) {
  const TestDatasetFile configured;
  ScratchDir root;
  const std::string dir = root.path() + "/datasets";
  fs::create_directory(dir);
  WriteTriangle(dir + "/triangle.csv");
  const std::string outside = root.path() + "/outside.csv";
  WriteTriangle(outside);
  fs::create_symlink(outside, dir + "/link.csv");
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(
      StartLocatord(configured.path(),
                    {"--reload-dir", dir, "--max-dataset-points", "100000"},
                    &server)
          .ok());
  auto stub = NewStub(*server);

  for (const std::string& escape :
       {std::string("../outside.csv"), dir + "/../outside.csv", outside,
        std::string("link.csv"), std::string("missing.csv")}) {
    const grpc::Status status = Reload(*stub, escape);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::PERMISSION_DENIED)
        << escape << ": " << status.error_message();
  }
  EXPECT_EQ(GetStats(*stub).generation(), 1u);

  // A generator over --max-dataset-points fails before it is built.
  const grpc::Status too_big = Reload(*stub, "uniform:10000000");
  EXPECT_EQ(too_big.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  EXPECT_THAT(too_big.error_message(), HasSubstr("100000"));

  v1::ReloadResponse response;
  grpc::Status status = Reload(*stub, "triangle.csv", &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.dataset().source(),
            fs::canonical(dir + "/triangle.csv").string());
  EXPECT_EQ(response.dataset().triangles(), 1u);
  status = Reload(*stub, "uniform:500:3", &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.dataset().input_points(), 500u);
}

// The attacks of issue 26, hole 4, with the admin's Reload and a GeoPackage
// inside the reload dir: open options that run SQL (ATTACH another file and
// read it through a where sub-select; VACUUM INTO a new file) and where
// clauses that call SQL functions are PERMISSION_DENIED before anything is
// opened; no file is written and the dataset is not replaced.
TEST(LocatordReloadPolicyTest, GisOptionsCannotRunSqlOrReachOtherFiles) {
  ScratchDir root;
  const std::string dir = root.path() + "/datasets";
  fs::create_directory(dir);
  const std::string gpkg = gis::testing::UtmHillGeoPackage(5, dir);
  // A database outside the dir with a secret in it.
  const std::string secret_db = gis::testing::UtmHillGeoPackage(3, root.path());
  const std::string written = root.path() + "/out.db";
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(StartLocatord(gpkg, {"--reload-dir", dir}, &server).ok());
  auto stub = NewStub(*server);

  const std::string attach =
      "?oo=PRELUDE_STATEMENTS=ATTACH%20DATABASE%20'" + secret_db + "'%20AS%20x";
  for (const std::string& requested : {
           gpkg + attach +
               "&where=(SELECT%20count(*)%20FROM%20x.hill)%20%3E%200",
           gpkg + "?oo=PRELUDE_STATEMENTS=VACUUM%20INTO%20'" + written + "'",
           gpkg + "?oo=prelude_statements=SELECT%201",
           gpkg + "?where=(SELECT%20count(*)%20FROM%20sqlite_master)%20%3E%200",
           gpkg + "?where=length(BlobFromFile('%2Fetc%2Fhostname'))%20%3E%200",
           gpkg + "?where=load_extension('" + secret_db + "')%20IS%20NULL",
           gpkg + "?a_srs=%2Bproj%3Dlonglat%20%2Bnadgrids%3D%2Fdev%2Fptmx",
           "ogr:" + gpkg + "?driver=SQLite",
       }) {
    const grpc::Status status = Reload(*stub, requested);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::PERMISSION_DENIED)
        << requested << ": " << status.error_message();
  }
  EXPECT_FALSE(fs::exists(written));
  EXPECT_EQ(GetStats(*stub).generation(), 1u);

  // Harmless options still reload: a plain where clause and an a_srs.
  v1::ReloadResponse response;
  const grpc::Status status = Reload(
      *stub, gpkg + "?where=height%20%3E%200&a_srs=EPSG:32632", &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.dataset().input_points(), 25u);
  EXPECT_EQ(response.dataset().source(),
            fs::canonical(gpkg).string() +
                "?where=height%20%3E%200&a_srs=EPSG:32632&driver=GPKG");
}

}  // namespace
}  // namespace locator::test
