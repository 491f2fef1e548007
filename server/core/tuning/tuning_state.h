// TuningState: what the self-tuning strategy has learned, as plain values,
// and the versioned binary file format it persists in (locatord
// --state-dir), so that a restarted server answers its first query already
// tuned.
//
// A state only means something for the dataset and configuration it was
// learned on; TuningFingerprint names both. Start faces are stored by the
// stable input ids of their corners, never by handle, so a state applies to
// any triangulation built from the same points.
//
// File layout (integers and doubles little-endian):
//   magic "LOCTUNE\n" | u32 format version | u64 file length
//   fingerprint: u64 dataset digest | u64 input points | u32 length +
//     strategy name | u32 grid size | 4 x f64 grid box | u64 budget bytes
//   payload: u64 snapshot version | u64 re-tunes | u8 seen traffic |
//     u32 cells | cells x f64 histogram | cells x f64 planned share |
//     cells x u32 sub-grid level | u64 starts | starts x 3 x u32 corner ids
//   u64 checksum: XXH3-64 of every byte before it
//
// Decoding validates every length, count and id before using it: any byte
// string is rejected with a Status naming the reason or yields a state whose
// sizes agree with its fingerprint and whose ids are < input_points.
//
// Thread-safety: free functions over plain values.

#ifndef LOCATOR_CORE_TUNING_STATE_H_
#define LOCATOR_CORE_TUNING_STATE_H_

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "locator/geometry.h"
#include "locator/status.h"

namespace locator {

inline constexpr std::string_view kTuningStateMagic = "LOCTUNE\n";
// Version 2: a cell's stored level r buys about r * r starts shaped by the
// cell's triangles (version 1 stored square r x r sub-grids). Version 3: the
// checksum and the dataset digest are XXH3 (version 2's were FNV-1a).
inline constexpr uint32_t kTuningStateFormatVersion = 3;
// Sub-grid levels above this are rejected (r * r must fit in 32 bits).
inline constexpr uint32_t kMaxStoredLevel = 65535;
// The most starts a cell at level r holds: its sub-grid has about r * r
// sub-cells (HotRegionTuner::ShapeOf stays within this bound, which decoding
// enforces; the exact count depends on the triangulation, and
// HotRegionTuner::Restore checks it).
inline constexpr uint64_t MaxStartsAtLevel(uint32_t r) {
  return r == 1 ? 1 : 2 * uint64_t{r} * r;
}

// Everything that changes what a stored state means.
struct TuningFingerprint {
  // ServingMesh::digest(): XXH3 over the distinct vertices (id, x, y), in
  // id order, and the domain (Triangulation::VertexDigest).
  uint64_t dataset_digest = 0;
  // ServingMesh::id_bound(): every vertex id is below it (the points read
  // from the dataset, plus the constraint points that are not among them).
  uint64_t input_points = 0;
  std::string strategy;
  // The coarse grid the histogram and start table use.
  uint32_t grid_size = 0;
  BoundingBox grid_box;
  // The resolved memory budget the plan was sized for.
  uint64_t budget_bytes = 0;

  // A digest of every field, e.g. to name the state file.
  uint64_t Digest() const;
};

// "" if `saved` equals `expected`, else which part differs.
std::string FingerprintMismatch(const TuningFingerprint& saved,
                                const TuningFingerprint& expected);

struct TuningState {
  uint64_t snapshot_version = 0;
  uint64_t retune_count = 0;
  // Whether any traffic was ever counted (the first counts are not decayed).
  bool seen_traffic = false;
  // Per coarse cell, row-major: the decayed query counts, the traffic share
  // the start table was planned for, and the sub-grid level r (>= 1: about
  // r * r starts, shaped by the tuner from the cell's triangles).
  std::vector<double> histogram;
  std::vector<double> planned_share;
  std::vector<uint32_t> levels;
  // The start faces by their corners' vertex ids (counter-clockwise), cell
  // by cell; a refined cell's sub-grid row-major. kUnresolvedStart for an
  // unrefined cell whose start is found on its first use.
  std::vector<std::array<uint32_t, 3>> starts;
};

// The start of an unrefined cell not used yet (StartTable::kUnresolved).
inline constexpr std::array<uint32_t, 3> kUnresolvedStart = {
    0xffffffffu, 0xffffffffu, 0xffffffffu};

// The file bytes of `state` learned under `fingerprint`. Precondition: the
// state's sizes agree with the fingerprint (as DecodeTuningState checks).
std::string EncodeTuningState(const TuningFingerprint& fingerprint,
                              const TuningState& state);

// Decodes file bytes into *out. InvalidArgument naming the problem for a
// truncated, corrupt or wrong-version file; FailedPrecondition naming the
// differing part when it was saved under another fingerprint.
Status DecodeTuningState(std::string_view bytes,
                         const TuningFingerprint& expected, TuningState* out);

}  // namespace locator

#endif  // LOCATOR_CORE_TUNING_STATE_H_
