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

#include "tests/core/scratch_dir.h"
#include "tests/server/e2e_support.h"

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

  for (const std::string escape :
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

}  // namespace
}  // namespace locator::test
