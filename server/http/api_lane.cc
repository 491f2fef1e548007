#include "server/http/api_lane.h"

#include <utility>

namespace locator {

ApiLane::ApiLane(const std::string& name, size_t threads, size_t max_waiting,
                 prometheus::Family<prometheus::Gauge>& running,
                 prometheus::Family<prometheus::Gauge>& waiting)
    : name_(name),
      max_waiting_(max_waiting),
      running_(running.Add({{"lane", name}})),
      waiting_(waiting.Add({{"lane", name}})),
      threads_(threads) {}

void ApiLane::Submit(std::function<void(bool admitted)> call) {
  // Counted before it is queued, so that no two callers take the last place.
  size_t waiting = waiting_calls_.load();
  do {
    if (waiting >= max_waiting_) {
      call(false);
      return;
    }
  } while (!waiting_calls_.compare_exchange_weak(waiting, waiting + 1));
  waiting_.Increment();
  threads_.Submit([this, call = std::move(call)] {
    waiting_calls_.fetch_sub(1);
    waiting_.Decrement();
    running_.Increment();
    call(true);
    running_.Decrement();
  });
}

}  // namespace locator
