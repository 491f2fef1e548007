#include "client/load/stream_runner.h"

#include <deque>

#include "common/in_flight.h"
#include "common/mutex.h"

namespace locator {
namespace {

// One bidi stream. Deletes itself when the stream is done.
class WindowedStream : public LocatorClient::StreamReactor {
 public:
  WindowedStream(QuerySource& source, size_t window, RunBudget& budget,
                 RunRecorder& recorder, InFlight& streams)
      : source_(source),
        window_(window),
        budget_(budget),
        recorder_(recorder),
        streams_(streams) {}

  void Start(LocatorClient& client,
             std::chrono::system_clock::time_point deadline) {
    streams_.Add();
    // Every request of the stream is this one with another point.
    ApplyScope(client.scope(), &request_);
    client.StartLocateStream(&context_, deadline, this);
    StartRead(&response_);
    SendMore();
    StartCall();
  }

  void OnWriteDone(bool ok) override {
    {
      MutexLock lock(&mutex_);
      writing_ = false;
      // A failed write means the stream is broken; OnDone() follows.
      if (!ok) closed_ = true;
    }
    SendMore();
  }

  void OnReadDone(bool ok) override {
    // Not ok: the server closed the stream; OnDone() follows.
    if (!ok) return;
    const uint32_t cost = response_.cost().total();
    Sent answered;
    {
      MutexLock lock(&mutex_);
      if (unanswered_.empty()) {
        // More answers than requests: the server is broken; end the stream.
        context_.TryCancel();
        return;
      }
      answered = unanswered_.front();
      unanswered_.pop_front();
    }
    recorder_.RecordCall(answered.claim, answered.at, LoadClock::now(),
                         grpc::Status::OK, std::span<const uint32_t>(&cost, 1));
    StartRead(&response_);
    SendMore();
  }

  void OnDone(const grpc::Status& status) override {
    const grpc::Status failure =
        status.ok() ? grpc::Status(grpc::StatusCode::INTERNAL,
                                   "stream ended with requests unanswered")
                    : status;
    std::deque<Sent> unanswered;
    {
      // No reaction runs any more; the lock is for the analysis' sake.
      MutexLock lock(&mutex_);
      unanswered.swap(unanswered_);
    }
    const LoadClock::time_point now = LoadClock::now();
    for (const Sent& sent : unanswered) {
      recorder_.RecordCall(sent.claim, sent.at, now, failure, {});
    }
    InFlight& streams = streams_;
    delete this;
    streams.Remove();
  }

 private:
  struct Sent {
    Claim claim;
    LoadClock::time_point at;
  };

  // Writes the next request if the window and the budget allow and no
  // write is in progress (a stream takes one write at a time), or half-
  // closes the stream once the budget is spent.
  void SendMore() EXCLUDES(mutex_) {
    enum { kNothing, kWrite, kClose } action = kNothing;
    {
      MutexLock lock(&mutex_);
      if (writing_ || closed_ || unanswered_.size() >= window_) return;
      const LoadClock::time_point now = LoadClock::now();
      Claim claim;
      if (budget_.TryClaim(1, now, &claim)) {
        const Point2 point = source_.Next();
        request_.mutable_point()->set_x(point.x);
        request_.mutable_point()->set_y(point.y);
        unanswered_.push_back(Sent{claim, now});
        writing_ = true;
        action = kWrite;
      } else {
        closed_ = true;
        action = kClose;
      }
    }
    // Outside the lock: gRPC may run reactions on other threads meanwhile.
    if (action == kWrite) StartWrite(&request_);
    if (action == kClose) StartWritesDone();
  }

  QuerySource& source_;
  const size_t window_;
  RunBudget& budget_;
  RunRecorder& recorder_;
  InFlight& streams_;

  grpc::ClientContext context_;
  v1::LocateRequest request_;    // guarded by writing_
  v1::LocateResponse response_;  // owned by the one read in progress

  Mutex mutex_;
  bool writing_ GUARDED_BY(mutex_) = false;  // a write is in progress
  // No more writes: half-closed or broken.
  bool closed_ GUARDED_BY(mutex_) = false;
  std::deque<Sent> unanswered_ GUARDED_BY(mutex_);
};

}  // namespace

void RunStreams(ClientPool& pool, QuerySource& source, size_t streams,
                size_t window, RunBudget& budget, RunRecorder& recorder) {
  const auto deadline = std::chrono::system_clock::now() +
                        (budget.end() - LoadClock::now()) + pool.deadline();
  InFlight streams_in_flight;
  for (size_t i = 0; i < streams; ++i) {
    auto* stream =
        new WindowedStream(source, window, budget, recorder, streams_in_flight);
    stream->Start(pool.client(i % pool.size()), deadline);
  }
  streams_in_flight.WaitUntilNone();
}

}  // namespace locator
