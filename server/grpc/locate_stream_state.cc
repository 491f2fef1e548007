#include "server/grpc/locate_stream_state.h"

#include <utility>

namespace locator {

LocateStreamState::Ticket LocateStreamState::PointRead() {
  reading_ = false;
  locating_ = true;
  const Ticket ticket = next_ticket_++;
  // After an end, or a point that failed, the point is answered in vain.
  if (!end_ && !failed_) queue_.emplace_back().ticket = ticket;
  return ticket;
}

LocateStreamState::Actions LocateStreamState::LocateStarted() {
  locating_ = false;
  return NextActions();
}

LocateStreamState::Actions LocateStreamState::Answered(
    Ticket ticket, const grpc::Status& located, v1::LocateResponse* answer) {
  // At most kMaxQueuedAnswers to look through, most often the front.
  for (Queued& queued : queue_) {
    if (queued.ticket != ticket) continue;
    queued.answered = true;
    queued.located = located;
    if (located.ok()) {
      queued.answer = std::move(*answer);
    } else {
      failed_ = true;
    }
    break;
  }
  return NextActions();
}

LocateStreamState::Actions LocateStreamState::ReadFailed() {
  reading_ = false;
  EndWith(End::kHalfClosed);
  return NextActions();
}

LocateStreamState::Actions LocateStreamState::WriteDone(bool ok) {
  writing_ = false;
  queue_.pop_front();
  if (!ok) {
    // Nobody will read the rest.
    queue_.clear();
    EndWith(End::kClientGone);
  }
  return NextActions();
}

LocateStreamState::Actions LocateStreamState::DeadlinePassed(
    bool* write_in_flight) {
  *write_in_flight = false;
  if (finished_) return {};
  EndWith(End::kDeadline);
  // Answers not yet being written are dropped: the stream is over.
  queue_.resize(writing_ ? 1 : 0);
  *write_in_flight = writing_;
  return NextActions();
}

void LocateStreamState::EndWith(End end) {
  if (!end_) end_ = end;
}

LocateStreamState::Actions LocateStreamState::NextActions() {
  Actions actions;
  if (finished_) return actions;
  if (!writing_ && !queue_.empty() && queue_.front().answered) {
    if (queue_.front().located.ok()) {
      writing_ = true;
      actions.write = &queue_.front().answer;
    } else {
      // Every answer before it is written; those after it never are. It
      // ends the stream even after a half-close: its point came first.
      bad_point_status_ = queue_.front().located;
      queue_.clear();
      end_ = End::kBadPoint;
    }
  }
  if (!end_ && !failed_ && !reading_ && !locating_ &&
      queue_.size() < kMaxQueuedAnswers) {
    reading_ = true;
    actions.read = true;
  }
  if (end_ && !writing_ && queue_.empty()) {
    finished_ = true;
    actions.finish = *end_;
  }
  return actions;
}

}  // namespace locator
