// The tuning state file format: round trips, and every way a file can be
// broken (truncated at any byte, any byte flipped, wrong magic or version,
// saved for another fingerprint, lengths and ids that lie) is rejected with
// a Status that says why, never a crash. Also checks the committed fuzz
// seeds still decode.

#include "server/core/tuning/tuning_state.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <sstream>
#include <string>

#include "common/workload.h"
#include "server/core/dataset/file_io.h"
#include "server/core/strategies/self_tuning_locator.h"
#include "server/core/tuning/hot_region_tuner.h"
#include "tests/core/scratch_dir.h"
#include "tests/fuzz/tuning_state_fixture.h"

namespace locator {
namespace {

using fuzz::ResealTuningState;
using fuzz::TuningStateFuzzFixture;
using ::testing::HasSubstr;

// Where the file layout puts things (see tuning_state.h).
constexpr size_t kVersionAt = 8;
constexpr size_t kStrategyLengthAt = 8 + 4 + 8 + 8 + 8;

const TuningFingerprint& Fingerprint() {
  return TuningStateFuzzFixture().fingerprint;
}

// The bytes a SelfTuningLocator on the fixture saves after `kind` traffic.
std::string SavedState(WorkloadKind kind) {
  const fuzz::TuningStateFixture& fixture = TuningStateFuzzFixture();
  test::ScratchDir dir;
  TuningOptions options = fixture.options;
  options.state_dir = dir.path();
  SelfTuningLocator locator(fixture.triangulation->mesh(), options);
  LocateResult result;
  for (const Point2& q :
       WorkloadQueries(kind, fixture.triangulation->bounding_box(), 3000, 1)) {
    locator.Locate(q, &result);
  }
  locator.Retune();
  EXPECT_TRUE(locator.SaveState().ok());
  std::string bytes;
  EXPECT_TRUE(
      ReadWholeFile(locator.Summary().persistence.state_path, "state", &bytes)
          .ok());
  return bytes;
}

const std::string& ClusteredSave() {
  static const std::string* bytes =
      new std::string(SavedState(WorkloadKind::kOneCluster));
  return *bytes;
}

TuningState Decoded(const std::string& bytes) {
  TuningState state;
  const Status s = DecodeTuningState(bytes, Fingerprint(), &state);
  EXPECT_TRUE(s.ok()) << s.ToString();
  return state;
}

// The clustered save with `change` applied to its decoded state, encoded
// again (the encoder writes whatever it is given).
std::string Reencoded(const std::function<void(TuningState*)>& change) {
  TuningState state = Decoded(ClusteredSave());
  change(&state);
  return EncodeTuningState(Fingerprint(), state);
}

Status Decode(const std::string& bytes) {
  TuningState state;
  return DecodeTuningState(bytes, Fingerprint(), &state);
}

TEST(TuningStateTest, ARealSaveDecodesAndEncodesToTheSameBytes) {
  const std::string& bytes = ClusteredSave();
  const TuningState state = Decoded(bytes);
  EXPECT_GT(state.snapshot_version, 1u);
  EXPECT_TRUE(state.seen_traffic);
  const size_t cells =
      size_t{Fingerprint().grid_size} * Fingerprint().grid_size;
  EXPECT_EQ(state.histogram.size(), cells);
  EXPECT_EQ(state.levels.size(), cells);
  // The hot spot got a refined cell.
  EXPECT_GT(state.starts.size(), cells);
  EXPECT_EQ(EncodeTuningState(Fingerprint(), state), bytes);
}

TEST(TuningStateTest, EveryTruncationIsRejected) {
  const std::string& bytes = ClusteredSave();
  for (size_t size = 0; size < bytes.size(); ++size) {
    const Status s = Decode(bytes.substr(0, size));
    ASSERT_EQ(s.code(), Status::Code::kInvalidArgument) << size;
    ASSERT_THAT(s.message(), HasSubstr("truncated")) << size;
  }
}

TEST(TuningStateTest, EveryFlippedByteIsRejected) {
  const std::string& bytes = ClusteredSave();
  for (size_t at = 0; at < bytes.size(); ++at) {
    std::string flipped = bytes;
    flipped[at] ^= 0x5a;
    const Status s = Decode(flipped);
    ASSERT_EQ(s.code(), Status::Code::kInvalidArgument) << at;
  }
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 1;
  EXPECT_THAT(Decode(flipped).message(), HasSubstr("checksum mismatch"));
}

TEST(TuningStateTest, WrongMagicOrVersionIsNamed) {
  std::string magic = ClusteredSave();
  magic[0] = 'X';
  ResealTuningState(&magic);
  EXPECT_THAT(Decode(magic).message(), HasSubstr("bad magic"));

  std::string version = ClusteredSave();
  version[kVersionAt] = kTuningStateFormatVersion + 1;
  ResealTuningState(&version);
  EXPECT_THAT(Decode(version).message(),
              HasSubstr("unsupported tuning state format version " +
                        std::to_string(kTuningStateFormatVersion + 1)));
}

TEST(TuningStateTest, AForeignFingerprintIsNamed) {
  const std::vector<
      std::pair<std::function<void(TuningFingerprint*)>, std::string>>
      changes = {
          {[](TuningFingerprint* f) { f->dataset_digest ^= 1; },
           "another dataset"},
          {[](TuningFingerprint* f) { f->input_points += 1; },
           "another dataset"},
          {[](TuningFingerprint* f) { f->strategy = "adaptive-paper"; },
           "saved for strategy 'self-tuning'"},
          {[](TuningFingerprint* f) { f->grid_size += 1; }, "grid, this one"},
          {[](TuningFingerprint* f) { f->grid_box.max_x += 1; },
           "another grid box"},
          {[](TuningFingerprint* f) { f->budget_bytes += 8; },
           "saved for a budget of"},
      };
  for (const auto& [change, reason] : changes) {
    TuningFingerprint expected = Fingerprint();
    change(&expected);
    EXPECT_NE(expected.Digest(), Fingerprint().Digest());
    TuningState state;
    const Status s = DecodeTuningState(ClusteredSave(), expected, &state);
    EXPECT_EQ(s.code(), Status::Code::kFailedPrecondition) << reason;
    EXPECT_THAT(s.message(), HasSubstr(reason));
  }
}

TEST(TuningStateTest, LengthsCountsAndIdsThatLieAreRejected) {
  const uint32_t points = static_cast<uint32_t>(Fingerprint().input_points);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {Reencoded([](TuningState* s) { s->histogram.push_back(1); }),
       "cells in a"},
      {Reencoded([](TuningState* s) { s->levels.assign(s->levels.size(), 1); }),
       "starts where the levels allow"},
      {Reencoded(
           [](TuningState* s) { s->starts.resize(s->levels.size() - 1); }),
       "starts where the levels allow"},
      {Reencoded([](TuningState* s) { s->levels[0] = 0; }), "sub-grid level 0"},
      {Reencoded([](TuningState* s) { s->levels[1] = 70000; }),
       "sub-grid level 70000"},
      {Reencoded([&](TuningState* s) { s->starts.back()[2] = points; }),
       "names vertex " + std::to_string(points)},
      {Reencoded([](TuningState* s) {
         s->histogram[3] = std::numeric_limits<double>::quiet_NaN();
       }),
       "histogram holds nan"},
      {Reencoded([](TuningState* s) { s->planned_share[0] = -1; }),
       "planned share holds -1"},
  };
  for (const auto& [bytes, reason] : cases) {
    const Status s = Decode(bytes);
    EXPECT_EQ(s.code(), Status::Code::kInvalidArgument) << reason;
    EXPECT_THAT(s.message(), HasSubstr(reason));
  }

