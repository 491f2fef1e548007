#include "server/locate_stream_reactor.h"

#include <utility>

#include "server/proto_convert.h"
#include "server/status_mapping.h"

namespace locator {

LocateStreamReactor::LocateStreamReactor(LocateFn locate)
    : locate_(std::move(locate)) {
  {
    // The reactions run on other threads; they see this construction (and
    // what locate_ refers to) through mu_, like all other state. gRPC orders
    // them after it too, but through synchronization ThreadSanitizer cannot
    // see.
    std::lock_guard<std::mutex> lock(mu_);
    reading_ = true;
  }
  StartRead(&request_);
}

void LocateStreamReactor::OnReadDone(bool ok) {
  Actions actions;
  {
    std::lock_guard<std::mutex> lock(mu_);
    reading_ = false;
    if (!ok) {
      // The client half-closed (or the call died, in which case the status
      // is never seen): finish once the queued answers are out.
      if (!outcome_) outcome_ = grpc::Status::OK;
    } else {
      LocateResult result;
      const v1::Point& point = request_.point();
      Status status = locate_(Point2{point.x(), point.y()}, &result);
      if (status.ok()) {
        ToLocateResponse(result, &answers_.emplace_back());
      } else if (!outcome_) {
        outcome_ = ToGrpcStatus(status);
      }
    }
    actions = NextActionsLocked();
  }
  Start(actions);
}

void LocateStreamReactor::OnWriteDone(bool ok) {
  Actions actions;
  {
    std::lock_guard<std::mutex> lock(mu_);
    writing_ = false;
    answers_.pop_front();
    if (!ok) {
      // Nobody will read the rest; the status only matters for the logs.
      answers_.clear();
      if (!outcome_) {
        outcome_ = grpc::Status(grpc::StatusCode::CANCELLED,
                                "the client stopped reading answers");
      }
    }
    actions = NextActionsLocked();
  }
  Start(actions);
}

void LocateStreamReactor::OnDone() { delete this; }

LocateStreamReactor::Actions LocateStreamReactor::NextActionsLocked() {
  Actions actions;
  if (finished_) return actions;
  if (!writing_ && !answers_.empty()) {
    writing_ = true;
    actions.write = &answers_.front();
  }
  if (!outcome_ && !reading_ && answers_.size() < kMaxQueuedAnswers) {
    reading_ = true;
    actions.read = true;
  }
  if (outcome_ && !writing_ && answers_.empty()) {
    finished_ = true;
    actions.finish = *outcome_;
  }
  return actions;
}

void LocateStreamReactor::Start(const Actions& actions) {
  // deque::emplace_back keeps references valid, and the front is popped only
  // in OnWriteDone, so actions.write stays valid until its write completes.
  if (actions.write != nullptr) StartWrite(actions.write);
  if (actions.read) StartRead(&request_);
  if (actions.finish) Finish(*actions.finish);
}

}  // namespace locator
