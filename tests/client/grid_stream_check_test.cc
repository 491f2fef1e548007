// GridStreamCheck: what a Grid stream must look like, message by message.

#include "client/grid_stream_check.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace locator {
namespace {

using ::testing::HasSubstr;

constexpr uint32_t kWidth = 3;
constexpr uint32_t kHeight = 4;

v1::GridResponse Rows(uint32_t first, uint32_t rows, int values = -1) {
  v1::GridResponse message;
  message.set_first_row(first);
  message.set_rows(rows);
  const int count = values >= 0 ? values : static_cast<int>(rows * kWidth);
  for (int i = 0; i < count; ++i) message.add_values(i);
  return message;
}

v1::GridResponse Header(uint32_t first, uint32_t rows) {
  v1::GridResponse message = Rows(first, rows);
  message.mutable_header()->set_width(kWidth);
  message.mutable_header()->set_height(kHeight);
  return message;
}

TEST(GridStreamCheckTest, RowsInAnyOrderUntilAllHaveCome) {
  GridStreamCheck check;
  EXPECT_FALSE(check.has_header());
  ASSERT_TRUE(check.Check(Header(2, 2)).ok());
  EXPECT_TRUE(check.has_header());
  EXPECT_EQ(check.header().width(), kWidth);
  Status complete = check.CheckComplete();
  EXPECT_EQ(complete.code(), Status::Code::kInternal);
  EXPECT_EQ(complete.message(),
            "the server's grid stream: ended after 2 of 4 rows");
  ASSERT_TRUE(check.Check(Rows(0, 0)).ok());  // an empty message is fine
  ASSERT_TRUE(check.Check(Rows(0, 1)).ok());
  ASSERT_TRUE(check.Check(Rows(1, 1)).ok());
  EXPECT_TRUE(check.CheckComplete().ok());
}

TEST(GridStreamCheckTest, BrokenStreamsAreNamed) {
  struct Case {
    std::vector<v1::GridResponse> messages;
    std::string problem;
  };
  v1::GridResponse empty_header = Header(0, 0);
  empty_header.mutable_header()->set_height(0);
  const std::vector<Case> cases = {
      {{Rows(0, 1)}, "rows before the header"},
      {{Header(0, 1), Header(1, 1)}, "a second header"},
      {{empty_header}, "the header's raster is 3 x 0"},
      {{Header(0, 1), Rows(3, 2)}, "rows 3 + 2 outside the raster's 4"},
      {{Header(0, 1), Rows(5, 0)}, "rows 5 + 0 outside the raster's 4"},
      {{Header(0, 1), Rows(1, 2, 5)}, "5 values for 2 rows of 3"},
      {{Header(0, 2), Rows(1, 1)}, "row 1 twice"}};
  for (const Case& c : cases) {
    GridStreamCheck check;
    Status status;
    for (const v1::GridResponse& message : c.messages) {
      status = check.Check(message);
      if (!status.ok()) break;
    }
    EXPECT_EQ(status.code(), Status::Code::kInternal) << c.problem;
    EXPECT_EQ(status.message(), "the server's grid stream: " + c.problem);
  }
  GridStreamCheck nothing;
  EXPECT_EQ(nothing.CheckComplete().message(),
            "the server's grid stream: no header");
}

}  // namespace
}  // namespace locator
