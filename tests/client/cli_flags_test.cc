// The `locator` CLI's command line, parsed without a server.

#include "client/cli_flags.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
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

TEST(CliFlagsTest, EveryCommandIsFound) {
  EXPECT_EQ(FindCliCommand("locate"), &RunLocate);
  EXPECT_EQ(FindCliCommand("batch"), &RunBatch);
  EXPECT_EQ(FindCliCommand("stats"), &RunStats);
  EXPECT_EQ(FindCliCommand("retune"), &RunRetune);
  EXPECT_EQ(FindCliCommand("reload"), &RunReload);
  EXPECT_EQ(FindCliCommand("health"), &RunHealth);
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

TEST(CliFlagsTest, ReloadWaitsLongerUnlessTold) {
  CliLine defaulted;
  ASSERT_TRUE(Parse({"reload", "--dataset", "uniform:10:1"}, &defaulted).ok());
  EXPECT_EQ(defaulted.deadline, kReloadDeadline);
  EXPECT_EQ(defaulted.settings.dataset, "uniform:10:1");
  CliLine told;
  ASSERT_TRUE(Parse({"reload", "--deadline-ms", "1000"}, &told).ok());
  EXPECT_EQ(told.deadline, std::chrono::milliseconds(1000));
}

TEST(CliFlagsTest, HelpNeedsNoCommand) {
  CliLine line;
  ASSERT_TRUE(Parse({"--help"}, &line).ok());
  EXPECT_TRUE(line.help);
  EXPECT_THAT(line.settings.usage, HasSubstr("usage: locator [flags]"));
  EXPECT_THAT(line.settings.usage, HasSubstr("--deadline-ms"));
}

TEST(CliFlagsTest, UsageProblemsAreNamed) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{}, "no command"},
      {{"--json"}, "no command"},
      {{"locat", "1", "2"}, "unknown command 'locat'"},
      {{"stats", "--deadline-ms", "0"}, "--deadline-ms must be positive"},
      {{"batch", "f", "--chunk", "-3"}, "--chunk must be positive"},
      {{"stats", "--dataset", "x.csv"}, "--dataset is for reload only"}};
  for (const auto& [words, problem] : cases) {
    CliLine line;
    const Status parsed = Parse(words, &line);
    EXPECT_EQ(parsed.code(), Status::Code::kInvalidArgument) << problem;
    EXPECT_EQ(parsed.message(), problem);
    // The usage is there for the error message.
    EXPECT_THAT(line.settings.usage, HasSubstr("commands:"));
  }
}

TEST(CliFlagsTest, ParserErrorsAreUsageErrors) {
  for (const std::vector<std::string>& words :
       {std::vector<std::string>{"stats", "--no-such-flag"},
        std::vector<std::string>{"stats", "--deadline-ms", "soon"},
        std::vector<std::string>{"stats", "--chunk"}}) {
    CliLine line;
    const Status parsed = Parse(words, &line);
    EXPECT_EQ(parsed.code(), Status::Code::kInvalidArgument) << words.back();
    EXPECT_FALSE(parsed.message().empty());
  }
}

}  // namespace
}  // namespace locator
