// LocateStreamState: the state machine of one LocateStream call, without
// gRPC's calls: which read, write and finish to start next, given what has
// happened (a point read, its answer, the client's half-close, a write done
// or failed, the deadline). LocateStreamReactor feeds it gRPC's reactions
// and starts the operations it returns; tests drive it directly.
//
// A point read takes a ticket; its answer may come at once (a server's
// engine) or later, from another thread (a router's shard), and answers are
// written in the order of their points whatever order they come in. At
// most one write is in flight; answers located meanwhile, and points still
// being located, wait in a queue. While kMaxQueuedAnswers are waiting no
// read is started, so a client that sends without reading cannot grow the
// server's memory. A point that failed to locate ends the stream with its
// status once the answers before it are written; no point after it is
// read, and none after it is answered. A failed write ends the stream at
// once. Until the stream finishes a read, a write or a locate is always
// outstanding. When the deadline passes, the answers not yet being written
// are dropped (and points still being located are answered in vain) and
// the stream finishes as soon as no write is in flight.
//
// Thread-safety: none; the reactor calls it under its mutex.

#ifndef LOCATOR_SERVER_LOCATE_STREAM_STATE_H_
#define LOCATOR_SERVER_LOCATE_STREAM_STATE_H_

#include <grpcpp/support/status.h>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>

#include "locator/v1/locator.pb.h"

namespace locator {

class LocateStreamState {
 public:
  static constexpr size_t kMaxQueuedAnswers = 64;

  // Why a stream ended.
  enum class End {
    kHalfClosed,  // the client half-closed (or the call died on a read)
    kBadPoint,    // a point failed to locate: see bad_point_status()
    kClientGone,  // a write failed: the client stopped reading
    kDeadline,    // the server's default deadline passed
  };

  // The operations to start next, in this order.
  struct Actions {
    const v1::LocateResponse* write = nullptr;  // valid until its WriteDone
    bool read = false;
    std::optional<End> finish;
  };

  // Names a point read, for its answer.
  using Ticket = uint64_t;

  // A new stream: its first read is outstanding (started by the caller).
  LocateStreamState() = default;

  LocateStreamState(const LocateStreamState&) = delete;
  LocateStreamState& operator=(const LocateStreamState&) = delete;

  // A read completed with a point, which is now being located. No read
  // starts until LocateStarted() (the read buffer holds the point).
  Ticket PointRead();
  // The locate of the last point read has started, or is done: the read
  // buffer is free.
  Actions LocateStarted();
  // The point of `ticket` was located: `located` OK with `*answer` (taken),
  // or its error. An answer the stream no longer waits for is dropped.
  Actions Answered(Ticket ticket, const grpc::Status& located,
                   v1::LocateResponse* answer);
  // A read failed: the client half-closed.
  Actions ReadFailed();
  // The write in flight completed (`ok`) or failed.
  Actions WriteDone(bool ok);
  // The deadline passed. `*write_in_flight` tells whether an answer is still
  // being written (the stream then finishes once it is, or never if the
  // client does not read it).
  Actions DeadlinePassed(bool* write_in_flight);

  // Whether the stream has been told to finish.
  bool finished() const { return finished_; }
  // Points read and not yet written (the one in flight included).
  size_t queued_answers() const { return queue_.size(); }
  // The status of the point that failed to locate (End::kBadPoint).
  const grpc::Status& bad_point_status() const { return bad_point_status_; }

 private:
  // A point read, in the order of reading.
  struct Queued {
    Ticket ticket;
    bool answered = false;
    grpc::Status located;       // when answered
    v1::LocateResponse answer;  // when answered OK
  };

  Actions NextActions();
  void EndWith(End end);

  std::deque<Queued> queue_;  // front is in flight if writing_
  Ticket next_ticket_ = 0;
  bool writing_ = false;
  bool reading_ = true;     // the first read starts with the stream
  bool locating_ = false;   // PointRead() until LocateStarted()
  bool failed_ = false;     // a point in the queue failed to locate
  std::optional<End> end_;  // set once no more points will be read
  grpc::Status bad_point_status_;
  bool finished_ = false;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_LOCATE_STREAM_STATE_H_
