// CrsVerdicts: the verdicts on CRSs (or CRS pairs) that requests named,
// shared by every thread, so that a CRS that failed to be made fails again
// at the cost of a look-up, and one being made is made once however many
// threads ask for it at the same time.
//
// It owns a map from a key (the CRS text, or a pair's) to the verdict, at
// most kCapacity keys: when full, the decided verdicts are forgotten (the
// ones still being made stay, for their waiters).
//
// Thread-safety: thread-safe; Decide() blocks while another thread makes
// the same key.

#ifndef LOCATOR_COMMON_GIS_CRS_VERDICTS_H_
#define LOCATOR_COMMON_GIS_CRS_VERDICTS_H_

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "common/mutex.h"
#include "common/thread_annotations.h"
#include "locator/status.h"

namespace locator::gis {

class CrsVerdicts {
 public:
  static constexpr size_t kCapacity = 256;

  CrsVerdicts() = default;
  CrsVerdicts(const CrsVerdicts&) = delete;
  CrsVerdicts& operator=(const CrsVerdicts&) = delete;

  // The status of making `key`: a failure already known is returned without
  // calling `make`; otherwise `make` runs (its objects are the caller's own,
  // so a key known to be good is made again by each caller), and its status
  // is recorded when it is the first for `key`. A caller that finds `key`
  // being made waits for that verdict first.
  Status Decide(const std::string& key, const std::function<Status()>& make)
      EXCLUDES(mu_);

 private:
  // Its fields are guarded by mu_ (shared with waiters that outlive the
  // map's entry).
  struct Verdict {
    bool decided = false;
    Status status;
  };

  Mutex mu_;
  CondVar decided_;
  std::map<std::string, std::shared_ptr<Verdict>> verdicts_ GUARDED_BY(mu_);
};

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_CRS_VERDICTS_H_
