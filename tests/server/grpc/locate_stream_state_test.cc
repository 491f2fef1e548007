// LocateStreamState driven directly, without gRPC: the operations it asks
// for after each event, for every way a stream ends.

#include "server/grpc/locate_stream_state.h"

#include <gtest/gtest.h>

#include <optional>

namespace locator {
namespace {

using End = LocateStreamState::End;
using Actions = LocateStreamState::Actions;

LocateResult AnswerFor(int64_t triangle) {
  LocateResult result;
  result.triangle_id = triangle;
  return result;
}

Actions Point(LocateStreamState& state, int64_t triangle) {
  return state.PointRead(Status::OK(), AnswerFor(triangle));
}

TEST(LocateStreamStateTest, AnswersInOrderOneWriteAtATime) {
  LocateStreamState state;
  Actions first = Point(state, 10);
  ASSERT_NE(first.write, nullptr);
  EXPECT_EQ(first.write->triangle_id(), 10);
  EXPECT_TRUE(first.read);
  EXPECT_FALSE(first.finish);

  // The next answer waits while the first is written.
  Actions second = Point(state, 11);
  EXPECT_EQ(second.write, nullptr);
  EXPECT_TRUE(second.read);
  EXPECT_EQ(state.queued_answers(), 2u);

  Actions written = state.WriteDone(true);
  ASSERT_NE(written.write, nullptr);
  EXPECT_EQ(written.write->triangle_id(), 11);
  EXPECT_FALSE(written.read);  // the read started above is still outstanding
  EXPECT_FALSE(written.finish);
}

TEST(LocateStreamStateTest, HalfCloseFinishesOkAfterTheQueuedAnswers) {
  LocateStreamState state;
  Point(state, 1);
  Point(state, 2);
  Actions closed = state.ReadFailed();
  EXPECT_FALSE(closed.read);
  EXPECT_FALSE(closed.finish);  // two answers still to write
  EXPECT_FALSE(state.WriteDone(true).finish);
  Actions last = state.WriteDone(true);
  EXPECT_EQ(last.write, nullptr);
  ASSERT_TRUE(last.finish);
  EXPECT_EQ(*last.finish, End::kHalfClosed);
  EXPECT_TRUE(state.finished());
}

TEST(LocateStreamStateTest, HalfCloseWithNothingQueuedFinishesAtOnce) {
  LocateStreamState state;
  Actions closed = state.ReadFailed();
  ASSERT_TRUE(closed.finish);
  EXPECT_EQ(*closed.finish, End::kHalfClosed);
  EXPECT_FALSE(closed.read);
  EXPECT_EQ(closed.write, nullptr);
}

TEST(LocateStreamStateTest, StopsReadingWhileTheQueueIsFull) {
  LocateStreamState state;
  Actions actions;
  for (size_t i = 0; i < LocateStreamState::kMaxQueuedAnswers; ++i) {
    actions = Point(state, static_cast<int64_t>(i));
  }
  // The client reads nothing: the last point filled the queue.
  EXPECT_FALSE(actions.read);
  EXPECT_EQ(state.queued_answers(), LocateStreamState::kMaxQueuedAnswers);
  // One answer out makes room: reading resumes.
  Actions written = state.WriteDone(true);
  EXPECT_TRUE(written.read);
  ASSERT_NE(written.write, nullptr);
  EXPECT_EQ(written.write->triangle_id(), 1);
}

TEST(LocateStreamStateTest, BadPointEndsTheStreamAfterTheAnswersBeforeIt) {
  LocateStreamState state;
  Point(state, 1);
  Actions bad =
      state.PointRead(Status::InvalidArgument("non-finite"), LocateResult());
  EXPECT_FALSE(bad.read);
  EXPECT_FALSE(bad.finish);
  Actions written = state.WriteDone(true);
  ASSERT_TRUE(written.finish);
  EXPECT_EQ(*written.finish, End::kBadPoint);
  EXPECT_EQ(state.bad_point_status().code(), Status::Code::kInvalidArgument);
  EXPECT_EQ(state.bad_point_status().message(), "non-finite");
}

TEST(LocateStreamStateTest, FailedWriteDropsTheRestAndEnds) {
  LocateStreamState state;
  Point(state, 1);
  Point(state, 2);
  Point(state, 3);
  // The read outstanding after the third point fails too, later.
  Actions failed = state.WriteDone(false);
  EXPECT_EQ(failed.write, nullptr);
  EXPECT_FALSE(failed.read);
  ASSERT_TRUE(failed.finish);
  EXPECT_EQ(*failed.finish, End::kClientGone);
  EXPECT_EQ(state.queued_answers(), 0u);
  // Nothing more happens after the finish.
  Actions late = state.ReadFailed();
  EXPECT_EQ(late.write, nullptr);
  EXPECT_FALSE(late.read);
  EXPECT_FALSE(late.finish);
}

TEST(LocateStreamStateTest, DeadlineWithoutWriteInFlightFinishesAtOnce) {
  LocateStreamState state;
  bool write_in_flight = true;
  Actions expired = state.DeadlinePassed(&write_in_flight);
  EXPECT_FALSE(write_in_flight);
  ASSERT_TRUE(expired.finish);
  EXPECT_EQ(*expired.finish, End::kDeadline);
  // The read still outstanding completes after the finish: nothing to do.
  Actions late = Point(state, 1);
  EXPECT_EQ(late.write, nullptr);
  EXPECT_FALSE(late.finish);
}

TEST(LocateStreamStateTest, DeadlineDuringAWriteDropsTheQueueAndWaitsForIt) {
  LocateStreamState state;
  Point(state, 1);
  Point(state, 2);
  Point(state, 3);
  bool write_in_flight = false;
  Actions expired = state.DeadlinePassed(&write_in_flight);
  EXPECT_TRUE(write_in_flight);
  EXPECT_FALSE(expired.finish);
  EXPECT_EQ(state.queued_answers(), 1u);  // only the one being written
  Actions written = state.WriteDone(true);
  EXPECT_EQ(written.write, nullptr);
  ASSERT_TRUE(written.finish);
  EXPECT_EQ(*written.finish, End::kDeadline);
}

TEST(LocateStreamStateTest, FirstEndWins) {
  LocateStreamState state;
  Point(state, 1);
  state.ReadFailed();  // half-closed first...
  bool write_in_flight = false;
  state.DeadlinePassed(&write_in_flight);  // ...then the deadline
  Actions written = state.WriteDone(true);
  ASSERT_TRUE(written.finish);
  EXPECT_EQ(*written.finish, End::kHalfClosed);
}

TEST(LocateStreamStateTest, DeadlineAfterFinishChangesNothing) {
  LocateStreamState state;
  state.ReadFailed();
  bool write_in_flight = true;
  Actions late = state.DeadlinePassed(&write_in_flight);
  EXPECT_FALSE(write_in_flight);
  EXPECT_FALSE(late.finish);
}

}  // namespace
}  // namespace locator
