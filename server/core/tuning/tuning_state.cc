#include "server/core/tuning/tuning_state.h"

#include <bit>
#include <cmath>

#include "common/status_macros.h"
#include "server/core/geometry/xxh3_digest.h"

namespace locator {
namespace {

// Magic, version and file length: enough to say what a file is and whether
// it is whole before anything else is read.
constexpr size_t kPreambleBytes = 8 + 4 + 8;
constexpr size_t kChecksumBytes = 8;
// Strategy names are short; a longer one is corruption, not a strategy.
constexpr uint32_t kMaxStrategyName = 64;
constexpr size_t kBytesPerStart = 3 * sizeof(uint32_t);

class ByteWriter {
 public:
  void U8(uint8_t v) { out_.push_back(static_cast<char>(v)); }
  void U32(uint32_t v) { Little(v, 4); }
  void U64(uint64_t v) { Little(v, 8); }
  void F64(double v) { U64(std::bit_cast<uint64_t>(v)); }
  void Text(std::string_view s) {
    U32(static_cast<uint32_t>(s.size()));
    out_.append(s);
  }
  std::string& bytes() { return out_; }

 private:
  void Little(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) U8(static_cast<uint8_t>(v >> (8 * i)));
  }
  std::string out_;
};

// Reads little-endian values; every read checks the bytes are there, and
// the first short read makes the reader fail for good.
class ByteReader {
 public:
  explicit ByteReader(std::string_view bytes) : in_(bytes) {}

  bool ok() const { return ok_; }
  size_t remaining() const { return in_.size(); }

  uint8_t U8() { return static_cast<uint8_t>(Little(1)); }
  uint32_t U32() { return static_cast<uint32_t>(Little(4)); }
  uint64_t U64() { return Little(8); }
  double F64() { return std::bit_cast<double>(U64()); }
  std::string_view Take(size_t n) {
    if (!ok_ || n > in_.size()) {
      ok_ = false;
      return {};
    }
    const std::string_view taken = in_.substr(0, n);
    in_.remove_prefix(n);
    return taken;
  }

 private:
  uint64_t Little(int n) {
    const std::string_view b = Take(static_cast<size_t>(n));
    uint64_t v = 0;
    for (size_t i = 0; i < b.size(); ++i) {
      v |= uint64_t{static_cast<unsigned char>(b[i])} << (8 * i);
    }
    return v;
  }

