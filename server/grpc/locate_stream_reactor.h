// LocateStreamReactor: serves one LocateStream call: reads points, answers
// each in order, and finishes when the client half-closes.
//
// What to read, write and finish next is decided by a LocateStreamState
// (see there: one write in flight, at most kMaxQueuedAnswers queued, how
// each kind of end is reached); this class carries it out with gRPC. A
// point is answered by a LocateFn, at once (a server's engine) or later
// from another thread (a router's shard call), so points may be located
// while others wait to be written.
//
// Until the reactor finishes, a read, a write or a locate is always
// outstanding, so a cancelled call always surfaces as a failed operation
// (or a locate failing with the call) and then finishes: OnCancel() needs
// no action of its own.
//
// A stream whose client set no deadline gets the server's default (see
// CallDeadline), enforced by an alarm: when it fires the stream finishes
// with DEADLINE_EXCEEDED. If an answer is still being written then (the
// client may not be reading, so the status could never reach it behind the
// answer) and is not written within kStuckWriteGrace, the call is cancelled.
//
// Owns itself: deletes itself once OnDone() has run and no alarm callback
// or answer is pending. Thread-safety: gRPC may run the read and write
// reactions and the alarm callbacks, and a LocateFn its answers,
// concurrently; the call's state is guarded by mu_, and gRPC operations are
// started after mu_ is released.

#ifndef LOCATOR_SERVER_LOCATE_STREAM_REACTOR_H_
#define LOCATOR_SERVER_LOCATE_STREAM_REACTOR_H_

#include <grpcpp/alarm.h>
#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>

#include "common/mutex.h"
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

  // Takes the answer to one point: `located` OK with `*answer` (which it
  // may move from), or the error that ends the stream.
  using Answer = std::function<void(const grpc::Status& located,
                                    v1::LocateResponse* answer)>;
  // Locates one point and calls `answer` exactly once, on this thread
  // before returning or on any thread later. It reads `request` only until
  // it returns. Calls come one at a time, in the order of the points.
  using LocateFn =
      std::function<void(const v1::LocateRequest& request, Answer answer)>;

  // Starts reading the stream of `context`; every point is answered by
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
  // A LocateFn's answer to the point of `ticket`.
  void OnLocated(LocateStreamState::Ticket ticket, const grpc::Status& located,
                 v1::LocateResponse* answer) EXCLUDES(mu_);
  // Alarm callbacks: `fired` is false when the alarm was cancelled.
  void OnDeadline(bool fired) EXCLUDES(mu_);
  void OnStuckWrite(bool fired) EXCLUDES(mu_);
  // Ends an alarm callback or an answer: deletes the reactor if it was the
  // last thing keeping it.
  void Release() EXCLUDES(mu_);
  // Whether the reactor may be deleted now.
  bool DoneLocked() const REQUIRES(mu_) { return done_ && holds_ == 0; }

  grpc::CallbackServerContext* const context_;
  const CallDeadline deadline_;
  const LocateFn locate_;
  v1::LocateRequest request_;  // filled by the single outstanding read

  Mutex mu_;
  LocateStreamState state_ GUARDED_BY(mu_);
  bool done_ GUARDED_BY(mu_) = false;  // OnDone() has run
  // Alarm callbacks and answers still to come, each keeping the reactor.
  int holds_ GUARDED_BY(mu_) = 0;
  grpc::Alarm deadline_alarm_;
  grpc::Alarm stuck_write_alarm_;
};

// A LocateFn that answers at once with what `locate` returns: the result of
// one point located on this thread (a server's engine, the no-op server).
LocateStreamReactor::LocateFn AnswerAtOnce(
    std::function<Status(const v1::LocateRequest& request,
                         LocateResult* result)>
        locate);

}  // namespace locator

#endif  // LOCATOR_SERVER_LOCATE_STREAM_REACTOR_H_
