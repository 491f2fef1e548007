#include "client/points_reader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "common/text_fields.h"

namespace locator {
namespace {

// Writes `text` to a file of its own under the test temp dir.
std::string WriteFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "points_reader_" + name;
  std::ofstream(path) << text;
  return path;
}

// Reads all of `path` in chunks of `chunk`; returns the chunk sizes.
std::vector<size_t> ChunkSizes(const std::string& path, size_t chunk,
                               std::vector<double>* all_xs,
                               std::vector<double>* all_ys) {
  std::unique_ptr<PointsReader> reader;
  EXPECT_TRUE(PointsReader::Open(path, &reader).ok());
  std::vector<size_t> sizes;
  std::vector<double> xs, ys;
  do {
    const Status status = reader->ReadChunk(chunk, &xs, &ys);
    EXPECT_TRUE(status.ok()) << status.ToString();
    EXPECT_EQ(xs.size(), ys.size());
    sizes.push_back(xs.size());
    all_xs->insert(all_xs->end(), xs.begin(), xs.end());
    all_ys->insert(all_ys->end(), ys.begin(), ys.end());
  } while (!xs.empty());
  return sizes;
}

// The status of reading all of `text`.
Status ReadAllOf(const std::string& name, const std::string& text) {
  std::vector<Point2> points;
  return ReadAllPoints(WriteFile(name, text), &points);
}

TEST(ParseDoubleTest, AcceptsWholeNumbersOnly) {
  double value = 0;
  EXPECT_TRUE(ParseDouble("-1.5e3", &value));
  EXPECT_EQ(value, -1500);
  EXPECT_TRUE(ParseDouble("+2", &value));
  EXPECT_EQ(value, 2);
  EXPECT_TRUE(ParseDouble("nan", &value));
  EXPECT_FALSE(ParseDouble("", &value));
  EXPECT_FALSE(ParseDouble("1.5x", &value));
  EXPECT_FALSE(ParseDouble("+-1", &value));
  EXPECT_FALSE(ParseDouble("abc", &value));
}

TEST(PointsReaderTest, ReadsCsvWithHeaderCommentsAndBlankLines) {
  const std::string path = WriteFile(
      "csv", "x,y\n# a comment\n1,2\n\n 3 , 4 # trailing comment\n5,6,7\n");
  std::vector<double> xs, ys;
  ChunkSizes(path, 100, &xs, &ys);
  EXPECT_EQ(xs, (std::vector<double>{1, 3, 5}));
  EXPECT_EQ(ys, (std::vector<double>{2, 4, 6}));
}

TEST(PointsReaderTest, ReadsWhitespaceSeparatedRows) {
  const std::string path = WriteFile("ws", "1 2\n-3\t4.5\r\n  6   7  extra\n");
  std::vector<double> xs, ys;
  ChunkSizes(path, 100, &xs, &ys);
  EXPECT_EQ(xs, (std::vector<double>{1, -3, 6}));
  EXPECT_EQ(ys, (std::vector<double>{2, 4.5, 7}));
}

TEST(PointsReaderTest, ReadsInChunksOfTheRequestedSize) {
  std::string text;
  for (int i = 0; i < 7; ++i) {
    text += std::to_string(i) + "," + std::to_string(10 * i) + "\n";
  }
  std::vector<double> xs, ys;
  EXPECT_EQ(ChunkSizes(WriteFile("chunks", text), 3, &xs, &ys),
            (std::vector<size_t>{3, 3, 1, 0}));
  EXPECT_EQ(xs, (std::vector<double>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(ys.back(), 60);
}

TEST(PointsReaderTest, ErrorsNameTheFileAndLine) {
  const std::string path = WriteFile("bad", "x,y\n1,2\n3,zz\n");
  std::vector<Point2> points;
  const Status status = ReadAllPoints(path, &points);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(status.message(), path + ":3: 'zz' is not a number");
}

TEST(PointsReaderTest, ReportsTheLineOfAnErrorInALaterChunk) {
  const std::string path = WriteFile("late", "1 1\n2 2\n3 3\n4\n");
  std::unique_ptr<PointsReader> reader;
  ASSERT_TRUE(PointsReader::Open(path, &reader).ok());
  std::vector<double> xs, ys;
  EXPECT_TRUE(reader->ReadChunk(2, &xs, &ys).ok());
  const Status status = reader->ReadChunk(2, &xs, &ys);
  EXPECT_EQ(status.message(), path + ":4: expected x and y, found 1 field");
}

TEST(PointsReaderTest, RejectsNonFiniteCoordinates) {
  const Status status = ReadAllOf("nan", "1,2\nnan,0\n");
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(status.message().find(":2: 'nan' is not a finite number"),
            std::string::npos)
      << status.message();
  EXPECT_FALSE(ReadAllOf("inf", "1 inf\n").ok());
}

TEST(PointsReaderTest, AnOverflowingCoordinateIsNotFinite) {
  // As a dataset reads it (common/text_fields.h), not "not a number".
  EXPECT_NE(ReadAllOf("overflow", "1e400 0\n")
                .message()
                .find(":1: '1e400' is not a finite number"),
            std::string::npos);
}

TEST(PointsReaderTest, AnEmptyCoordinateIsNotANumber) {
  const Status status = ReadAllOf("empty_field", "1,2\n1,,2\n");
  EXPECT_NE(status.message().find(":2: '' is not a number"), std::string::npos)
      << status.message();
}

TEST(PointsReaderTest, ReplaysTheCsvThatBatchWrites) {
  // Empty cells after x and y (no value, no barycentric coordinates).
  const std::string path =
      WriteFile("batch",
                "x,y,type,triangle_id,v0,v1,v2,b0,b1,b2,value,cost\n"
                "5,6,OUTSIDE_CONVEX_HULL,0,0,0,0,,,,,3\n");
  std::vector<double> xs, ys;
  ChunkSizes(path, 100, &xs, &ys);
  EXPECT_EQ(xs, (std::vector<double>{5}));
  EXPECT_EQ(ys, (std::vector<double>{6}));
}

TEST(PointsReaderTest, OnlyTheFirstRowMayBeAHeader) {
  const Status status = ReadAllOf("header_late", "1,2\nx,y\n");
  EXPECT_NE(status.message().find(":2: 'x' is not a number"), std::string::npos)
      << status.message();
}

TEST(PointsReaderTest, MissingFileIsNotFound) {
  std::unique_ptr<PointsReader> reader;
  const Status status =
      PointsReader::Open(::testing::TempDir() + "no_such_points", &reader);
  EXPECT_EQ(status.code(), Status::Code::kNotFound);
}

TEST(ReadAllPointsTest, ReadsEveryPoint) {
  std::vector<Point2> points;
  ASSERT_TRUE(ReadAllPoints(WriteFile("all", "1,2\n3,4\n"), &points).ok());
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1].x, 3);
  EXPECT_EQ(points[1].y, 4);
}

TEST(ReadAllPointsTest, AFileWithoutPointsIsAnError) {
  EXPECT_EQ(ReadAllOf("empty", "x,y\n# nothing\n").code(),
            Status::Code::kInvalidArgument);
}

}  // namespace
}  // namespace locator
