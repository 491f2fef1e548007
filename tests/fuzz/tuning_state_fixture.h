// The small triangulation and self-tuning configuration that the tuning
// state fuzzer, its seed corpus (tests/fuzz/corpus/tuning_state_fuzzer/) and
// the core tests share: a state saved by the fixture's locator decodes under
// the fixture's fingerprint and restores onto its tuner's grid.
//
// Header-only, so that the fuzz target needs no support library.
// Thread-safety: the fixture is built once and immutable afterwards.

#ifndef LOCATOR_TESTS_FUZZ_TUNING_STATE_FIXTURE_H_
#define LOCATOR_TESTS_FUZZ_TUNING_STATE_FIXTURE_H_

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "locator/dataset_sources.h"
#include "locator/tuning_options.h"
#include "server/core/cgal/triangulation.h"
#include "server/core/geometry/xxh3_digest.h"
#include "server/core/strategies/self_tuning_locator.h"
#include "server/core/tuning/hot_region_tuner.h"
#include "server/core/tuning/tuning_state.h"

namespace locator::fuzz {

struct TuningStateFixture {
  static constexpr size_t kPoints = 400;
  static constexpr uint64_t kSeed = 5;
  static constexpr size_t kBudgetBytes = 4096;

  std::unique_ptr<Triangulation> triangulation;
  TuningOptions options;
  // The coarse grid a SelfTuningLocator with `options` uses.
  GridGeometry grid;
  TuningFingerprint fingerprint;
};

inline const TuningStateFixture& TuningStateFuzzFixture() {
  static const TuningStateFixture* fixture = [] {
    auto* f = new TuningStateFixture();
    // A budget of its own, not a share of the mesh's bytes: enough for
    // refined cells, so that saves hold sub-grid starts.
    f->options.budget_bytes = TuningStateFixture::kBudgetBytes;
    StatusOr<std::unique_ptr<Triangulation>> built =
        Triangulation::Build(GenerateUniform(TuningStateFixture::kPoints,
                                             TuningStateFixture::kSeed));
    if (!built.ok()) {
      std::fprintf(stderr, "tuning state fixture: %s\n",
                   built.status().ToString().c_str());
      std::abort();
    }
    f->triangulation = *std::move(built);
    const TuningSummary summary =
        SelfTuningLocator(f->triangulation->mesh(), f->options).Summary();
    f->grid = GridGeometry(summary.grid_box, summary.grid_size);
    f->fingerprint =
        HotRegionTuner(f->triangulation->mesh(), f->grid, f->options, 0)
            .Fingerprint("self-tuning");
    return f;
  }();
  return *fixture;
}

// Makes the length field and the checksum of an encoded state agree with
// its bytes, so that a mutated state reaches the checks behind them.
inline void ResealTuningState(std::string* bytes) {
  constexpr size_t kLengthAt = kTuningStateMagic.size() + 4;
  if (bytes->size() < kLengthAt + 16) return;
  for (size_t i = 0; i < 8; ++i) {
    (*bytes)[kLengthAt + i] = static_cast<char>(bytes->size() >> (8 * i));
  }
  const uint64_t checksum =
      Xxh3Of(std::string_view(*bytes).substr(0, bytes->size() - 8));
  for (size_t i = 0; i < 8; ++i) {
    (*bytes)[bytes->size() - 8 + i] = static_cast<char>(checksum >> (8 * i));
  }
}

}  // namespace locator::fuzz

#endif  // LOCATOR_TESTS_FUZZ_TUNING_STATE_FIXTURE_H_
