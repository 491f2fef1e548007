#include "common/gis/ogr_dataset_spec.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace locator::gis {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(OgrDatasetSpecTest, RecognizesOgrExtensionsAndThePrefix) {
  EXPECT_TRUE(IsOgrDatasetSpec("dem.gpkg"));
  EXPECT_TRUE(IsOgrDatasetSpec("/data/Survey.SHP?z=height"));
  EXPECT_TRUE(IsOgrDatasetSpec("pts.geojson"));
  EXPECT_TRUE(IsOgrDatasetSpec("pts.fgb"));
  EXPECT_TRUE(IsOgrDatasetSpec("ogr:points.csv?oo=X_POSSIBLE_NAMES=x"));
  EXPECT_FALSE(IsOgrDatasetSpec("points.csv"));
  EXPECT_FALSE(IsOgrDatasetSpec("mesh.node"));
  EXPECT_FALSE(IsOgrDatasetSpec("uniform:1000"));
  EXPECT_FALSE(IsOgrDatasetSpec("gpkg"));
}

TEST(OgrDatasetSpecTest, ParsesEveryOption) {
  const StatusOr<OgrDatasetSpec> parsed = ParseOgrDatasetSpec(
      "ogr:a.csv?layer=pts&z=h&where=h%20%3E%2010%20AND%20k%3D'a%26b'"
      "&breaklines=lines&domain=area&a_srs=EPSG:32633"
      "&oo=X_POSSIBLE_NAMES=x&oo=Y_POSSIBLE_NAMES=y&driver=ESRI%"
      "20Shapefile");
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  const OgrDatasetSpec& spec = *parsed;
  EXPECT_EQ(spec.source, "a.csv");
  EXPECT_EQ(spec.layer, "pts");
  EXPECT_EQ(spec.z_field, "h");
  EXPECT_EQ(spec.where, "h > 10 AND k='a&b'");
  EXPECT_EQ(spec.breaklines_layer, "lines");
  EXPECT_EQ(spec.domain_layer, "area");
  EXPECT_EQ(spec.assigned_crs, "EPSG:32633");
  EXPECT_THAT(spec.open_options,
              ElementsAre("X_POSSIBLE_NAMES=x", "Y_POSSIBLE_NAMES=y"));
  EXPECT_EQ(spec.driver, "ESRI Shapefile");
}

TEST(OgrDatasetSpecTest, APathWithoutOptionsIsJustTheSource) {
  const StatusOr<OgrDatasetSpec> parsed = ParseOgrDatasetSpec("dir/dem.gpkg");
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  const OgrDatasetSpec& spec = *parsed;
  EXPECT_EQ(spec.source, "dir/dem.gpkg");
  EXPECT_TRUE(spec.layer.empty());
  EXPECT_TRUE(spec.open_options.empty());
}

TEST(OgrDatasetSpecTest, RejectsMalformedOptionsNamingThem) {
  const struct {
    const char* spec;
    const char* message;
  } kCases[] = {
      {"a.gpkg?color=red", "unknown option 'color'"},
      {"a.gpkg?layer", "option 'layer' has no '=VALUE'"},
      {"a.gpkg?layer=a&layer=b", "option 'layer' given twice"},
      {"a.gpkg?z=", "option 'z' is empty"},
      {"a.gpkg?where=a%2", "option 'where' has a malformed %-escape"},
      {"a.gpkg?where=a%zz", "option 'where' has a malformed %-escape"},
      {"a.gpkg?oo=NOVALUE", "open option 'NOVALUE' is not NAME=VALUE"},
      {"ogr:?layer=a", "no source before the options"},
  };
  for (const auto& c : kCases) {
    const Status status = ParseOgrDatasetSpec(c.spec).status();
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument) << c.spec;
    EXPECT_THAT(status.message(), HasSubstr(c.message)) << c.spec;
    EXPECT_THAT(status.message(), HasSubstr(c.spec)) << c.spec;
  }
}

// What a spec names is quoted short (QuotedInput: 80 bytes, control
// characters escaped), however long the spec: a Reload's spec is the
// client's text.
TEST(OgrDatasetSpecTest, QuotesWhatItNamesShort) {
  const std::string long_name(4000, 'c');
  const std::string quoted_long =
      "'" + std::string(80, 'c') + "...' (4000 bytes)";
  const struct {
    std::string spec;
    std::string message;
  } kCases[] = {
      {"a.gpkg?" + long_name + "=1",
       "dataset spec 'a.gpkg?" + std::string(73, 'c') +
           "...' (4009 bytes): unknown option " + quoted_long + " (known: "},
      {"a.gpkg?" + long_name, "option " + quoted_long + " has no '=VALUE'"},
      {"a.gpkg?" + long_name + "=%zz",
       "option " + quoted_long + " has a malformed %-escape"},
      {"a.gpkg?oo=" + long_name, "open option " + quoted_long + " is not"},
      {"a.gpkg?lay\ner=1", "unknown option 'lay\\x0aer'"},
  };
  for (const auto& c : kCases) {
    const Status status = ParseOgrDatasetSpec(c.spec).status();
    EXPECT_EQ(status.code(), Status::Code::kInvalidArgument);
    EXPECT_THAT(status.message(), HasSubstr(c.message));
    EXPECT_LT(status.message().size(), 400u);
  }
}

}  // namespace
}  // namespace locator::gis
