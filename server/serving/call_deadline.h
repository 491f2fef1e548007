// CallDeadline: the deadline the server holds a call to. It is the client's
// deadline; a call whose client set none gets the server's default
// (--default-deadline-ms) from when its handler started, so that no call
// can hold a server thread or stream forever.
//
// Thread-safety: a plain value.

#ifndef LOCATOR_SERVER_CALL_DEADLINE_H_
#define LOCATOR_SERVER_CALL_DEADLINE_H_

#include <chrono>
#include <string_view>

#include "locator/status.h"

namespace locator {

struct CallDeadline {
  // time_point::max() when neither the client nor the server set one.
  std::chrono::system_clock::time_point when;
  // Nonzero when `when` is the server's default, not the client's deadline.
  std::chrono::milliseconds server_default{0};

  // The deadline of a call whose client set none: `server_default` from now
  // (zero: none).
  static CallDeadline ServerDefault(std::chrono::milliseconds server_default);

  bool Passed() const { return std::chrono::system_clock::now() >= when; }
  // Whether a deadline the client did not set has to be enforced by the
  // server (gRPC enforces the client's).
  bool ServerEnforced() const { return server_default.count() > 0; }

  // DEADLINE_EXCEEDED "deadline passed while <doing>", saying when it was
  // the server's default.
  Status ExceededStatus(std::string_view doing) const;
};

}  // namespace locator

#endif  // LOCATOR_SERVER_CALL_DEADLINE_H_
