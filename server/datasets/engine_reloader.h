// EngineReloader: builds engines one at a time on a thread of its own and
// publishes each, so that neither a gRPC callback thread nor the signal loop
// waits while a triangulation is built.
//
// Owns the build thread. Invariants: at most one build runs (Start() while
// one runs fails with FailedPrecondition "reload in progress"), and a build
// publishes its engine before the next build can start, so engines are
// published in the order their reloads were accepted.
//
// Thread-safety: Start() and in_progress() may be called from any thread.

#ifndef LOCATOR_SERVER_ENGINE_RELOADER_H_
#define LOCATOR_SERVER_ENGINE_RELOADER_H_

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "common/mutex.h"
#include "locator/engine.h"
#include "locator/status.h"
#include "server/datasets/built_dataset.h"

namespace locator {

class EngineReloader {
 public:
  // Builds an engine (and its tiles) from a dataset spec.
  using Build =
      std::function<Status(const std::string& dataset, BuiltDataset* built)>;
  // Makes a built engine serve; returns its generation.
  using Publish = std::function<uint64_t(BuiltDataset built)>;
  // Receives a reload's outcome: OK, the engine and its generation; or the
  // error, null and 0.
  using Done =
      std::function<void(const Status& status, std::shared_ptr<Engine> engine,
                         uint64_t generation)>;

  EngineReloader(Build build, Publish publish);
  // Waits for a running build to finish.
  ~EngineReloader();

  EngineReloader(const EngineReloader&) = delete;
  EngineReloader& operator=(const EngineReloader&) = delete;

  // Starts building `dataset` on the build thread, which publishes the
  // engine if the build succeeds, marks the reload finished and then calls
  // `done` (which must not call Start()). FailedPrecondition "reload in
  // progress" (and `done` is never called) if a build is running.
  Status Start(const std::string& dataset, Done done) EXCLUDES(mu_);
  // Whether a build is running.
  bool in_progress() const EXCLUDES(mu_);

 private:
  const Build build_;
  const Publish publish_;
  mutable Mutex mu_;
  bool running_ GUARDED_BY(mu_) = false;
  std::thread worker_ GUARDED_BY(mu_);  // the last build's thread
};

}  // namespace locator

#endif  // LOCATOR_SERVER_ENGINE_RELOADER_H_
