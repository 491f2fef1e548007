#include "server/locate_stream_reactor.h"

#include <utility>

#include "server/proto_convert.h"
#include "server/status_mapping.h"

namespace locator {

LocateStreamReactor::LocateStreamReactor(
    grpc::CallbackServerContext* context,
    std::chrono::milliseconds default_deadline, LocateFn locate)
    : context_(context),
      deadline_(CallDeadline::For(*context, default_deadline)),
      locate_(std::move(locate)) {
  {
    // The reactions run on other threads; they see this construction (and
    // what locate_ refers to) through mu_, like all other state. gRPC orders
    // them after it too, but through synchronization ThreadSanitizer cannot
    // see.
    std::lock_guard<std::mutex> lock(mu_);
    reading_ = true;
    if (deadline_.ServerEnforced()) alarms_pending_ = 1;
  }
  // gRPC enforces a deadline the client set; the server's default is ours.
  if (deadline_.ServerEnforced()) {
    deadline_alarm_.Set(deadline_.when,
                        [this](bool fired) { OnDeadline(fired); });
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
      Point2 point;
      LocateResult result;
      Status status = FromLocateRequest(request_, &point);
      if (status.ok()) status = locate_(point, &result);
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

void LocateStreamReactor::OnDone() {
  bool delete_now;
  {
    std::lock_guard<std::mutex> lock(mu_);
    done_ = true;
    delete_now = DoneLocked();
    // Counted like an alarm while the alarms are cancelled below: their
    // callbacks run on other threads, and the last one to run deletes the
    // reactor, which must not happen while this thread still touches it.
    if (!delete_now) ++alarms_pending_;
  }
  if (delete_now) {
    delete this;
    return;
  }
  // The pending callbacks run with fired == false.
  deadline_alarm_.Cancel();
  stuck_write_alarm_.Cancel();
  ReleaseAlarm();
}

void LocateStreamReactor::OnDeadline(bool fired) {
  Actions actions;
  {
    std::lock_guard<std::mutex> lock(mu_);
    if (fired && !finished_ && !done_) {
      if (!outcome_) outcome_ = deadline_.ExceededStatus("streaming");
      // Answers not yet being written are dropped: the stream is over.
      answers_.resize(writing_ ? 1 : 0);
      if (writing_) {
        ++alarms_pending_;
        stuck_write_alarm_.Set(
            std::chrono::system_clock::now() + kStuckWriteGrace,
            [this](bool stuck) { OnStuckWrite(stuck); });
      }
      actions = NextActionsLocked();
    }
  }
  // Safe without gRPC's reference: this alarm's count keeps the reactor.
  Start(actions);
  ReleaseAlarm();
}

void LocateStreamReactor::OnStuckWrite(bool fired) {
  {
    // Under mu_, so that OnDone() (which ends the context's life) waits.
    // TryCancel() runs no reaction on this thread: gRPC schedules them.
    std::lock_guard<std::mutex> lock(mu_);
    if (fired && !finished_ && !done_) context_->TryCancel();
  }
  ReleaseAlarm();
}

void LocateStreamReactor::ReleaseAlarm() {
  bool delete_now;
  {
    std::lock_guard<std::mutex> lock(mu_);
    --alarms_pending_;
    delete_now = DoneLocked();
  }
  if (delete_now) delete this;
}

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