  std::string long_name = ClusteredSave();
  long_name[kStrategyLengthAt + 3] = '\x7f';
  ResealTuningState(&long_name);
  EXPECT_THAT(Decode(long_name).message(), HasSubstr("strategy name of"));

  std::string trailing = ClusteredSave();
  trailing.insert(trailing.size() - 8, "extra");
  ResealTuningState(&trailing);
  EXPECT_THAT(Decode(trailing).message(), HasSubstr("5 bytes after"));

  // A start count near 2^64 must not be trusted for an allocation.
  TuningState state = Decoded(ClusteredSave());
  const size_t count_at =
      ClusteredSave().size() - 8 - 12 * state.starts.size() - 8;
  std::string huge = ClusteredSave();
  huge[count_at + 7] = '\x7f';
  ResealTuningState(&huge);
  EXPECT_THAT(Decode(huge).message(), HasSubstr("starts where"));
}

TEST(TuningStateTest, RestoreRejectsIdsThatNameNoTriangle) {
  const fuzz::TuningStateFixture& fixture = TuningStateFuzzFixture();
  HotRegionTuner tuner(fixture.triangulation->mesh(), fixture.grid,
                       fixture.options, 0);
  TuningState state = Decoded(ClusteredSave());
  std::swap(state.starts[2][1], state.starts[2][2]);  // clockwise now
  std::shared_ptr<const TuningSnapshot> snapshot;
  const Status s = tuner.Restore(state, 7, &snapshot);
  EXPECT_THAT(s.message(), HasSubstr("start 2: vertices"));
  EXPECT_THAT(s.message(), HasSubstr("are not a triangle of this dataset"));
  EXPECT_EQ(snapshot, nullptr);
  // The tuner is unchanged and still takes a good state.
  ASSERT_TRUE(tuner.Restore(Decoded(ClusteredSave()), 7, &snapshot).ok());
  EXPECT_EQ(snapshot->version, 7u);
}

// The committed fuzz seeds are real saves of the fixture. With
// LOCATOR_WRITE_FUZZ_SEEDS=1 in the environment this test writes them
// afresh (after a change of the format or of the fixture).
TEST(TuningStateTest, CommittedFuzzSeedsDecodeAndRestore) {
  const std::string dir = LOCATOR_TUNING_STATE_CORPUS;
  const std::vector<std::pair<std::string, std::string>> seeds = {
      {"clustered.state", ClusteredSave()},
      {"uniform.state", SavedState(WorkloadKind::kUniform)},
      {"truncated.state", ClusteredSave().substr(0, 100)},
  };
  if (std::getenv("LOCATOR_WRITE_FUZZ_SEEDS") != nullptr) {
    for (const auto& [name, bytes] : seeds) {
      std::ofstream(dir + "/" + name, std::ios::binary) << bytes;
    }
  }
  const fuzz::TuningStateFixture& fixture = TuningStateFuzzFixture();
  for (const auto& [name, unused] : seeds) {
    std::string bytes;
    ASSERT_TRUE(ReadWholeFile(dir + "/" + name, "seed", &bytes).ok()) << name;
    TuningState state;
    const Status s = DecodeTuningState(bytes, fixture.fingerprint, &state);
    if (name == "truncated.state") {
      EXPECT_THAT(s.message(), HasSubstr("truncated"));
      continue;
    }
    ASSERT_TRUE(s.ok()) << name << ": " << s.ToString();
    HotRegionTuner tuner(fixture.triangulation->mesh(), fixture.grid,
                         fixture.options, 0);
    std::shared_ptr<const TuningSnapshot> snapshot;
    EXPECT_TRUE(tuner.Restore(state, 1, &snapshot).ok()) << name;
  }
}

// format2.state is the clustered seed as version 2 wrote it (FNV-1a
// checksum and dataset digest): refused by its version, not misread.
TEST(TuningStateTest, AStateOfTheFormerFormatIsRefused) {
  std::string bytes;
  ASSERT_TRUE(
      ReadWholeFile(std::string(LOCATOR_TUNING_STATE_CORPUS) + "/format2.state",
                    "seed", &bytes)
          .ok());
  EXPECT_THAT(Decode(bytes).message(),
              HasSubstr("unsupported tuning state format version 2 (this "
                        "build reads 3)"));
}

}  // namespace
}  // namespace locator
