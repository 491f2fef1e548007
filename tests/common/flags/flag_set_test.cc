// FlagSet: the command-line forms every program accepts, --help, and the
// one wording of flag errors.

#include "common/flags/flag_set.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace locator {
namespace {

using ::testing::HasSubstr;

// A program with one flag of each kind.
struct Program {
  bool verbose = false;
  std::string name = "anon";
  uint32_t threads = 2;
  double interval_s = 0;
  size_t budget = size_t{64} << 20;
  std::string mode = "fast";
  std::vector<std::string> origins;
  std::vector<std::string> box;
  std::vector<std::string> positionals;
  FlagSet flags{"Usage: prog [flags]"};

  Program() {
    flags.Add("verbose", flag::Switch(&verbose), "say more");
    flags.Add("name", flag::Text(&name).Shape("NAME"), "who");
    flags.Add("threads", flag::Count(&threads, 1, 256), "threads");
    flags.Add("interval-s", flag::Seconds(&interval_s), "how often");
    flags.Add("budget", flag::Bytes(&budget, 0, uint64_t{1} << 40), "memory");
    flags.Add("mode", flag::Choice(&mode, {"fast", "exact"}), "how");
    flags.Add("origin", flag::Repeated(&origins), "repeatable");
    flags.Add("box", flag::Words(&box, 4).Shape("X0 Y0 X1 Y1"), "a box");
  }