  std::string_view in_;
  bool ok_ = true;
};

Status Corrupt(const std::string& what) {
  return Status::InvalidArgument("corrupt tuning state: " + what);
}

void WriteFingerprint(const TuningFingerprint& fp, ByteWriter* w) {
  w->U64(fp.dataset_digest);
  w->U64(fp.input_points);
  w->Text(fp.strategy);
  w->U32(fp.grid_size);
  for (double v : {fp.grid_box.min_x, fp.grid_box.min_y, fp.grid_box.max_x,
                   fp.grid_box.max_y}) {
    w->F64(v);
  }
  w->U64(fp.budget_bytes);
}

Status ReadFingerprint(ByteReader* r, TuningFingerprint* fp) {
  fp->dataset_digest = r->U64();
  fp->input_points = r->U64();
  const uint32_t name_length = r->U32();
  if (name_length > kMaxStrategyName) {
    return Corrupt("strategy name of " + std::to_string(name_length) +
                   " bytes");
  }
  fp->strategy = std::string(r->Take(name_length));
  fp->grid_size = r->U32();
  fp->grid_box.min_x = r->F64();
  fp->grid_box.min_y = r->F64();
  fp->grid_box.max_x = r->F64();
  fp->grid_box.max_y = r->F64();
  fp->budget_bytes = r->U64();
  return r->ok() ? Status::OK() : Corrupt("fingerprint cut short");
}

// Reads `cells` doubles, each finite and >= 0.
Status ReadCounts(ByteReader* r, size_t cells, std::string_view what,
                  std::vector<double>* out) {
  if (r->remaining() / sizeof(double) < cells)
    return Corrupt(std::string(what) + " cut short");
  out->resize(cells);
  for (double& v : *out) {
    v = r->F64();
    if (!std::isfinite(v) || v < 0) {
      return Corrupt(std::string(what) + " holds " + std::to_string(v));
    }
  }
  return Status::OK();
}

// Reads the sub-grid levels and returns the fewest and the most starts they
// allow (each cell has at least one).
Status ReadLevels(ByteReader* r, size_t cells, TuningState* state,
                  uint64_t* min_starts, uint64_t* max_starts) {
  if (r->remaining() / sizeof(uint32_t) < cells) {
    return Corrupt("sub-grid levels cut short");
  }
  state->levels.resize(cells);
  *min_starts = cells;
  *max_starts = 0;
  for (uint32_t& level : state->levels) {
    level = r->U32();
    if (level < 1 || level > kMaxStoredLevel) {
      return Corrupt("sub-grid level " + std::to_string(level));
    }
    *max_starts += MaxStartsAtLevel(level);
  }
  return Status::OK();
}

Status ReadStarts(ByteReader* r, uint64_t min_starts, uint64_t max_starts,
                  uint64_t input_points, TuningState* state) {
  const uint64_t count = r->U64();
  if (!r->ok() || count < min_starts || count > max_starts) {
    return Corrupt(std::to_string(count) + " starts where the levels allow " +
                   std::to_string(min_starts) + " to " +
                   std::to_string(max_starts));
  }
  if (r->remaining() / kBytesPerStart < count) {
    return Corrupt("starts cut short");
  }
  state->starts.resize(count);
  for (size_t i = 0; i < count; ++i) {
    std::array<uint32_t, 3>& ids = state->starts[i];
    for (uint32_t& id : ids) id = r->U32();
    if (ids == kUnresolvedStart) continue;
    for (const uint32_t id : ids) {
      if (id >= input_points) {
        return Corrupt("start " + std::to_string(i) + " names vertex " +
                       std::to_string(id) + " of " +
                       std::to_string(input_points));
      }
    }
  }
  return Status::OK();
}

Status ReadPayload(ByteReader* r, const TuningFingerprint& fp,
                   TuningState* state) {
  state->snapshot_version = r->U64();
  state->retune_count = r->U64();
  const uint8_t seen = r->U8();
  const uint32_t cells = r->U32();
  if (!r->ok()) return Corrupt("payload cut short");
  if (seen > 1) return Corrupt("seen-traffic flag " + std::to_string(seen));
  state->seen_traffic = seen == 1;
  if (cells != uint64_t{fp.grid_size} * fp.grid_size) {
    return Corrupt(std::to_string(cells) + " cells in a " +
                   std::to_string(fp.grid_size) + "-grid");
  }
  uint64_t min_starts = 0, max_starts = 0;
  Status s = ReadCounts(r, cells, "histogram", &state->histogram);
  if (s.ok()) s = ReadCounts(r, cells, "planned share", &state->planned_share);
  if (s.ok()) s = ReadLevels(r, cells, state, &min_starts, &max_starts);
  if (s.ok()) {
    s = ReadStarts(r, min_starts, max_starts, fp.input_points, state);
  }
  if (s.ok() && r->remaining() != 0) {
    s = Corrupt(std::to_string(r->remaining()) + " bytes after the starts");
  }
  return s;
}

}  // namespace

uint64_t TuningFingerprint::Digest() const {
  ByteWriter w;
  WriteFingerprint(*this, &w);
  return Xxh3Of(w.bytes());
}

