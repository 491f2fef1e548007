// Clients that abuse a connection, for the bad-input table: each function
// plays one against a running locatord and returns the status the table
// row checks; the rest are test expectations.
//
// FloodWithUnreadStreams: a client that opens LocateStreams and writes to
// them without ever reading the answers, against a locatord started with
// --max-concurrent-streams kFloodStreams --default-deadline-ms 0.
//
// The server must hold it back, not buffer it: each stream stops being read
// once its answers wait unread, so flow control stalls the writers; the
// server's resident memory grows by less than kFloodRssBound; other clients
// (on their own connections) are served meanwhile; and one more stream on
// the flooded connection is not even started (the stream limit), so it ends
// DEADLINE_EXCEEDED after its 1 s deadline. That last status is returned;
// the rest are test expectations. The flood is cancelled before returning.
//
// Thread-safety: one call at a time per server.

#ifndef LOCATOR_TESTS_SERVER_ABUSIVE_CLIENTS_H_
#define LOCATOR_TESTS_SERVER_ABUSIVE_CLIENTS_H_

#include <grpcpp/grpcpp.h>

#include <chrono>
#include <cstddef>

#include "tests/testing/server_process.h"

namespace locator::test {

inline constexpr int kFloodStreams = 4;
// Measured: ~3 MB (~50 MB when gRPC may grow stream windows by BDP probing).
inline constexpr size_t kFloodRssBound = size_t{16} << 20;

grpc::Status FloodWithUnreadStreams(const test::ServerProcess& server);

// PingWhileIdle: a client that sends HTTP/2 keepalive pings as often as its
// gRPC allows (asked for every 100 ms; gRPC 1.51 sends about one a second)
// on a connection whose one stream is idle, for up to kPingDuration. A
// server enforcing its minimum ping interval with one strike allowed closes
// the connection after the third ping, ~3 s in (GOAWAY too_many_pings), and
// the stream ends UNAVAILABLE; one that allows the pings lets the stream
// live until its deadline (DEADLINE_EXCEEDED).
inline constexpr std::chrono::seconds kPingDuration{8};
grpc::Status PingWhileIdle(const test::ServerProcess& server);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_ABUSIVE_CLIENTS_H_
