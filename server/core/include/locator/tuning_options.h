// TuningOptions: the knobs of the learning strategies, with the defaults the
// paper (and the issue tracker) fixes, and the strategy names. No CGAL here:
// the server validates its flags with these before building anything.

#ifndef LOCATOR_TUNING_OPTIONS_H_
#define LOCATOR_TUNING_OPTIONS_H_

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "locator/status.h"

namespace locator {

struct TuningOptions {
  // Histogram grid: grid_size x grid_size cells over the bounding box.
  int grid_size = 32;
  // adaptive-paper: queries answered by jump-and-walk (and counted) before
  // the hot rectangles are found.
  uint64_t warmup_queries = 2000;
  // adaptive-paper: random start edges sampled per hot rectangle.
  int samples_per_region = 3;
  // self-tuning: re-tune after this many queries.
  uint64_t retune_every = 2000;
  // self-tuning: memory budget of the start table. 0 means
  // budget_fraction of the triangulation's bytes.
  size_t budget_bytes = 0;
  double budget_fraction = 0.1;
  // self-tuning: histogram weight kept per re-tune (older traffic fades).
  double decay = 0.25;
  // self-tuning: re-tune from a background thread (the server) instead of
  // inline in the query that crosses the threshold (deterministic benches).
  bool background = false;
  // self-tuning: the mesh may be larger than RAM (a tile set), so tuning
  // reads as little of it as it can: no table is planned before traffic
  // arrives, plans give cells without traffic no share of the budget (they
  // keep the start their first query finds), and the cells' densities are
  // measured on a sample of the faces instead of all of them.
  bool mesh_larger_than_memory = false;
  // Seed for the strategies' sampling.
  uint64_t seed = 1;
  // self-tuning: directory where the learned state persists, one file per
  // dataset fingerprint (see TuningStateStore); empty: nothing persists. It
  // is restored at construction and, with `background`, saved by the tuner
  // thread after re-tunes (at most once per second).
  std::string state_dir;
};

// Grids above this make the per-cell arrays outgrow any sane budget.
inline constexpr int kMaxGridSize = 1024;

// The strategy names, default ("self-tuning") last.
const std::vector<std::string>& StrategyNames();

// InvalidArgument naming the valid strategies unless `name` is one.
Status ValidateStrategy(std::string_view name);

// InvalidArgument naming the first option out of range.
Status ValidateTuningOptions(const TuningOptions& options);

}  // namespace locator

#endif  // LOCATOR_TUNING_OPTIONS_H_
