// The `locator` CLI's command line, parsed without a server.

#include "client/cli_flags.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace locator {
namespace {

using ::testing::HasSubstr;

// Parses "locator" followed by `words`.
Status Parse(const std::vector<std::string>& words, CliLine* line) {
  std::vector<const char*> argv = {"locator"};
  for (const std::string& word : words) argv.push_back(word.c_str());
  return ParseCliLine(static_cast<int>(argv.size()), argv.data(), line);
}

TEST(CliFlagsTest, CommandArgumentsAndFlagsAnywhere) {
  CliLine line;
  const Status parsed =
      Parse({"locate", "--json", "-0.5", "2", "--target", "h:1"}, &line);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(line.command, &RunLocate);
  EXPECT_EQ(line.args, (CliArgs{"-0.5", "2"}));
  EXPECT_TRUE(line.settings.json);
  EXPECT_EQ(line.channel.target, "h:1");
  EXPECT_EQ(line.deadline, std::chrono::milliseconds(5000));
  EXPECT_FALSE(line.help);
}

TEST(CliFlagsTest, EqualsFormsAndDoubleDash) {
  CliLine line;
  const Status parsed = Parse({"--target=h:2", "--deadline-ms=250", "--json",
                               "--", "locate", "-1", "--5"},
                              &line);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(line.channel.target, "h:2");
  EXPECT_EQ(line.deadline, std::chrono::milliseconds(250));
  EXPECT_EQ(line.command, &RunLocate);
  EXPECT_EQ(line.args, (CliArgs{"-1", "--5"}));
  CliLine help;
  ASSERT_TRUE(Parse({"stats", "-h"}, &help).ok());
  EXPECT_TRUE(help.help);
}

TEST(CliFlagsTest, EveryCommandIsFound) {
  EXPECT_EQ(FindCliCommand("locate"), &RunLocate);
  EXPECT_EQ(FindCliCommand("batch"), &RunBatch);
  EXPECT_EQ(FindCliCommand("stats"), &RunStats);
  EXPECT_EQ(FindCliCommand("retune"), &RunRetune);
  EXPECT_EQ(FindCliCommand("reload"), &RunReload);
  EXPECT_EQ(FindCliCommand("health"), &RunHealth);
  EXPECT_EQ(FindCliCommand("datasets"), &RunDatasets);
  EXPECT_EQ(FindCliCommand("profile"), &RunProfile);
  EXPECT_EQ(FindCliCommand("grid"), &RunGrid);
  EXPECT_EQ(FindCliCommand("Locate"), nullptr);
}

TEST(CliFlagsTest, NumericFlagsAndRetry) {
  CliLine line;
  ASSERT_TRUE(Parse({"--deadline-ms", "250", "--chunk", "17", "--retry",
                     "batch", "points.csv"},
                    &line)
                  .ok());
  EXPECT_EQ(line.command, &RunBatch);
  EXPECT_EQ(line.deadline, std::chrono::milliseconds(250));
  EXPECT_EQ(line.settings.chunk, 17u);
  EXPECT_TRUE(line.channel.retry_unavailable);
  EXPECT_EQ(line.args, CliArgs{"points.csv"});
}

TEST(CliFlagsTest, ReloadTakesTheSpecAndWaitsLongerUnlessTold) {
  CliLine defaulted;
  ASSERT_TRUE(
      Parse({"reload", "uniform:10:1", "--dataset", "terrain"}, &defaulted)
          .ok());
  EXPECT_EQ(defaulted.deadline, kLongCallDeadline);
  EXPECT_EQ(defaulted.args, CliArgs{"uniform:10:1"});
  EXPECT_EQ(defaulted.scope.dataset, "terrain");
  CliLine told;
  ASSERT_TRUE(Parse({"reload", "--deadline-ms", "1000"}, &told).ok());
  EXPECT_EQ(told.deadline, std::chrono::milliseconds(1000));
  EXPECT_TRUE(told.args.empty());
  EXPECT_TRUE(told.scope.dataset.empty());
}

TEST(CliFlagsTest, DatasetCrsAndInterpolationMakeTheScope) {
  CliLine line;
  const Status parsed =
      Parse({"--dataset", "terrain", "locate", "15.01", "49.6", "--crs",
             "EPSG:4326", "--interpolation", "natural-neighbor"},
            &line);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(line.scope.dataset, "terrain");
  EXPECT_EQ(line.scope.crs, "EPSG:4326");
  EXPECT_EQ(line.scope.interpolation, v1::INTERPOLATION_NATURAL_NEIGHBOR);
  EXPECT_EQ(line.args, (CliArgs{"15.01", "49.6"}));

  const std::vector<std::pair<std::string, v1::Interpolation>> names = {
      {"linear", v1::INTERPOLATION_LINEAR},
      {"natural-neighbor", v1::INTERPOLATION_NATURAL_NEIGHBOR},
      {"nearest", v1::INTERPOLATION_NEAREST}};
  for (const auto& [name, interpolation] : names) {
    CliLine batch;
    ASSERT_TRUE(Parse({"batch", "f.csv", "--interpolation", name}, &batch).ok())
        << name;
    EXPECT_EQ(batch.scope.interpolation, interpolation) << name;
  }
  CliLine plain;
  ASSERT_TRUE(Parse({"stats"}, &plain).ok());
  EXPECT_EQ(plain.scope.dataset, "");
  EXPECT_EQ(plain.scope.crs, "");
  EXPECT_EQ(plain.scope.interpolation, v1::INTERPOLATION_UNSPECIFIED);
}

TEST(CliFlagsTest, ProfileTakesTheLineAsPairsOrWkt) {
  CliLine line;
  Status parsed = Parse({"profile", "--line", "-1.5,2 3,4e1 5,-6", "--samples",
                         "11", "--csv", "--crs", "EPSG:4326"},
                        &line);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(line.command, &RunProfile);
  ASSERT_EQ(line.settings.profile.line.size(), 3u);
  EXPECT_EQ(line.settings.profile.line[0].x, -1.5);
  EXPECT_EQ(line.settings.profile.line[1].y, 40);
  EXPECT_EQ(line.settings.profile.line[2].y, -6);
  EXPECT_EQ(line.settings.profile.samples, 11u);
  EXPECT_TRUE(line.settings.csv);
  EXPECT_EQ(line.deadline, std::chrono::milliseconds(5000));

  CliLine wkt;
  parsed =
      Parse({"--json", "profile", "--line", "LINESTRING (0 1, 2 3)"}, &wkt);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  ASSERT_EQ(wkt.settings.profile.line.size(), 2u);
  EXPECT_EQ(wkt.settings.profile.line[1].x, 2);
  EXPECT_EQ(wkt.settings.profile.samples, 0u);
  EXPECT_TRUE(wkt.settings.json);
}

TEST(CliFlagsTest, GridTakesGdalStyleExtentSizeAndFormat) {
  CliLine line;
  Status parsed = Parse(
      {"--te",      "-10",         "-20.5",      "10",    "1e3",
       "--outsize", "640",         "480",        "grid",  "--out",
       "dem.tif",   "--of",        "GTiff",      "--co",  "COMPRESS=DEFLATE",
       "--co",      "PREDICTOR=3", "--a_nodata", "-9999", "--interpolation",
       "nearest",   "--dataset",   "terrain"},
      &line);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_EQ(line.command, &RunGrid);
  const GridSettings& grid = line.settings.grid;
  ASSERT_TRUE(grid.box.has_value());
  EXPECT_EQ(grid.box->min_x, -10);
  EXPECT_EQ(grid.box->min_y, -20.5);
  EXPECT_EQ(grid.box->max_x, 10);
  EXPECT_EQ(grid.box->max_y, 1000);
  EXPECT_EQ(grid.width, 640u);
  EXPECT_EQ(grid.height, 480u);
  EXPECT_EQ(grid.cell_size, 0);
  ASSERT_TRUE(grid.nodata.has_value());
  EXPECT_EQ(*grid.nodata, -9999);
  EXPECT_EQ(grid.format.driver, "GTiff");
  EXPECT_EQ(grid.format.creation_options,
            (std::vector<std::string>{"COMPRESS=DEFLATE", "PREDICTOR=3"}));
  EXPECT_EQ(grid.out, "dem.tif");
  EXPECT_EQ(line.scope.interpolation, v1::INTERPOLATION_NEAREST);
  EXPECT_EQ(line.scope.dataset, "terrain");
  EXPECT_EQ(line.deadline, kLongCallDeadline);
  EXPECT_TRUE(line.args.empty());

  // The cell size instead of the size; no box: the dataset's; --nodata is
  // --a_nodata; COG by default.
  CliLine by_cell;
  parsed = Parse({"grid", "--tr", "2.5", "2.5", "--out", "x.tif", "--nodata",
                  "nan", "--deadline-ms", "1000"},
                 &by_cell);
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_FALSE(by_cell.settings.grid.box.has_value());
  EXPECT_EQ(by_cell.settings.grid.cell_size, 2.5);
  EXPECT_EQ(by_cell.settings.grid.width, 0u);
  ASSERT_TRUE(by_cell.settings.grid.nodata.has_value());
  EXPECT_TRUE(std::isnan(*by_cell.settings.grid.nodata));
  EXPECT_EQ(by_cell.settings.grid.format.driver, "COG");
  EXPECT_EQ(by_cell.deadline, std::chrono::milliseconds(1000));

  CliLine no_nodata;
  ASSERT_TRUE(
      Parse({"grid", "--outsize", "1", "1", "--out", "x.tif"}, &no_nodata)
          .ok());
  EXPECT_FALSE(no_nodata.settings.grid.nodata.has_value());
}

TEST(CliFlagsTest, HelpNeedsNoCommand) {
  CliLine line;
  ASSERT_TRUE(Parse({"--help"}, &line).ok());
  EXPECT_TRUE(line.help);
  EXPECT_THAT(line.settings.usage, HasSubstr("usage: locator [flags]"));
  EXPECT_THAT(line.settings.usage, HasSubstr("--deadline-ms"));
}

TEST(CliFlagsTest, UsageProblemsAreNamed) {
  const std::vector<std::string> grid = {"grid", "--out", "x.tif"};
  const auto with = [](std::vector<std::string> words,
                       const std::vector<std::string>& more) {
    words.insert(words.end(), more.begin(), more.end());
    return words;
  };
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{}, "no command"},
      {{"--json"}, "no command"},
      {{"locat", "1", "2"}, "unknown command 'locat'"},
      {{"stats", "--deadline-ms", "0"},
       "--deadline-ms '0': must be a whole number >= 1"},
      {{"batch", "f", "--chunk", "-3"},
       "--chunk '-3': must be a whole number >= 1"},
      // Flags the command does not take.
      {{"health", "--dataset", "terrain"},
       "--dataset is for locate, batch, stats, retune, reload, profile and "
       "grid only"},
      {{"datasets", "--dataset", "terrain"},
       "--dataset is for locate, batch, stats, retune, reload, profile and "
       "grid only"},
      {{"stats", "--crs", "EPSG:4326"},
       "--crs is for locate, batch and profile only"},
      {{"grid", "--crs", "EPSG:4326"},
       "--crs is for locate, batch and profile only"},
      {{"stats", "--interpolation", "linear"},
       "--interpolation is for locate, batch, profile and grid only"},
      {{"batch", "f", "--json"},
       "--json is for locate, stats, retune, reload, health, datasets and "
       "profile only"},
      {{"stats", "--chunk", "5"}, "--chunk is for batch only"},
      {{"locate", "1", "2", "--line", "0,0 1,1"}, "--line is for profile only"},
      {{"locate", "1", "2", "--csv"}, "--csv is for profile only"},
      {{"profile", "--line", "0,0 1,1", "--out", "x"},
       "--out is for grid only"},
      {{"locate", "1", "2", "--te", "0", "0", "1", "1"},
       "--te is for grid only"},
      {{"stats", "--of", "GTiff"}, "--of is for grid only"},
      {{"stats", "--co", "A=B"}, "--co is for grid only"},
      {{"stats", "--a_nodata", "0"}, "--a_nodata is for grid only"},
      {{"stats", "--nodata", "0"}, "--nodata is for grid only"},
      {{"stats", "--outsize", "1", "1"}, "--outsize is for grid only"},
      {{"stats", "--tr", "1", "1"}, "--tr is for grid only"},
      {{"stats", "--samples", "3"}, "--samples is for profile only"},
      // Interpolation.
      {{"locate", "1", "2", "--interpolation", "cubic"},
       "--interpolation 'cubic': must be linear, natural-neighbor or "
       "nearest"},
      // Profile.
      {{"profile"}, "profile needs --line"},
      {{"profile", "--line", "0,0"},
       "--line '0,0': a line needs at least 2 vertices, not 1"},
      {{"profile", "--line", "0,0 1,x"},
       "--line '0,0 1,x': 'x' is not a number"},
      {{"profile", "--line", "0,0 1,1", "--samples", "-1"},
       "--samples '-1': must be a whole number from 0 to 4294967295"},
      {{"profile", "--line", "0,0 1,1", "--samples", "4294967296"},
       "--samples '4294967296': must be a whole number from 0 to 4294967295"},
      {{"profile", "--line", "0,0 1,1", "--json", "--csv"},
       "give --json or --csv, not both"},
      // Grid.
      {{"grid", "--outsize", "1", "1"}, "grid needs --out FILE"},
      {grid, "grid needs --outsize WIDTH HEIGHT or --tr XRES YRES"},
      // --te takes exactly four values, once; a flag is not one of them.
      {{"grid", "--te", "0", "0", "1", "--out", "x", "--outsize", "1", "1"},
       "--te needs 4 values (XMIN YMIN XMAX YMAX)"},
      {with(grid, {"--outsize", "1", "1", "--outsize", "2", "2"}),
       "--outsize is given twice"},
      {with(grid, {"--outsize", "2", "2", "--tr", "1", "1"}),
       "give --outsize or --tr, not both"},
      {with(grid, {"--outsize", "0", "2"}),
       "--outsize '0': must be a whole number from 1 to 4294967295 (WIDTH "
       "HEIGHT)"},
      {with(grid, {"--outsize", "2", "2.5"}),
       "--outsize '2.5': must be a whole number from 1 to 4294967295 (WIDTH "
       "HEIGHT)"},
      {with(grid, {"--outsize", "4294967296", "2"}),
       "--outsize '4294967296': must be a whole number from 1 to 4294967295 "
       "(WIDTH HEIGHT)"},
      {with(grid, {"--outsize", "w", "2"}),
       "--outsize 'w': must be a whole number from 1 to 4294967295 (WIDTH "
       "HEIGHT)"},
      {with(grid, {"--tr", "1", "2"}),
       "--tr '1 2': the Grid RPC renders square cells: XRES must equal YRES"},
      {with(grid, {"--tr", "-1", "-1"}),
       "--tr '-1': must be a positive number (XRES YRES)"},
      {with(grid, {"--tr", "inf", "inf"}),
       "--tr 'inf': must be a positive number (XRES YRES)"},
      {with(grid, {"--tr", "1", "1", "--te", "0", "0", "1", "top"}),
       "--te 'top': must be a number (XMIN YMIN XMAX YMAX)"},
      {with(grid, {"--tr", "1", "1", "--a_nodata", "none"}),
       "--a_nodata 'none': must be a number or nan"},
      {with(grid, {"--tr", "1", "1", "--nodata", "none"}),
       "--nodata 'none': must be a number or nan"},
      {with(grid, {"--tr", "1", "1", "--a_nodata", "0", "--nodata", "0"}),
       "give --a_nodata or --nodata, not both"},
      {with(grid, {"--tr", "1", "1", "--of", "PNG"}),
       "unknown raster format 'PNG': GTiff or COG"},
      {with(grid, {"--tr", "1", "1", "--co", "COMPRESS"}),
       "creation option 'COMPRESS' is not NAME=VALUE"}};
  for (const auto& [words, problem] : cases) {
    CliLine line;
    const Status parsed = Parse(words, &line);
    EXPECT_EQ(parsed.code(), Status::Code::kInvalidArgument) << problem;
    EXPECT_EQ(parsed.message(), problem);
    // The usage is there for the error message.
    EXPECT_THAT(line.settings.usage, HasSubstr("commands:"));
  }
}