std::string FingerprintMismatch(const TuningFingerprint& saved,
                                const TuningFingerprint& expected) {
  if (saved.dataset_digest != expected.dataset_digest ||
      saved.input_points != expected.input_points) {
    return "saved for another dataset";
  }
  if (saved.strategy != expected.strategy) {
    return "saved for strategy '" + saved.strategy + "'";
  }
  if (saved.grid_size != expected.grid_size) {
    return "saved for a " + std::to_string(saved.grid_size) + "x" +
           std::to_string(saved.grid_size) + " grid, this one is " +
           std::to_string(expected.grid_size);
  }
  const BoundingBox& a = saved.grid_box;
  const BoundingBox& b = expected.grid_box;
  if (a.min_x != b.min_x || a.min_y != b.min_y || a.max_x != b.max_x ||
      a.max_y != b.max_y) {
    return "saved for another grid box";
  }
  if (saved.budget_bytes != expected.budget_bytes) {
    return "saved for a budget of " + std::to_string(saved.budget_bytes) +
           " bytes, this one is " + std::to_string(expected.budget_bytes);
  }
  return "";
}

std::string EncodeTuningState(const TuningFingerprint& fingerprint,
                              const TuningState& state) {
  ByteWriter w;
  w.bytes().append(kTuningStateMagic);
  w.U32(kTuningStateFormatVersion);
  w.U64(0);  // the length, patched below
  WriteFingerprint(fingerprint, &w);
  w.U64(state.snapshot_version);
  w.U64(state.retune_count);
  w.U8(state.seen_traffic ? 1 : 0);
  w.U32(static_cast<uint32_t>(state.histogram.size()));
  for (double v : state.histogram) w.F64(v);
  for (double v : state.planned_share) w.F64(v);
  for (uint32_t r : state.levels) w.U32(r);
  w.U64(state.starts.size());
  for (const auto& corners : state.starts) {
    for (uint32_t id : corners) w.U32(id);
  }
  std::string& bytes = w.bytes();
  const uint64_t length = bytes.size() + kChecksumBytes;
  for (int i = 0; i < 8; ++i) {
    bytes[kTuningStateMagic.size() + 4 + i] =
        static_cast<char>(length >> (8 * i));
  }
  w.U64(Xxh3Of(bytes));
  return std::move(bytes);
}

Status DecodeTuningState(std::string_view bytes,
                         const TuningFingerprint& expected, TuningState* out) {
  if (bytes.size() < kPreambleBytes + kChecksumBytes) {
    return Status::InvalidArgument(
        "truncated tuning state: " + std::to_string(bytes.size()) + " bytes");
  }
  ByteReader r(bytes.substr(0, bytes.size() - kChecksumBytes));
  if (r.Take(kTuningStateMagic.size()) != kTuningStateMagic) {
    return Status::InvalidArgument("not a tuning state file (bad magic)");
  }
  const uint32_t version = r.U32();
  if (version != kTuningStateFormatVersion) {
    return Status::InvalidArgument(
        "unsupported tuning state format version " + std::to_string(version) +
        " (this build reads " + std::to_string(kTuningStateFormatVersion) +
        ")");
  }
  const uint64_t length = r.U64();
  if (length != bytes.size()) {
    return Status::InvalidArgument(
        std::string(length > bytes.size() ? "truncated" : "overlong") +
        " tuning state: " + std::to_string(bytes.size()) +
        " bytes, the header says " + std::to_string(length));
  }
  ByteReader trailer(bytes.substr(bytes.size() - kChecksumBytes));
  if (trailer.U64() != Xxh3Of(bytes.substr(0, bytes.size() - kChecksumBytes))) {
    return Status::InvalidArgument("tuning state checksum mismatch");
  }
  TuningFingerprint saved;
  RETURN_IF_ERROR(ReadFingerprint(&r, &saved));
  if (const std::string why = FingerprintMismatch(saved, expected);
      !why.empty()) {
    return Status::FailedPrecondition("tuning state " + why);
  }
  TuningState state;
  RETURN_IF_ERROR(ReadPayload(&r, saved, &state));
  *out = std::move(state);
  return Status::OK();
}

}  // namespace locator
