// libFuzzer target: arbitrary bytes as a tuning state file. Decoding must
// reject them with a Status or yield a state that restores onto the
// fixture's triangulation (or is rejected there, for ids that name no
// triangle), without a crash, a leak or undefined behaviour.
//
// Seeds: tests/fuzz/corpus/tuning_state_fuzzer/ (real saves of the fixture's
// locator; see tests/core/tuning/tuning_state_test.cc to regenerate them).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "server/core/tuning/hot_region_tuner.h"
#include "server/core/tuning/tuning_state.h"
#include "tests/fuzz/tuning_state_fixture.h"

namespace {

void DecodeAndRestore(const std::string& bytes) {
  const locator::fuzz::TuningStateFixture& fixture =
      locator::fuzz::TuningStateFuzzFixture();
  locator::TuningState state;
  if (!locator::DecodeTuningState(bytes, fixture.fingerprint, &state).ok()) {
    return;
  }
  locator::HotRegionTuner tuner(fixture.triangulation->mesh(), fixture.grid,
                                fixture.options, 0);
  std::shared_ptr<const locator::TuningSnapshot> snapshot;
  if (!tuner.Restore(state, state.snapshot_version, &snapshot).ok()) return;
  // Every start of a restored table is a real face: jump to a few.
  uint32_t lookups = 0;
  const locator::BoundingBox& box = fixture.grid.box();
  for (double f : {0.0, 0.25, 0.5, 0.99}) {
    const auto face = snapshot->table->Start(
        {box.min_x + f * box.width(), box.min_y + f * box.height()}, &lookups);
    if (face >= fixture.triangulation->mesh().num_faces()) __builtin_trap();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  DecodeAndRestore(bytes);
  // A mutation almost never keeps the length and checksum right; a resealed
  // copy reaches the fingerprint and payload checks behind them.
  locator::fuzz::ResealTuningState(&bytes);
  DecodeAndRestore(bytes);
  return 0;
}