TEST(CliFlagsTest, BadCreationOptionsAreNamedWithGdalsWords) {
  CliLine line;
  const Status parsed = Parse({"grid", "--out", "x.tif", "--outsize", "1", "1",
                               "--of", "COG", "--co", "COMPRESS=NONSENSE"},
                              &line);
  EXPECT_EQ(parsed.code(), Status::Code::kInvalidArgument);
  EXPECT_THAT(parsed.message(), HasSubstr("bad COG creation option: "));
  EXPECT_THAT(parsed.message(), HasSubstr("NONSENSE"));
}

TEST(CliFlagsTest, ParserErrorsAreUsageErrors) {
  for (const std::vector<std::string>& words :
       {std::vector<std::string>{"stats", "--no-such-flag"},
        std::vector<std::string>{"stats", "--deadline-ms", "soon"},
        std::vector<std::string>{"stats", "--chunk"},
        // Too few values for --te at the end of the line.
        std::vector<std::string>{"grid", "--out", "x", "--outsize", "1", "1",
                                 "--te", "0", "0", "1"},
        std::vector<std::string>{"profile", "--line", "0,0 1,1", "--samples",
                                 "many"}}) {
    CliLine line;
    const Status parsed = Parse(words, &line);
    EXPECT_EQ(parsed.code(), Status::Code::kInvalidArgument) << words.back();
    EXPECT_FALSE(parsed.message().empty());
  }
}

}  // namespace
}  // namespace locator
