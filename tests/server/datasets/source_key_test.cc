// Source keys (server/datasets/source_key.h): what a key records round-trips
// exactly; a key of another spec, a damaged key and a truncated one are
// refused naming the file; a file replaced, written, removed or a side-car
// that appears is noticed, and an untouched file is not.

#include "server/datasets/source_key.h"

#include <fcntl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "tests/core/scratch_dir.h"

namespace locator {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

void Write(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << path;
}

std::string Read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)),
                     std::istreambuf_iterator<char>());
}

class SourceKeyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    data_ = files_.path() + "/dem with spaces.tif";
    aux_ = data_ + ".aux.xml";
    Write(data_, "raster bytes");
    key_.files = {IdentifyFile(data_), IdentifyFile(aux_)};
    key_.fingerprint = 0x0123456789abcdefULL;
    key_.crs = "PROJCRS[\"a\nb\"]";
    SimplificationStats s;
    s.source_samples = 1000;
    s.unserved_samples = 2;
    s.vertices = 57;
    s.triangles = 100;
    s.max_error = 0.1 + 0.2;  // not a short decimal
    s.target_error = 0.3;
    s.max_points = 64;
    s.build_seconds = 1.0 / 3;
    key_.simplification = s;
    spec_ = data_ + "?max_error=0.3";
  }

  test::ScratchDir files_, cache_;
  std::string data_, aux_, spec_;
  SourceKey key_;
};

TEST_F(SourceKeyTest, WhatIsRecordedIsReadBackExactly) {
  ASSERT_TRUE(key_.files[0].exists);
  ASSERT_FALSE(key_.files[1].exists);
  ASSERT_TRUE(WriteSourceKey(cache_.path(), spec_, key_).ok());
  EXPECT_THAT(SourceKeyPath(cache_.path(), spec_),
              StartsWith(cache_.path() + "/source-"));
  SourceKey read;
  const Status status = ReadSourceKey(cache_.path(), spec_, &read);
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_EQ(read.files, key_.files);
  EXPECT_EQ(read.fingerprint, key_.fingerprint);
  EXPECT_EQ(read.crs, key_.crs);
  ASSERT_TRUE(read.simplification.has_value());
  EXPECT_EQ(read.simplification->max_error, key_.simplification->max_error);
  EXPECT_EQ(read.simplification->build_seconds,
            key_.simplification->build_seconds);
  EXPECT_EQ(read.simplification->unserved_samples, 2u);
  EXPECT_EQ(read.simplification->max_points, 64u);
  EXPECT_TRUE(CheckSourceFiles(read).ok());

  key_.simplification.reset();
  ASSERT_TRUE(WriteSourceKey(cache_.path(), spec_, key_).ok());
  ASSERT_TRUE(ReadSourceKey(cache_.path(), spec_, &read).ok());
  EXPECT_FALSE(read.simplification.has_value());
}

TEST_F(SourceKeyTest, OtherSpecsHaveNoKeyAndBadKeysAreNamed) {
  SourceKey read;
  EXPECT_EQ(ReadSourceKey(cache_.path(), spec_, &read).code(),
            Status::Code::kNotFound);
  ASSERT_TRUE(WriteSourceKey(cache_.path(), spec_, key_).ok());
  EXPECT_EQ(ReadSourceKey(cache_.path(), data_, &read).code(),
            Status::Code::kNotFound);

  const std::string path = SourceKeyPath(cache_.path(), spec_);
  const std::string good = Read(path);
  std::string damaged = good;
  damaged[damaged.find("fingerprint ") + 12] ^= 1;
  Write(path, damaged);
  Status status = ReadSourceKey(cache_.path(), spec_, &read);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(status.message(),
            "source key " + path + ": its checksum does not match");

  Write(path, good.substr(0, good.size() / 2));
  status = ReadSourceKey(cache_.path(), spec_, &read);
  EXPECT_THAT(status.message(), HasSubstr("its checksum does not match"));

  Write(path, "locator source key 0\n");
  status = ReadSourceKey(cache_.path(), spec_, &read);
  EXPECT_THAT(status.message(), HasSubstr("not a source key of this version"));

  // A key copied under another spec's name.
  Write(SourceKeyPath(cache_.path(), data_), good);
  status = ReadSourceKey(cache_.path(), data_, &read);
  EXPECT_THAT(status.message(), HasSubstr("it is the key of another spec"));
}

TEST_F(SourceKeyTest, ChangedFilesAreNoticed) {
  ASSERT_TRUE(CheckSourceFiles(key_).ok());
  // Rewritten in place, same size: a new modification time.
  struct stat before;
  ASSERT_EQ(::stat(data_.c_str(), &before), 0);
  const struct timespec later[2] = {before.st_atim,
                                    {before.st_mtim.tv_sec + 1, 0}};
  ASSERT_EQ(::utimensat(AT_FDCWD, data_.c_str(), later, 0), 0);
  Status status = CheckSourceFiles(key_);
  EXPECT_EQ(status.code(), Status::Code::kFailedPrecondition);
  EXPECT_EQ(status.message(), data_ + " changed since the mesh was built");
  key_.files[0] = IdentifyFile(data_);
  ASSERT_TRUE(CheckSourceFiles(key_).ok());

  // Replaced by a copy with the same size and times: another inode.
  const std::string copy = data_ + ".new";
  std::filesystem::copy_file(data_, copy);
  const struct timespec same[2] = {later[0], later[1]};
  ASSERT_EQ(::utimensat(AT_FDCWD, copy.c_str(), same, 0), 0);
  std::filesystem::rename(copy, data_);
  EXPECT_THAT(CheckSourceFiles(key_).message(),
              HasSubstr(" changed since the mesh was built"));
  key_.files[0] = IdentifyFile(data_);

  Write(aux_, "<PAMDataset/>");
  EXPECT_EQ(CheckSourceFiles(key_).message(),
            aux_ + " appeared since the mesh was built");
  std::filesystem::remove(aux_);
  ASSERT_TRUE(CheckSourceFiles(key_).ok());
  std::filesystem::remove(data_);
  EXPECT_EQ(CheckSourceFiles(key_).message(),
            data_ + " is gone since the mesh was built");
}

}  // namespace
}  // namespace locator