  Status Parse(const std::vector<std::string>& args) {
    return flags.Parse(args);
  }
};

TEST(FlagSetTest, DefaultsStayWithoutFlags) {
  Program p;
  ASSERT_TRUE(p.Parse({}).ok());
  EXPECT_FALSE(p.verbose);
  EXPECT_EQ(p.name, "anon");
  EXPECT_EQ(p.threads, 2u);
  EXPECT_EQ(p.budget, size_t{64} << 20);
  EXPECT_EQ(p.mode, "fast");
  EXPECT_FALSE(p.flags.Given("threads"));
  EXPECT_FALSE(p.flags.help_requested());
}

TEST(FlagSetTest, EqualsAndNextWordFormsBothSetTheValue) {
  Program p;
  const Status parsed =
      p.Parse({"--verbose", "--name=a=b", "--threads", "8", "--interval-s=2.5",
               "--budget", "3MiB", "--mode=exact", "--origin", "x",
               "--origin=y", "--box", "-1", "-2.5", "3", "4"});
  ASSERT_TRUE(parsed.ok()) << parsed.ToString();
  EXPECT_TRUE(p.verbose);
  EXPECT_EQ(p.name, "a=b");
  EXPECT_EQ(p.threads, 8u);
  EXPECT_EQ(p.interval_s, 2.5);
  EXPECT_EQ(p.budget, size_t{3} << 20);
  EXPECT_EQ(p.mode, "exact");
  EXPECT_EQ(p.origins, (std::vector<std::string>{"x", "y"}));
  EXPECT_EQ(p.box, (std::vector<std::string>{"-1", "-2.5", "3", "4"}));
  EXPECT_TRUE(p.flags.Given("threads"));
  EXPECT_FALSE(p.flags.Given("no-such"));
}

TEST(FlagSetTest, ValuesMayLookLikeNegativeNumbersOrBeEmpty) {
  Program p;
  ASSERT_TRUE(p.Parse({"--name", "-x", "--box=-1", "-2", "-3", "-4"}).ok());
  EXPECT_EQ(p.name, "-x");
  EXPECT_EQ(p.box, (std::vector<std::string>{"-1", "-2", "-3", "-4"}));
  ASSERT_TRUE(p.Parse({"--name="}).ok());
  EXPECT_EQ(p.name, "");
}

TEST(FlagSetTest, RepeatedReplacesItsDefault) {
  std::vector<std::string> datasets = {"uniform:10"};
  FlagSet flags("x");
  flags.Add("dataset", flag::Repeated(&datasets), "d");
  ASSERT_TRUE(flags.Parse({"--dataset", "a", "--dataset", "b"}).ok());
  EXPECT_EQ(datasets, (std::vector<std::string>{"a", "b"}));
}

TEST(FlagSetTest, PositionalsAnywhereWhenAllowedAndAfterDoubleDash) {
  Program p;
  p.flags.AllowPositionals(&p.positionals);
  ASSERT_TRUE(
      p.Parse({"locate", "--verbose", "-0.5", "2", "--", "--threads"}).ok());
  EXPECT_EQ(p.positionals,
            (std::vector<std::string>{"locate", "-0.5", "2", "--threads"}));
  EXPECT_TRUE(p.verbose);
  EXPECT_FALSE(p.flags.Given("threads"));
}

TEST(FlagSetTest, HelpWinsOverEverythingElse) {
  for (const char* help : {"--help", "-h"}) {
    Program p;
    ASSERT_TRUE(p.Parse({"--threads", "zero", help, "--bogus"}).ok()) << help;
    EXPECT_TRUE(p.flags.help_requested());
    EXPECT_EQ(p.threads, 2u);
  }
}

TEST(FlagSetTest, HelpListsEveryFlagWithShapeAndDefault) {
  Program p;
  const std::string help = p.flags.Help();
  EXPECT_THAT(help, HasSubstr("Usage: prog [flags]\n"));
  EXPECT_THAT(help, HasSubstr("--verbose "));
  EXPECT_THAT(help, HasSubstr("--name NAME "));
  EXPECT_THAT(help, HasSubstr("(default: anon)"));
  EXPECT_THAT(help, HasSubstr("--threads N "));
  EXPECT_THAT(help, HasSubstr("(default: 2)"));
  EXPECT_THAT(help, HasSubstr("--interval-s SECONDS "));
  EXPECT_THAT(help, HasSubstr("--budget SIZE "));
  EXPECT_THAT(help, HasSubstr("(default: 64MiB)"));
  EXPECT_THAT(help, HasSubstr("--mode fast|exact "));
  EXPECT_THAT(help, HasSubstr("--box X0 Y0 X1 Y1"));
  EXPECT_THAT(help, HasSubstr("--help, -h"));
  for (size_t start = 0, end; start < help.size(); start = end + 1) {
    end = help.find('\n', start);
    EXPECT_LE(end - start, 80u) << help.substr(start, end - start);
  }
}

TEST(FlagSetTest, EveryErrorNamesTheFlagAndTheAcceptedForm) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--threads", "two"},
       "--threads 'two': must be a whole number from 1 to 256"},
      {{"--threads", "0"},
       "--threads '0': must be a whole number from 1 to 256"},
      {{"--threads", "-1"},
       "--threads '-1': must be a whole number from 1 to 256"},
      {{"--threads", "1e3"},
       "--threads '1e3': must be a whole number from 1 to 256"},
      {{"--threads="}, "--threads '': must be a whole number from 1 to 256"},
      {{"--interval-s", "-1"},
       "--interval-s '-1': must be a number of seconds >= 0"},
      {{"--interval-s", "nan"},
       "--interval-s 'nan': must be a number of seconds >= 0"},
      {{"--interval-s", "inf"},
       "--interval-s 'inf': must be a number of seconds >= 0"},
      {{"--budget", "12kb"},
       "--budget '12kb': must be a byte size from 0 to 1099511627776 bytes (a "
       "whole number, optionally with B, KiB, MiB or GiB)"},
      {{"--mode", "slow"}, "--mode 'slow': must be fast or exact"},
      {{"--box", "1", "2", "3"}, "--box needs 4 values (X0 Y0 X1 Y1)"},
      {{"--box", "1", "2", "3", "--verbose"},
       "--box needs 4 values (X0 Y0 X1 Y1)"},
      {{"--threads"}, "--threads needs a value (N)"},
      {{"--threads", "--verbose"}, "--threads needs a value (N)"},
      {{"--threads", "--name=x"}, "--threads needs a value (N)"},
      {{"--threads", "3", "--threads", "4"}, "--threads is given twice"},
      {{"--verbose=yes"}, "--verbose takes no value, not 'yes'"},
      {{"--thread", "3"}, "unknown flag --thread"},
      {{"--no-such-flag=1"}, "unknown flag --no-such-flag"},
      {{"stray"}, "unexpected argument 'stray'"},
      {{"-v"}, "unexpected argument '-v'"},
  };
  for (const auto& [args, message] : cases) {
    Program p;
    const Status parsed = p.Parse(args);
    EXPECT_EQ(parsed.code(), Status::Code::kInvalidArgument) << message;
    EXPECT_EQ(parsed.message(), message);
  }
}

TEST(FlagSetTest, CountsBoundedOnlyByTheirTypeSayAtLeast) {
  int64_t deadline_ms = 5000;
  FlagSet flags("x");
  flags.Add("deadline-ms", flag::Count(&deadline_ms, 1, flag::kMaxOf<int64_t>),
            "d");
  EXPECT_EQ(flags.Parse({"--deadline-ms", "0"}).message(),
            "--deadline-ms '0': must be a whole number >= 1");
  ASSERT_TRUE(flags.Parse({"--deadline-ms=9223372036854775807"}).ok());
  EXPECT_EQ(deadline_ms, INT64_MAX);
  EXPECT_FALSE(flags.Parse({"--deadline-ms=9223372036854775808"}).ok());
}

