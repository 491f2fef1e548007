// ApiLane: one lane of the HTTP/JSON API's calls: a fixed number of threads
// that run the lane's calls in arrival order, and two gauges on /metrics,
//
//   locator_http_calls_running{lane="NAME"}  calls a thread is running
//   locator_http_calls_waiting{lane="NAME"}  calls queued for a thread
//
// The API keeps cheap calls and expensive ones in separate lanes (see
// JsonApi), so that a cheap call never queues behind an expensive one, and
// at most `threads` expensive calls run at once.
//
// Owns its threads (a WorkerPool) and its two series of the families it is
// given. Thread-safety: Submit() may be called from any thread.

#ifndef LOCATOR_SERVER_HTTP_API_LANE_H_
#define LOCATOR_SERVER_HTTP_API_LANE_H_

#include <prometheus/family.h>
#include <prometheus/gauge.h>

#include <cstddef>
#include <functional>
#include <string>

#include "server/worker_pool.h"

namespace locator {

class ApiLane {
 public:
  // `running` and `waiting` are the two families above; they must outlive
  // the lane.
  ApiLane(const std::string& name, size_t threads,
          prometheus::Family<prometheus::Gauge>& running,
          prometheus::Family<prometheus::Gauge>& waiting);

  ApiLane(const ApiLane&) = delete;
  ApiLane& operator=(const ApiLane&) = delete;

  // Queues `call` to run on one of the lane's threads.
  void Submit(std::function<void()> call);

 private:
  prometheus::Gauge& running_;
  prometheus::Gauge& waiting_;
  WorkerPool threads_;  // last: stopped first
};

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_API_LANE_H_
