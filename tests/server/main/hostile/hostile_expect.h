// What a hostile call may answer, and how an answer is judged against it.
//
// An Expectation starts as "OK only". Each hostile field of a request adds
// what it allows: Allow() another outcome (a huge but finite coordinate may
// be answered or refused), Require() a refusal (a NaN coordinate must be).
// A refusal is a gRPC code and the words its message may use to name the
// field (any one of them, compared case-insensitively). Every error message
// must also be non-empty, at most kMaxMessageBytes long (the cut the server
// applies to every status message) and free of numbers
// with more than kMaxDigitRun digits: a message that echoes a 1 MiB
// request field, or prints a 300-digit number, is itself a defect.
//
// Thread-safety: plain values.

#ifndef LOCATOR_TESTS_SERVER_HOSTILE_EXPECT_H_
#define LOCATOR_TESTS_SERVER_HOSTILE_EXPECT_H_

#include <grpcpp/support/status.h>

#include <cstddef>
#include <string>
#include <vector>

namespace locator::test {

inline constexpr size_t kMaxMessageBytes = 1024;
// Most digits a number a message prints may have before its decimal
// point: numbers are printed readably, never as the 300 digits of a tiny
// cell size's quotient. (A short prefix of the request quoted back may
// hold more digits in a row; no digit follows the "..." that ends it.)
inline constexpr size_t kMaxDigitRun = 40;

// How a call reaches the server.
enum class Transport { kGrpc, kHttp };
inline const char* TransportName(Transport t) {
  return t == Transport::kGrpc ? "gRPC" : "HTTP";
}

// How a call ended, whatever its transport.
struct Outcome {
  grpc::StatusCode code = grpc::StatusCode::OK;
  std::string message;
  // The HTTP status of the reply; 0 over gRPC.
  unsigned http_status = 0;
  // Non-empty when the transport itself misbehaved (an HTTP status that is
  // not the code's, a reply that is not an ApiError, a dropped connection).
  std::string transport_problem;
};

// How a gRPC call ended.
inline Outcome FromGrpc(const grpc::Status& status) {
  Outcome outcome;
  outcome.code = status.error_code();
  outcome.message = status.error_message();
  return outcome;
}

// Whether the call was still running when its deadline (or the HTTP
// client's timeout) passed: the server may still hold a thread for it.
inline bool OutlivedDeadline(const Outcome& outcome) {
  return outcome.code == grpc::StatusCode::DEADLINE_EXCEEDED ||
         outcome.transport_problem.find("timeout") != std::string::npos;
}

class Expectation {
 public:
  // The call may fail with `code`, its message naming one of `names`.
  Expectation& Allow(grpc::StatusCode code, std::vector<std::string> names);
  // The call must fail; with `code` naming one of `names`, or with another
  // refusal Allow()ed or Require()d.
  Expectation& Require(grpc::StatusCode code, std::vector<std::string> names);

  // Over HTTP, a reply with `status` is also accepted, whatever its body:
  // what the HTTP server answers before any API call (413, 414, 431).
  Expectation& AllowHttpStatus(unsigned status);

  bool ok_allowed() const { return ok_allowed_; }
  // Whether `code` (not OK) is one of the refusals accepted.
  bool Accepts(grpc::StatusCode code) const;
  // "" when `outcome` is acceptable, otherwise what is wrong with it.
  std::string Judge(const Outcome& outcome) const;
  // "OK, or INVALID_ARGUMENT naming point|crs, or ...".
  std::string Describe() const;

 private:
  struct Refusal {
    grpc::StatusCode code;
    std::vector<std::string> names;
  };

  bool ok_allowed_ = true;
  std::vector<Refusal> refusals_;
  std::vector<unsigned> http_statuses_;
};

// The name of `code` ("INVALID_ARGUMENT"), as a string.
std::string CodeName(grpc::StatusCode code);
// `text` cut to its first `limit` bytes, marked when cut, with control
// and non-ASCII bytes escaped (\xNN), for a failure message.
std::string Shorten(const std::string& text, size_t limit = 300);
// Whether `text` contains `word`, case-insensitively.
bool Names(const std::string& text, const std::string& word);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HOSTILE_EXPECT_H_
