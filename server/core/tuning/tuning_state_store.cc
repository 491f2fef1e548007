#include "server/core/tuning/tuning_state_store.h"

#include <utility>

#include "server/core/dataset/file_io.h"

namespace locator {

TuningStateStore::TuningStateStore(const std::string& dir,
                                   TuningFingerprint fingerprint)
    : fingerprint_(std::move(fingerprint)),
      path_(DigestNamedPath(dir, "tuning-", fingerprint_.Digest(), ".state")) {}

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
