// ReloadPolicy: the configured dataset always; generator specs and files
// inside --reload-dir only with one; every other spec refused alike.

#include "server/reload_policy.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

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
    std::string spec = "unset";
    const grpc::Status status = policy.Resolve(requested, &spec);
    if (status.ok()) return spec;
    EXPECT_EQ(status.error_code(), grpc::StatusCode::PERMISSION_DENIED)
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
  for (const std::string requested :
       {secret_, root_.path() + "/missing.csv", std::string("uniform:500:1"),
        std::string("clusters:500:2"), dir_ + "/points.csv"}) {
    EXPECT_EQ(Resolved(policy, requested), "denied") << requested;
  }
  std::string spec;
  EXPECT_THAT(policy.Resolve(secret_, &spec).error_message(),
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
  std::ofstream(dir_ + "/dem.tif") << "raster";
  std::ofstream(dir_ + "/tile.bin") << "LASF";
  EXPECT_EQ(Resolved(policy, "dem.tif?max_error=0.5&band=2"),
            Canonical(dir_ + "/dem.tif") + "?max_error=0.5&band=2");
  EXPECT_EQ(Resolved(policy, "las:tile.bin?classes=2"),
            "las:" + Canonical(dir_ + "/tile.bin") + "?classes=2");
  EXPECT_EQ(Resolved(policy, "raster:tile.bin"),
            "raster:" + Canonical(dir_ + "/tile.bin"));
  EXPECT_EQ(Resolved(policy, "points.csv?max_points=100"),
            Canonical(dir_ + "/points.csv") + "?max_points=100");
  // The options never name the file.
  EXPECT_EQ(Resolved(policy, "missing.tif?x=" + dir_ + "/dem.tif"), "denied");
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
  std::string spec;
  const grpc::Status missing = policy.Resolve(root_.path() + "/x.csv", &spec);
  fs::rename(secret_, root_.path() + "/x.csv");
  const grpc::Status existing = policy.Resolve(root_.path() + "/x.csv", &spec);
  EXPECT_EQ(missing.error_code(), grpc::StatusCode::PERMISSION_DENIED);
  EXPECT_EQ(existing.error_code(), grpc::StatusCode::PERMISSION_DENIED);
  EXPECT_EQ(missing.error_message(), existing.error_message());
  // Inside the dir, too: a missing file says nothing more than a forbidden
  // one.
  EXPECT_EQ(Resolved(policy, "missing.csv"), "denied");
  // The dir itself and subdirectories are not datasets.
  EXPECT_EQ(Resolved(policy, "sub"), "denied");
  EXPECT_EQ(Resolved(policy, "."), "denied");
}

}  // namespace
}  // namespace locator
