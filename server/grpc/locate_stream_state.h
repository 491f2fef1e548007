// LocateStreamState: the state machine of one LocateStream call, without
// gRPC: which read, write and finish to start next, given what has happened
// (a point read, the client's half-close, a write done or failed, the
// deadline). LocateStreamReactor feeds it gRPC's reactions and starts the
// operations it returns; tests drive it directly.
//
// At most one write is in flight; answers computed meanwhile wait in a
// queue. While kMaxQueuedAnswers are waiting no read is started, so a client
// that sends without reading cannot grow the server's memory. A point that
// failed to locate ends the stream with its status once the answers before it
// are written; a failed write ends it at once. Until the stream finishes a
// read or a write is always outstanding. When the deadline passes, the
// answers not yet being written are dropped and the stream finishes as soon
// as no write is in flight.
//
// Thread-safety: none; the reactor calls it under its mutex.

#ifndef LOCATOR_SERVER_LOCATE_STREAM_STATE_H_
#define LOCATOR_SERVER_LOCATE_STREAM_STATE_H_

#include <cstddef>
#include <deque>
#include <optional>

#include "locator/locate_result.h"
#include "locator/status.h"
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

  // A new stream: its first read is outstanding (started by the caller).
  LocateStreamState() = default;

  LocateStreamState(const LocateStreamState&) = delete;
  LocateStreamState& operator=(const LocateStreamState&) = delete;

  // A read completed with a point, located with `located` and `result`.
  Actions PointRead(const Status& located, const LocateResult& result);
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
  // Answers located and not yet written (the one in flight included).
  size_t queued_answers() const { return answers_.size(); }
  // The status of the point that failed to locate (End::kBadPoint).
  const Status& bad_point_status() const { return bad_point_status_; }

 private:
  Actions NextActions();
  void EndWith(End end);

  std::deque<v1::LocateResponse> answers_;  // front is in flight if writing_
  bool writing_ = false;
  bool reading_ = true;     // the first read starts with the stream
  std::optional<End> end_;  // set once no more points will be read
  Status bad_point_status_;
  bool finished_ = false;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_LOCATE_STREAM_STATE_H_
