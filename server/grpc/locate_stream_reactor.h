// LocateStreamReactor: serves one LocateStream call: reads points, answers
// each in order, and finishes when the client half-closes.
//
// What to read, write and finish next is decided by a LocateStreamState
// (see there: one write in flight, at most kMaxQueuedAnswers queued, how
// each kind of end is reached); this class carries it out with gRPC.
//
// Until the reactor finishes, a read or a write is always outstanding, so a
// cancelled call always surfaces as a failed operation and then finishes:
// OnCancel() needs no action of its own.
//
// A stream whose client set no deadline gets the server's default (see
// CallDeadline), enforced by an alarm: when it fires the stream finishes
// with DEADLINE_EXCEEDED. If an answer is still being written then (the
// client may not be reading, so the status could never reach it behind the
// answer) and is not written within kStuckWriteGrace, the call is cancelled.
//
// Owns itself: deletes itself once OnDone() has run and no alarm callback
// is pending. Thread-safety: gRPC may run the read and write reactions and
// the alarm callbacks concurrently; the call's state is guarded by mu_, and
// gRPC operations are started after mu_ is released.

#ifndef LOCATOR_SERVER_LOCATE_STREAM_REACTOR_H_
#define LOCATOR_SERVER_LOCATE_STREAM_REACTOR_H_

#include <grpcpp/alarm.h>
#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>

#include "common/mutex.h"
#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/status.h"
#include "locator/v1/locator.pb.h"
#include "server/grpc/locate_stream_state.h"
#include "server/serving/call_deadline.h"

namespace locator {

class LocateStreamReactor final
    : public grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse> {
 public:
  static constexpr std::chrono::seconds kStuckWriteGrace{1};

  // Answers one request: the engine's (in the request's CRS), or the no-op
  // server's canned answer.
  using LocateFn =
      std::function<Status(const v1::LocateRequest& request, LocateResult*)>;

  // Starts reading the stream of `context`; every point is answered with
  // `locate`; `default_deadline` (zero: none) bounds a stream whose client
  // set no deadline.
  LocateStreamReactor(grpc::CallbackServerContext* context,
                      std::chrono::milliseconds default_deadline,
                      LocateFn locate);

  void OnReadDone(bool ok) override EXCLUDES(mu_);
  void OnWriteDone(bool ok) override EXCLUDES(mu_);
  void OnDone() override EXCLUDES(mu_);

 private:
  // The gRPC operations one reaction decided on, started once mu_ is free.
  struct Actions {
    const v1::LocateResponse* write = nullptr;
    bool read = false;
    std::optional<grpc::Status> finish;
  };

  // `next` with the stream's end as the status to finish with.
  Actions ToActionsLocked(const LocateStreamState::Actions& next) const
      REQUIRES(mu_);
  void Start(const Actions& actions) EXCLUDES(mu_);
  // Alarm callbacks: `fired` is false when the alarm was cancelled.
  void OnDeadline(bool fired) EXCLUDES(mu_);
  void OnStuckWrite(bool fired) EXCLUDES(mu_);
  // Ends an alarm callback: deletes the reactor if it was the last thing
  // keeping it.
  void ReleaseAlarm() EXCLUDES(mu_);
  // Whether the reactor may be deleted now.
  bool DoneLocked() const REQUIRES(mu_) {
    return done_ && alarms_pending_ == 0;
  }

  grpc::CallbackServerContext* const context_;
  const CallDeadline deadline_;
  const LocateFn locate_;
  v1::LocateRequest request_;  // filled by the single outstanding read

  Mutex mu_;
  LocateStreamState state_ GUARDED_BY(mu_);
  bool done_ GUARDED_BY(mu_) = false;       // OnDone() has run
  int alarms_pending_ GUARDED_BY(mu_) = 0;  // alarm callbacks still to run
  grpc::Alarm deadline_alarm_;
  grpc::Alarm stuck_write_alarm_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_LOCATE_STREAM_REACTOR_H_