TEST(FlagSetTest, ChoiceMapsWordsToValues) {
  enum class Level { kLow, kHigh };
  Level level = Level::kHigh;
  FlagSet flags("x");
  flags.Add(
      "level",
      flag::Choice(&level, {{"low", Level::kLow}, {"high", Level::kHigh}}),
      "l");
  EXPECT_THAT(flags.Help(), HasSubstr("(default: high)"));
  ASSERT_TRUE(flags.Parse({"--level=low"}).ok());
  EXPECT_EQ(level, Level::kLow);
}

TEST(FlagSetTest, NumbersAboveAMinimum) {
  double rate = 0;
  double timeline_s = 1;
  FlagSet flags("x");
  flags.Add("rate", flag::Number(&rate, 0), "r");
  flags.Add("timeline-s", flag::Seconds(&timeline_s, 0.1), "t");
  EXPECT_EQ(flags.Parse({"--timeline-s", "0.01"}).message(),
            "--timeline-s '0.01': must be a number of seconds >= 0.1");
  EXPECT_EQ(flags.Parse({"--rate", "-1"}).message(),
            "--rate '-1': must be a number >= 0");
  double duration = 10;
  flags.Add("duration", flag::Seconds(&duration, 0, /*above=*/true), "d");
  EXPECT_EQ(flags.Parse({"--duration", "0"}).message(),
            "--duration '0': must be a number of seconds > 0");
}

TEST(FlagSetTest, CommaListsReplaceTheirDefaultWhole) {
  std::vector<size_t> sizes = {1000, 2000};
  std::vector<double> errors = {0.01};
  std::vector<std::string> names;
  FlagSet flags("x");
  flags.Add("sizes", flag::Counts(&sizes, 1, 1000000), "s");
  flags.Add("errors", flag::Numbers(&errors, 0, /*above=*/true), "e");
  flags.Add("names", flag::Texts(&names), "n");
  EXPECT_THAT(flags.Help(), HasSubstr("--sizes N,N,... "));
  EXPECT_THAT(flags.Help(), HasSubstr("(default: 1000,2000)"));
  ASSERT_TRUE(
      flags.Parse({"--sizes", "5,6,7", "--errors=0.5,2", "--names", "a,b"})
          .ok());
  EXPECT_EQ(sizes, (std::vector<size_t>{5, 6, 7}));
  EXPECT_EQ(errors, (std::vector<double>{0.5, 2}));
  EXPECT_EQ(names, (std::vector<std::string>{"a", "b"}));
  // A bad item leaves the list as it was.
  EXPECT_EQ(flags.Parse({"--sizes", "8,0"}).message(),
            "--sizes '8,0': must be a whole number from 1 to 1000000, "
            "comma-separated");
  EXPECT_EQ(sizes, (std::vector<size_t>{5, 6, 7}));
  EXPECT_EQ(flags.Parse({"--errors", "0.5,"}).message(),
            "--errors '0.5,': must be a number > 0, comma-separated");
  EXPECT_EQ(flags.Parse({"--names", "a,,b"}).message(),
            "--names 'a,,b': must be a word, comma-separated");
}

TEST(FlagSetTest, ParsedFlagsSayTheirOwnProblem) {
  int port = 0;
  FlagSet flags("x");
  flags.Add("port", flag::Parsed([&port](std::string_view text) {
                      if (text != "80")
                        return Status::InvalidArgument("not 80");
                      port = 80;
                      return Status::OK();
                    }).Shape("PORT"),
            "p");
  EXPECT_EQ(flags.Parse({"--port", "81"}).message(), "--port '81': not 80");
  ASSERT_TRUE(flags.Parse({"--port=80"}).ok());
  EXPECT_EQ(port, 80);
}

TEST(FlagSetTest, ExitCodeForFlags) {
  EXPECT_EQ(ExitCodeForFlags("prog", Status::InvalidArgument("bad"), ""), 2);
  EXPECT_EQ(ExitCodeForFlags("prog", Status::OK(), "help\n"), 0);
  EXPECT_EQ(ExitCodeForFlags("prog", Status::OK(), ""), std::nullopt);
}

}  // namespace
}  // namespace locator
