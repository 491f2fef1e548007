#include "server/grpc/locate_stream_reactor.h"

#include <utility>

#include "common/status_mapping.h"
#include "server/app/proto_convert.h"
#include "server/grpc/call_context.h"

namespace locator {

LocateStreamReactor::LocateStreamReactor(
    grpc::CallbackServerContext* context,
    std::chrono::milliseconds default_deadline, LocateFn locate)
    : context_(context),
      deadline_(DeadlineOf(*context, default_deadline)),
      locate_(std::move(locate)) {
  {
    // The reactions run on other threads; they see this construction (and
    // what locate_ refers to) through mu_, like all other state. gRPC orders
    // them after it too, but through synchronization ThreadSanitizer cannot
    // see.
    MutexLock lock(&mu_);
    if (deadline_.ServerEnforced()) holds_ = 1;
  }
  // gRPC enforces a deadline the client set; the server's default is ours.
  if (deadline_.ServerEnforced()) {
    deadline_alarm_.Set(deadline_.when,
                        [this](bool fired) { OnDeadline(fired); });
  }
  StartRead(&request_);
}

void LocateStreamReactor::OnReadDone(bool ok) {
  if (!ok) {
    // The client half-closed (or the call died, in which case the status is
    // never seen).
    Actions actions;
    {
      MutexLock lock(&mu_);
      actions = ToActionsLocked(state_.ReadFailed());
    }
    Start(actions);
    return;
  }
  LocateStreamState::Ticket ticket;
  {
    MutexLock lock(&mu_);
    ticket = state_.PointRead();
    ++holds_;  // until the answer comes
  }
  locate_(request_, [this, ticket](const grpc::Status& located,
                                   v1::LocateResponse* answer) {
    OnLocated(ticket, located, answer);
  });
  Actions actions;
  {
    MutexLock lock(&mu_);
    actions = ToActionsLocked(state_.LocateStarted());
  }
  Start(actions);
}

void LocateStreamReactor::OnLocated(LocateStreamState::Ticket ticket,
                                    const grpc::Status& located,
                                    v1::LocateResponse* answer) {
  Actions actions;
  {
    MutexLock lock(&mu_);
    actions = ToActionsLocked(state_.Answered(ticket, located, answer));
  }
  // Safe without gRPC's reference: this answer's hold keeps the reactor.
  Start(actions);
  Release();
}

void LocateStreamReactor::OnWriteDone(bool ok) {
  Actions actions;
  {
    MutexLock lock(&mu_);
    actions = ToActionsLocked(state_.WriteDone(ok));
  }
  Start(actions);
}

void LocateStreamReactor::OnDone() {
  bool delete_now;
  {
    MutexLock lock(&mu_);
    done_ = true;
    delete_now = DoneLocked();
    // Counted like an alarm while the alarms are cancelled below: their
    // callbacks run on other threads, and the last one to run deletes the
    // reactor, which must not happen while this thread still touches it.
    if (!delete_now) ++holds_;
  }
  if (delete_now) {
    delete this;
    return;
  }
  // The pending callbacks run with fired == false.
  deadline_alarm_.Cancel();
  stuck_write_alarm_.Cancel();
  Release();
}

void LocateStreamReactor::OnDeadline(bool fired) {
  Actions actions;
  {
    MutexLock lock(&mu_);
    if (fired && !state_.finished() && !done_) {
      bool write_in_flight = false;
      actions = ToActionsLocked(state_.DeadlinePassed(&write_in_flight));
      if (write_in_flight) {
        ++holds_;
        stuck_write_alarm_.Set(
            std::chrono::system_clock::now() + kStuckWriteGrace,
            [this](bool stuck) { OnStuckWrite(stuck); });
      }
    }
  }
  // Safe without gRPC's reference: this alarm's count keeps the reactor.
  Start(actions);
  Release();
}

void LocateStreamReactor::OnStuckWrite(bool fired) {
  {
    // Under mu_, so that OnDone() (which ends the context's life) waits.
    // TryCancel() runs no reaction on this thread: gRPC schedules them.
    MutexLock lock(&mu_);
    if (fired && !state_.finished() && !done_) context_->TryCancel();
  }
  Release();
}

void LocateStreamReactor::Release() {
  bool delete_now;
  {
    MutexLock lock(&mu_);
    --holds_;
    delete_now = DoneLocked();
  }
  if (delete_now) delete this;
}

LocateStreamReactor::Actions LocateStreamReactor::ToActionsLocked(
    const LocateStreamState::Actions& next) const {
  Actions actions;
  actions.write = next.write;
  actions.read = next.read;
  if (!next.finish) return actions;
  switch (*next.finish) {
    case LocateStreamState::End::kHalfClosed:
      actions.finish = grpc::Status::OK;
      break;
    case LocateStreamState::End::kBadPoint:
      actions.finish = state_.bad_point_status();
      break;
    case LocateStreamState::End::kClientGone:
      // Nobody reads it; it only matters for the logs.
      actions.finish = grpc::Status(grpc::StatusCode::CANCELLED,
                                    "the client stopped reading answers");
      break;
    case LocateStreamState::End::kDeadline:
      actions.finish = ToGrpcStatus(deadline_.ExceededStatus("streaming"));
      break;
  }
  return actions;
}

void LocateStreamReactor::Start(const Actions& actions) {
  // LocateStreamState keeps actions.write valid until its write completes.
  if (actions.write != nullptr) StartWrite(actions.write);
  if (actions.read) StartRead(&request_);
  if (actions.finish) Finish(*actions.finish);
}

LocateStreamReactor::LocateFn AnswerAtOnce(
    std::function<Status(const v1::LocateRequest& request,
                         LocateResult* result)>
        locate) {
  return
      [locate = std::move(locate)](const v1::LocateRequest& request,
                                   const LocateStreamReactor::Answer& answer) {
        LocateResult result;
        v1::LocateResponse response;
        const Status located = locate(request, &result);
        if (located.ok()) ToLocateResponse(result, &response);
        answer(ToGrpcStatus(located), &response);
      };
}

}  // namespace locator
