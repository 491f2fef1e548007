// LocateStreamReactor: serves one LocateStream call: reads points, answers
// each in order, and finishes when the client half-closes.
//
// At most one write is in flight; answers computed meanwhile wait in a queue.
// When kMaxQueuedAnswers are waiting the reactor stops reading until the
// client catches up, so a client that sends without reading cannot grow the
// server's memory. A point that fails to locate (not finite) ends the stream
// with that status once the answers before it have been written; a failed
// write (the client went away) ends it at once.
//
// Until the reactor finishes, a read or a write is always outstanding, so a
// cancelled call always surfaces as a failed operation and then finishes:
// OnCancel() needs no action of its own.
//
// A stream whose client set no deadline gets the server's default (see
// CallDeadline), enforced by an alarm: when it fires the stream stops
// reading, drops the answers not yet sent and finishes with
// DEADLINE_EXCEEDED. If an answer is still being written then (the client
// may not be reading, so the status could never reach it behind the answer)
// and is not written within kStuckWriteGrace, the call is cancelled.
//
// Owns itself: deletes itself once OnDone() has run and no alarm callback
// is pending. Thread-safety: gRPC may run the read and write reactions and
// the alarm callbacks concurrently; all state is guarded by mu_, and gRPC
// operations are started after mu_ is released.

#ifndef LOCATOR_SERVER_LOCATE_STREAM_REACTOR_H_
#define LOCATOR_SERVER_LOCATE_STREAM_REACTOR_H_

#include <grpcpp/alarm.h>
#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>

#include "locator/v1/locator.pb.h"
#include "server/call_deadline.h"
#include "server/core/geometry.h"
#include "server/core/locate_result.h"
#include "server/core/status.h"

namespace locator {

class LocateStreamReactor final
    : public grpc::ServerBidiReactor<v1::LocateRequest, v1::LocateResponse> {
 public:
  static constexpr size_t kMaxQueuedAnswers = 64;
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

  void OnReadDone(bool ok) override;
  void OnWriteDone(bool ok) override;
  void OnDone() override;

 private:
  // The gRPC operations one reaction decided on, started once mu_ is free.
  struct Actions {
    const v1::LocateResponse* write = nullptr;
    bool read = false;
    std::optional<grpc::Status> finish;
  };

  // Under mu_: starts the next write if none is in flight, resumes reading
  // if the queue has room, and finishes once the outcome is known and every
  // answer before it is written.
  Actions NextActionsLocked();
  void Start(const Actions& actions);
  // Alarm callbacks: `fired` is false when the alarm was cancelled.
  void OnDeadline(bool fired);
  void OnStuckWrite(bool fired);
  // Ends an alarm callback: deletes the reactor if it was the last thing
  // keeping it.
  void ReleaseAlarm();
  // Under mu_: whether the reactor may be deleted now.
  bool DoneLocked() const { return done_ && alarms_pending_ == 0; }

  grpc::CallbackServerContext* const context_;
  const CallDeadline deadline_;
  const LocateFn locate_;
  v1::LocateRequest request_;  // filled by the single outstanding read

  std::mutex mu_;
  std::deque<v1::LocateResponse> answers_;  // front is in flight if writing_
  bool writing_ = false;
  bool reading_ = false;  // a read is outstanding
  // The stream's outcome, set once no more points will be read.
  std::optional<grpc::Status> outcome_;
  bool finished_ = false;
  bool done_ = false;       // OnDone() has run
  int alarms_pending_ = 0;  // alarm callbacks still to run
  grpc::Alarm deadline_alarm_;
  grpc::Alarm stuck_write_alarm_;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_LOCATE_STREAM_REACTOR_H_
