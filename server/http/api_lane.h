// ApiLane: one lane of the HTTP/JSON API's calls: a fixed number of threads
// that run the lane's calls in arrival order, at most `max_waiting` calls
// queued for them, and two gauges on /metrics,
//
//   locator_http_calls_running{lane="NAME"}  calls a thread is running
//   locator_http_calls_waiting{lane="NAME"}  calls queued for a thread
//
// The API keeps cheap calls and expensive ones in separate lanes (see
// JsonApi), so that a cheap call never queues behind an expensive one, and
// at most `threads` expensive calls run at once. A call that finds
// `max_waiting` calls queued is refused at once instead of queued: each
// queued call holds its request body and its connection, and one that
// waits behind many long ones would mostly wait out its deadline.
//
// Owns its threads (a WorkerPool) and its two series of the families it is
// given. Thread-safety: Submit() may be called from any thread.
// Invariant: waiting_calls_ <= max_waiting_ (a call is counted from its
// Submit() until a thread starts it).

#ifndef LOCATOR_SERVER_HTTP_API_LANE_H_
#define LOCATOR_SERVER_HTTP_API_LANE_H_

#include <prometheus/family.h>
#include <prometheus/gauge.h>

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>

#include "server/serving/worker_pool.h"

namespace locator {

class ApiLane {
 public:
  // `running` and `waiting` are the two families above; they must outlive
  // the lane. `max_waiting` >= 1.
  ApiLane(const std::string& name, size_t threads, size_t max_waiting,
          prometheus::Family<prometheus::Gauge>& running,
          prometheus::Family<prometheus::Gauge>& waiting);

  ApiLane(const ApiLane&) = delete;
  ApiLane& operator=(const ApiLane&) = delete;

  // Runs `call(true)` on one of the lane's threads, after the calls queued
  // before it; or, when max_waiting() calls are queued already, runs
  // `call(false)` at once on the calling thread, so that the call can
  // answer its refusal.
  void Submit(std::function<void(bool admitted)> call);

  const std::string& name() const { return name_; }
  size_t max_waiting() const { return max_waiting_; }

 private:
  const std::string name_;
  const size_t max_waiting_;
  std::atomic<size_t> waiting_calls_{0};
  prometheus::Gauge& running_;
  prometheus::Gauge& waiting_;
  WorkerPool threads_;  // last: stopped first
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_API_LANE_H_
