#include "server/core/tuning_state_store.h"

#include <cstdio>
#include <utility>

#include "server/core/file_io.h"

namespace locator {
namespace {

std::string StatePath(const std::string& dir, uint64_t digest) {
  char name[40];
  std::snprintf(name, sizeof(name), "tuning-%016llx.state",
                static_cast<unsigned long long>(digest));
  if (dir.empty() || dir.back() == '/') return dir + name;
  return dir + "/" + name;
}

}  // namespace

TuningStateStore::TuningStateStore(const std::string& dir,
                                   TuningFingerprint fingerprint)
    : fingerprint_(std::move(fingerprint)),
      path_(StatePath(dir, fingerprint_.Digest())) {}

Status TuningStateStore::Load(TuningState* state) const {
  std::string bytes;
  Status status = ReadWholeFile(path_, "tuning state", &bytes, kMaxFileBytes);
  if (!status.ok()) return status;
  return DecodeTuningState(bytes, fingerprint_, state);
}

Status TuningStateStore::Save(const TuningState& state) const {
  return WriteFileAtomically(path_, EncodeTuningState(fingerprint_, state));
}

}  // namespace locator
