// DrainGate: tickets until Close(), and WaitUntilIdle() tells when the last
// admitted call has ended (or the deadline passed).

#include "server/serving/drain_gate.h"

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <memory>
#include <thread>

#include "tests/testing/wait.h"

namespace locator {
namespace {

using Clock = std::chrono::system_clock;

Clock::time_point GenerousDeadline() {
  return Clock::now() + test::kGenerousWait;
}

TEST(DrainGateTest, AdmitsUntilClosed) {
  DrainGate gate;
  DrainGate::Ticket first = gate.Enter();
  EXPECT_NE(first, nullptr);
  EXPECT_NE(gate.Enter(), nullptr);
  gate.Close();
  EXPECT_EQ(gate.Enter(), nullptr);
  EXPECT_EQ(gate.Enter(), nullptr);
}

TEST(DrainGateTest, IdleWithoutTickets) {
  DrainGate gate;
  EXPECT_TRUE(gate.WaitUntilIdle(Clock::now()));
  { DrainGate::Ticket ended = gate.Enter(); }
  EXPECT_TRUE(gate.WaitUntilIdle(Clock::now()));
}

TEST(DrainGateTest, HeldTicketKeepsItBusyPastTheDeadline) {
  DrainGate gate;
  DrainGate::Ticket held = gate.Enter();
  gate.Close();
  EXPECT_FALSE(gate.WaitUntilIdle(Clock::now()));
  // Copies count as the same call.
  DrainGate::Ticket copy = held;
  held.reset();
  EXPECT_FALSE(gate.WaitUntilIdle(Clock::now()));
  copy.reset();
  EXPECT_TRUE(gate.WaitUntilIdle(Clock::now()));
}

TEST(DrainGateTest, RefusedEnterIsNotCounted) {
  DrainGate gate;
  gate.Close();
  DrainGate::Ticket refused = gate.Enter();
  EXPECT_EQ(refused, nullptr);
  EXPECT_TRUE(gate.WaitUntilIdle(Clock::now()));
}

TEST(DrainGateTest, WaitEndsWhenAnotherThreadReleasesTheLastTicket) {
  DrainGate gate;
  DrainGate::Ticket in_flight = gate.Enter();
  gate.Close();
  std::future<bool> idle = std::async(std::launch::async, [&gate] {
    return gate.WaitUntilIdle(GenerousDeadline());
  });
  // The waiter keeps waiting while the call runs...
  EXPECT_EQ(idle.wait_for(std::chrono::seconds(0)),
            std::future_status::timeout);
  // ...and returns true once it ends.
  std::thread([ticket = std::move(in_flight)]() mutable {
    ticket.reset();
  }).join();
  EXPECT_TRUE(idle.get());
}

TEST(DrainGateTest, TicketMayOutliveTheGate) {
  DrainGate::Ticket survivor;
  {
    DrainGate gate;
    survivor = gate.Enter();
  }
  // Releasing it must not touch the destroyed gate: the ASAN build fails
  // this test if it does.
  survivor.reset();
}

}  // namespace
}  // namespace locator
