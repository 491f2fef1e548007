// LocateStreamState driven directly, without gRPC: the operations it asks
// for after each event, for every way a stream ends.

#include "server/grpc/locate_stream_state.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

namespace locator {
namespace {

using End = LocateStreamState::End;
using Actions = LocateStreamState::Actions;

v1::LocateResponse AnswerFor(int64_t triangle) {
  v1::LocateResponse answer;
  answer.set_triangle_id(triangle);
  return answer;
}

// What the reactor starts after both: `first`'s operations, then `second`'s.
Actions Both(const Actions& first, const Actions& second) {
  EXPECT_FALSE(first.write != nullptr && second.write != nullptr);
  EXPECT_FALSE(first.read && second.read);
  return Actions{.write = first.write != nullptr ? first.write : second.write,
                 .read = first.read || second.read,
                 .finish = first.finish ? first.finish : second.finish};
}

// A point read and answered at once (`located`), as a server's engine
// answers it: the actions of its answer and of its locate's start.
Actions Located(LocateStreamState& state, const grpc::Status& located,
                int64_t triangle) {
  const LocateStreamState::Ticket ticket = state.PointRead();
  v1::LocateResponse answer = AnswerFor(triangle);
  const Actions answered = state.Answered(ticket, located, &answer);
  return Both(answered, state.LocateStarted());
}

Actions Point(LocateStreamState& state, int64_t triangle) {
  return Located(state, grpc::Status::OK, triangle);
}

// A point read whose answer comes later, as a router's shard answers it.
LocateStreamState::Ticket Pending(LocateStreamState& state,
                                  Actions* started = nullptr) {
  const LocateStreamState::Ticket ticket = state.PointRead();
  const Actions actions = state.LocateStarted();
  if (started != nullptr) *started = actions;
  return ticket;
}

Actions Answer(LocateStreamState& state, LocateStreamState::Ticket ticket,
               int64_t triangle) {
  v1::LocateResponse answer = AnswerFor(triangle);
  return state.Answered(ticket, grpc::Status::OK, &answer);
}

Actions Fail(LocateStreamState& state, LocateStreamState::Ticket ticket,
             const std::string& why) {
  v1::LocateResponse unused;
  return state.Answered(
      ticket, grpc::Status(grpc::StatusCode::INVALID_ARGUMENT, why), &unused);
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
  Actions bad = Located(
      state, grpc::Status(grpc::StatusCode::INVALID_ARGUMENT, "non-finite"), 0);
  EXPECT_FALSE(bad.read);
  EXPECT_FALSE(bad.finish);
  Actions written = state.WriteDone(true);
  ASSERT_TRUE(written.finish);
  EXPECT_EQ(*written.finish, End::kBadPoint);
  EXPECT_EQ(state.bad_point_status().error_code(),
            grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(state.bad_point_status().error_message(), "non-finite");
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

TEST(LocateStreamStateTest, ReadsWaitUntilTheLocateHasTheBufferNoMore) {
  LocateStreamState state;
  const LocateStreamState::Ticket ticket = state.PointRead();
  v1::LocateResponse answer = AnswerFor(5);
  Actions answered = state.Answered(ticket, grpc::Status::OK, &answer);
  ASSERT_NE(answered.write, nullptr);
  EXPECT_EQ(answered.write->triangle_id(), 5);
  EXPECT_FALSE(answered.read);  // the point is still in the read buffer
  EXPECT_TRUE(state.LocateStarted().read);
}

TEST(LocateStreamStateTest, AnswersThatComeOutOfOrderAreWrittenInOrder) {
  LocateStreamState state;
  Actions started;
  const auto first = Pending(state, &started);
  EXPECT_TRUE(started.read);  // reading goes on while the point is located
  EXPECT_EQ(started.write, nullptr);
  const auto second = Pending(state, &started);
  EXPECT_TRUE(started.read);
  EXPECT_EQ(state.queued_answers(), 2u);

  Actions later = Answer(state, second, 2);
  EXPECT_EQ(later.write, nullptr);  // the first point's answer comes first
  Actions earlier = Answer(state, first, 1);
  ASSERT_NE(earlier.write, nullptr);
  EXPECT_EQ(earlier.write->triangle_id(), 1);
  Actions written = state.WriteDone(true);
  ASSERT_NE(written.write, nullptr);
  EXPECT_EQ(written.write->triangle_id(), 2);
}

TEST(LocateStreamStateTest, PointsBeingLocatedCountAgainstTheQueue) {
  LocateStreamState state;
  Actions started;
  LocateStreamState::Ticket first = 0;
  for (size_t i = 0; i < LocateStreamState::kMaxQueuedAnswers; ++i) {
    const auto ticket = Pending(state, &started);
    if (i == 0) first = ticket;
  }
  EXPECT_FALSE(started.read);
  Actions answered = Answer(state, first, 7);
  ASSERT_NE(answered.write, nullptr);
  EXPECT_FALSE(answered.read);  // written, not yet out of the queue
  EXPECT_TRUE(state.WriteDone(true).read);
}

TEST(LocateStreamStateTest, AFailureWaitsForTheAnswersBeforeItAndStopsReads) {
  LocateStreamState state;
  const auto first = Pending(state);
  const auto second = Pending(state);
  EXPECT_FALSE(Fail(state, second, "second").finish);
  // The read outstanding completes: its point comes after the failure.
  Actions started;
  Pending(state, &started);
  EXPECT_FALSE(started.read);
  EXPECT_EQ(state.queued_answers(), 2u);

  Actions answered = Answer(state, first, 1);
  ASSERT_NE(answered.write, nullptr);
  EXPECT_FALSE(answered.finish);
  Actions written = state.WriteDone(true);
  EXPECT_EQ(written.write, nullptr);
  ASSERT_TRUE(written.finish);
  EXPECT_EQ(*written.finish, End::kBadPoint);
  EXPECT_EQ(state.bad_point_status().error_message(), "second");
}

TEST(LocateStreamStateTest, TheEarliestFailureEndsTheStream) {
  LocateStreamState state;
  const auto first = Pending(state);
  const auto second = Pending(state);
  EXPECT_FALSE(Fail(state, second, "second").finish);
  Actions failed = Fail(state, first, "first");
  ASSERT_TRUE(failed.finish);
  EXPECT_EQ(*failed.finish, End::kBadPoint);
  EXPECT_EQ(state.bad_point_status().error_message(), "first");
}

TEST(LocateStreamStateTest, AFailureAfterTheHalfCloseStillEndsTheStream) {
  LocateStreamState state;
  const auto ticket = Pending(state);
  EXPECT_FALSE(state.ReadFailed().finish);  // an answer is still to come
  Actions failed = Fail(state, ticket, "late");
  ASSERT_TRUE(failed.finish);
  EXPECT_EQ(*failed.finish, End::kBadPoint);
}

TEST(LocateStreamStateTest, TheDeadlineDropsPointsBeingLocated) {
  LocateStreamState state;
  const auto ticket = Pending(state);
  bool write_in_flight = true;
  Actions expired = state.DeadlinePassed(&write_in_flight);
  EXPECT_FALSE(write_in_flight);
  ASSERT_TRUE(expired.finish);
  EXPECT_EQ(*expired.finish, End::kDeadline);
  // The answer comes after the finish: nothing to do.
  Actions late = Answer(state, ticket, 1);
  EXPECT_EQ(late.write, nullptr);
  EXPECT_FALSE(late.finish);
  EXPECT_FALSE(late.read);
}

}  // namespace
}  // namespace locator
