#include "server/grpc/locate_stream_state.h"

#include "server/app/proto_convert.h"

namespace locator {

LocateStreamState::Actions LocateStreamState::PointRead(
    const Status& located, const LocateResult& result) {
  reading_ = false;
  if (located.ok()) {
    ToLocateResponse(result, &answers_.emplace_back());
  } else if (!end_) {
    bad_point_status_ = located;
    EndWith(End::kBadPoint);
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
  answers_.pop_front();
  if (!ok) {
    // Nobody will read the rest.
    answers_.clear();
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
  answers_.resize(writing_ ? 1 : 0);
  *write_in_flight = writing_;
  return NextActions();
}

void LocateStreamState::EndWith(End end) {
  if (!end_) end_ = end;
}

LocateStreamState::Actions LocateStreamState::NextActions() {
  Actions actions;
  if (finished_) return actions;
  if (!writing_ && !answers_.empty()) {
    writing_ = true;
    actions.write = &answers_.front();
  }
  if (!end_ && !reading_ && answers_.size() < kMaxQueuedAnswers) {
    reading_ = true;
    actions.read = true;
  }
  if (end_ && !writing_ && answers_.empty()) {
    finished_ = true;
    actions.finish = *end_;
  }
  return actions;
}

}  // namespace locator
