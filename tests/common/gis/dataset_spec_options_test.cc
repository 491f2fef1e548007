#include "common/gis/dataset_spec_options.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace locator::gis {
namespace {

using ::testing::HasSubstr;

TEST(DatasetSpecOptionsTest, OptionsBeginAtTheFirstQuestionMark) {
  SpecParts parts = SplitSpec("dir/dem.tif?band=2&max_error=0.5");
  EXPECT_EQ(parts.prefix, "");
  EXPECT_EQ(parts.source, "dir/dem.tif");
  EXPECT_EQ(parts.options, "?band=2&max_error=0.5");
  parts = SplitSpec("raster:a.png?where=x?y", "raster:");
  EXPECT_EQ(parts.prefix, "raster:");
  EXPECT_EQ(parts.source, "a.png");
  EXPECT_EQ(parts.options, "?where=x?y");
  parts = SplitSpec("points.csv");
  EXPECT_EQ(parts.source, "points.csv");
  EXPECT_EQ(parts.options, "");
}

TEST(DatasetSpecOptionsTest, ParsesAndDecodesOptionsInOrder) {
  std::vector<SpecOption> options;
  ASSERT_TRUE(
      ParseSpecOptions("a.gpkg?where=k%3D'a%26b'&&z=h&empty=", &options).ok());
  ASSERT_EQ(options.size(), 3u);
  EXPECT_EQ(options[0].name, "where");
  EXPECT_EQ(options[0].value, "k='a&b'");
  EXPECT_EQ(options[0].text, "where=k%3D'a%26b'");
  EXPECT_EQ(options[1].name, "z");
  EXPECT_EQ(options[2].value, "");
}

TEST(DatasetSpecOptionsTest, SourceExtensionsIgnoreCaseAndOptions) {
  constexpr std::string_view kTif[] = {".tif"};
  EXPECT_TRUE(SourceHasExtension("DEM.TIF?band=1", kTif));
  EXPECT_FALSE(SourceHasExtension("dem.csv?x=.tif", kTif));
  EXPECT_FALSE(SourceHasExtension("tif", kTif));
}

TEST(DatasetSpecOptionsTest, TakesTheSimplifyOptionsAndKeepsTheOthers) {
  SimplifySpec simplify;
  std::string rest;
  ASSERT_TRUE(TakeSimplifyOptions("a.gpkg?layer=x&max_error=0.25&z=h"
                                  "&max_points=1000",
                                  &simplify, &rest)
                  .ok());
  EXPECT_TRUE(simplify.requested);
  EXPECT_EQ(simplify.max_error, 0.25);
  EXPECT_EQ(simplify.max_points, 1000u);
  EXPECT_EQ(rest, "a.gpkg?layer=x&z=h");

  ASSERT_TRUE(
      TakeSimplifyOptions("pts.csv?max_error=0", &simplify, &rest).ok());
  EXPECT_TRUE(simplify.requested);
  EXPECT_EQ(simplify.max_error, 0);
  EXPECT_EQ(rest, "pts.csv");

  ASSERT_TRUE(TakeSimplifyOptions("uniform:100", &simplify, &rest).ok());
  EXPECT_FALSE(simplify.requested);
  EXPECT_EQ(rest, "uniform:100");
}

TEST(DatasetSpecOptionsTest, RejectsBadSimplifyOptionsNamingThem) {
  const struct {
    const char* spec;
    const char* message;
  } kCases[] = {
      {"a.tif?max_error=-1",
       "option 'max_error' must be a finite number >= 0, "
       "got '-1'"},
      {"a.tif?max_error=nan", "got 'nan'"},
      {"a.tif?max_error=inf", "got 'inf'"},
      {"a.tif?max_error=1e999", "got '1e999'"},
      {"a.tif?max_error=", "got ''"},
      {"a.tif?max_error=0.5m", "got '0.5m'"},
      {"a.tif?max_points=2",
       "option 'max_points' must be an integer from 3 "
       "to 4294967295, got '2'"},
      {"a.tif?max_points=4294967296", "got '4294967296'"},
      {"a.tif?max_points=-5", "got '-5'"},
      {"a.tif?max_error=1&max_error=2", "option 'max_error' given twice"},
      {"a.tif?max_error", "option 'max_error' has no '=VALUE'"},
      {"a.tif?max_error=%zz", "option 'max_error' has a malformed %-escape"},
  };
  for (const auto& c : kCases) {
    SimplifySpec simplify;
    std::string rest;
    const Status status = TakeSimplifyOptions(c.spec, &simplify, &rest);
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << c.spec;
    EXPECT_THAT(status.message(), HasSubstr(c.message)) << c.spec;
    EXPECT_THAT(status.message(),
                HasSubstr("dataset spec '" + std::string(c.spec) + "'"))
        << c.spec;
  }
}

// A spec's errors echo what the request wrote, cut short: the spec, the
// option's name and its value each as QuotedInput shows them.
TEST(DatasetSpecOptionsTest, ErrorsQuoteTheSpecAndItsValuesShort) {
  const std::string value(100000, '9');
  const std::string spec = "a.tif?max_points=" + value;
  SimplifySpec simplify;
  std::string rest;
  const Status status = TakeSimplifyOptions(spec, &simplify, &rest);
  EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
  EXPECT_LT(status.message().size(), 400u) << status.message();
  EXPECT_THAT(status.message(), HasSubstr("(100017 bytes)"));
  EXPECT_THAT(status.message(), HasSubstr("(100000 bytes)"));
  const Status unknown = UnknownSpecOption("a.tif", "\x01\nname", "band");
  EXPECT_THAT(unknown.message(),
              HasSubstr("unknown option '\\x01\\x0aname' (known: band, "
                        "max_error, max_points)"));
}

}  // namespace
}  // namespace locator::gis
