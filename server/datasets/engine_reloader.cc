#include "server/datasets/engine_reloader.h"

#include <utility>

namespace locator {

EngineReloader::EngineReloader(Build build, Publish publish)
    : build_(std::move(build)), publish_(std::move(publish)) {}

EngineReloader::~EngineReloader() {
  if (worker_.joinable()) worker_.join();
}

Status EngineReloader::Start(const std::string& dataset, Done done) {
  MutexLock lock(&mu_);
  if (running_) return Status::FailedPrecondition("reload in progress");
  // The previous build cleared running_ before its last step, so its thread
  // has finished or is about to: reap it.
  if (worker_.joinable()) worker_.join();
  running_ = true;
  worker_ = std::thread([this, dataset, done = std::move(done)] {
    BuiltDataset built;
    const Status status = build_(dataset, &built);
    std::shared_ptr<Engine> engine = built.engine;
    const uint64_t generation = status.ok() ? publish_(std::move(built)) : 0;
    {
      // Finished before `done` answers: whoever hears of this reload may
      // start the next one at once.
      MutexLock lock(&mu_);
      running_ = false;
    }
    done(status, status.ok() ? std::move(engine) : nullptr, generation);
  });
  return Status::OK();
}

bool EngineReloader::in_progress() const {
  MutexLock lock(&mu_);
  return running_;
}

}  // namespace locator
