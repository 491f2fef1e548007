// TuningStateStore: where one fingerprint's tuning state lives in a state
// directory, and loading and saving it there.
//
// The file is named after the fingerprint's digest
// ("tuning-<16 hex digits>.state"), so states learned for other datasets or
// configurations sit side by side in one directory and a server that
// reloads back to an earlier dataset finds its state again. Saves are
// atomic (WriteFileAtomically): a reader never sees half a file.
//
// Thread-safety: immutable after construction; Load() and Save() may be
// called from any thread (concurrent saves: the last rename wins whole).

#ifndef LOCATOR_CORE_TUNING_STATE_STORE_H_
#define LOCATOR_CORE_TUNING_STATE_STORE_H_

#include <cstddef>
#include <string>

#include "locator/status.h"
#include "server/core/tuning/tuning_state.h"

namespace locator {

class TuningStateStore {
 public:
  // Larger files are rejected unread: no budget needs a state this big.
  static constexpr size_t kMaxFileBytes = size_t{1} << 30;

  // The store for `fingerprint` in the directory `dir`.
  TuningStateStore(const std::string& dir, TuningFingerprint fingerprint);

  // The state file's path.
  const std::string& path() const { return path_; }

  // Reads and decodes the state file. NotFound when there is none yet;
  // otherwise a Status naming why the file cannot be used.
  Status Load(TuningState* state) const;
  // Encodes `state` and replaces the state file with it atomically.
  Status Save(const TuningState& state) const;

 private:
  const TuningFingerprint fingerprint_;
  const std::string path_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TUNING_STATE_STORE_H_
