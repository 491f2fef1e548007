#include "server/route/shard_streams.h"

#include <deque>
#include <optional>
#include <string>
#include <utility>

namespace locator {

// One LocateStream to a shard. It keeps itself alive from Start() until
// gRPC's OnDone(), and holds the call open (a hold) until it is closed or
// broken, as points may be written from outside its reactions.
class ShardStream final
    : public grpc::ClientBidiReactor<v1::LocateRequest, v1::LocateResponse>,
      public std::enable_shared_from_this<ShardStream> {
 public:
  explicit ShardStream(std::shared_ptr<grpc::ClientContext> context)
      : context_(std::move(context)) {}

  // Starts the call on `async`. Once, right after construction.
  void Start(v1::Locator::StubInterface::async_interface* async) {
    self_ = shared_from_this();
    async->LocateStream(context_.get(), this);
    AddHold();
    StartRead(&read_);
    StartCall();
  }

  // Writes `request` after the points sent before it; `done` gets the
  // shard's status for it once its answer is in *response.
  void Send(const v1::LocateRequest& request, v1::LocateResponse* response,
            ShardStreams::Done done) EXCLUDES(mu_) {
    const v1::LocateRequest* write = nullptr;
    std::optional<grpc::Status> ended;
    {
      MutexLock lock(&mu_);
      if (ended_status_) {
        ended = ended_status_;
      } else {
        unsent_.push_back(Unsent{request, Awaited{response, std::move(done)}});
        // A broken stream keeps its points for OnDone() to fail.
        if (!writing_ && !broken_) write = StartNextWrite();
      }
    }
    if (write != nullptr) StartWrite(write);
    if (ended) done(*ended);
  }

  // No more points: half-closes once the last is written.
  void Close() EXCLUDES(mu_) {
    bool writes_done = false, release = false;
    {
      MutexLock lock(&mu_);
      closing_ = true;
      if (!writing_ && !broken_) writes_done = true;
      release = ReleaseHold(writes_done || broken_);
    }
    if (writes_done) StartWritesDone();
    if (release) RemoveHold();
  }

  void OnWriteDone(bool ok) override EXCLUDES(mu_) {
    const v1::LocateRequest* write = nullptr;
    bool writes_done = false, release = false;
    {
      MutexLock lock(&mu_);
      unsent_.pop_front();
      writing_ = false;
      if (!ok) broken_ = true;  // OnDone() follows, with the status
      if (!broken_ && !unsent_.empty()) {
        write = StartNextWrite();
      } else if (!broken_ && closing_) {
        writes_done = true;
      }
      release = ReleaseHold(writes_done || broken_);
    }
    if (write != nullptr) StartWrite(write);
    if (writes_done) StartWritesDone();
    if (release) RemoveHold();
  }

  void OnReadDone(bool ok) override EXCLUDES(mu_) {
    std::optional<Awaited> answered;
    bool release = false;
    {
      MutexLock lock(&mu_);
      if (!ok) {
        // The shard ended the stream; OnDone() follows with its status.
        broken_ = true;
        release = ReleaseHold(true);
      } else if (!unanswered_.empty()) {
        answered = std::move(unanswered_.front());
        unanswered_.pop_front();
      }
    }
    if (release) RemoveHold();
    if (!ok) return;
    if (!answered) {
      // More answers than points: the shard is broken.
      context_->TryCancel();
      return;
    }
    *answered->response = std::move(read_);
    read_.Clear();
    StartRead(&read_);
    answered->done(grpc::Status::OK);
  }

  void OnDone(const grpc::Status& status) override EXCLUDES(mu_) {
    std::deque<Awaited> failed;
    grpc::Status failure = status;
    {
      MutexLock lock(&mu_);
      if (failure.ok()) {
        failure = grpc::Status(
            grpc::StatusCode::INTERNAL,
            "the shard's stream ended with " +
                std::to_string(unanswered_.size() + unsent_.size()) +
                " points unanswered");
      }
      ended_status_ = failure;
      failed = std::move(unanswered_);
      for (Unsent& unsent : unsent_) {
        failed.push_back(std::move(unsent.awaited));
      }
      unsent_.clear();
    }
    for (Awaited& awaited : failed) awaited.done(failure);
    // Last: may delete this.
    const std::shared_ptr<ShardStream> me = std::move(self_);
  }

 private:
  struct Awaited {
    v1::LocateResponse* response;
    ShardStreams::Done done;
  };
  struct Unsent {
    v1::LocateRequest request;
    Awaited awaited;
  };

  // Marks unsent_.front() as being written, its answer awaited next in
  // line, and returns the request to write. Precondition: !unsent_.empty().
  const v1::LocateRequest* StartNextWrite() REQUIRES(mu_) {
    writing_ = true;
    Unsent& next = unsent_.front();
    unanswered_.push_back(std::move(next.awaited));
    return &next.request;
  }

  // Whether the hold is to be removed now that `over` says the stream
  // needs no more writes: true once.
  bool ReleaseHold(bool over) REQUIRES(mu_) {
    if (!over || hold_released_) return false;
    hold_released_ = true;
    return true;
  }

  const std::shared_ptr<grpc::ClientContext> context_;
  std::shared_ptr<ShardStream> self_;  // from Start() to OnDone()
  v1::LocateResponse read_;            // owned by the read in flight

  Mutex mu_;
  // Not yet written; the front is being written while writing_.
  std::deque<Unsent> unsent_ GUARDED_BY(mu_);
  // Written (or being written), in order: the shard answers them so.
  std::deque<Awaited> unanswered_ GUARDED_BY(mu_);
  bool writing_ GUARDED_BY(mu_) = false;
  bool closing_ GUARDED_BY(mu_) = false;  // half-close after the last write
  bool broken_ GUARDED_BY(mu_) = false;   // a read or a write failed
  bool hold_released_ GUARDED_BY(mu_) = false;
  // Set by OnDone(): what every point it had not answered got.
  std::optional<grpc::Status> ended_status_ GUARDED_BY(mu_);
};

ShardStreams::ShardStreams(
    ShardTopology* topology,
    std::vector<std::shared_ptr<grpc::ClientContext>> contexts)
    : topology_(topology),
      contexts_(std::move(contexts)),
      streams_(contexts_.size()) {}

ShardStreams::~ShardStreams() {
  MutexLock lock(&mu_);
  for (const std::shared_ptr<ShardStream>& stream : streams_) {
    if (stream != nullptr) stream->Close();
  }
}

void ShardStreams::Send(size_t shard, const v1::LocateRequest& request,
                        v1::LocateResponse* response, Done done) {
  std::shared_ptr<ShardStream> stream;
  {
    MutexLock lock(&mu_);
    if (streams_[shard] == nullptr) {
      streams_[shard] =
          std::make_shared<ShardStream>(std::move(contexts_[shard]));
      streams_[shard]->Start(topology_->async(shard));
    }
    stream = streams_[shard];
  }
  stream->Send(request, response, std::move(done));
}

}  // namespace locator
