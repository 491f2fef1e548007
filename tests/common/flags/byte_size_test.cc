#include "common/flags/byte_size.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <limits>
#include <string>

namespace locator {
namespace {

struct Accepted {
  const char* text;
  size_t bytes;
};

class ByteSizeAcceptTest : public ::testing::TestWithParam<Accepted> {};

TEST_P(ByteSizeAcceptTest, Parses) {
  size_t bytes = 12345;  // must be overwritten
  const Status s = ParseByteSize(GetParam().text, &bytes);
  ASSERT_TRUE(s.ok()) << s.ToString();
  EXPECT_EQ(bytes, GetParam().bytes);
}

INSTANTIATE_TEST_SUITE_P(
    Units, ByteSizeAcceptTest,
    ::testing::Values(
        Accepted{"65536", 65536}, Accepted{"0", 0}, Accepted{"7B", 7},
        Accepted{"64KiB", 65536}, Accepted{"64K", 65536}, Accepted{"5KB", 5000},
        Accepted{"3MiB", 3 * 1024 * 1024}, Accepted{"2MB", 2'000'000},
        Accepted{"1GiB", size_t{1} << 30}, Accepted{"1G", size_t{1} << 30},
        // The largest whole number of GiB that fits.
        Accepted{"17179869183GiB", size_t{17179869183} << 30}));

class ByteSizeRejectTest : public ::testing::TestWithParam<const char*> {};

TEST_P(ByteSizeRejectTest, InvalidArgumentNamingTheText) {
  size_t bytes = 12345;
  const std::string text = GetParam();
  const Status s = ParseByteSize(text, &bytes);
  ASSERT_FALSE(s.ok()) << "'" << text << "' parsed as " << bytes;
  EXPECT_EQ(s.code(), Status::Code::kInvalidArgument);
  EXPECT_NE(s.message().find("'" + text + "'"), std::string::npos)
      << s.message();
  EXPECT_EQ(bytes, 12345u) << "output written on failure";
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, ByteSizeRejectTest,
    ::testing::Values("", "abc", "12XB", "-1", "1.5MiB", "KiB", " 64KiB",
                      "64 KiB", "64KiBs",
                      // size_t overflow in the number and in the product.
                      "99999999999999999999GiB", "99999999999999999999",
                      "17179869184GiB"));

}  // namespace
}  // namespace locator
