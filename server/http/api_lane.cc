#include "server/http/api_lane.h"

#include <utility>

namespace locator {

ApiLane::ApiLane(const std::string& name, size_t threads,
                 prometheus::Family<prometheus::Gauge>& running,
                 prometheus::Family<prometheus::Gauge>& waiting)
    : running_(running.Add({{"lane", name}})),
      waiting_(waiting.Add({{"lane", name}})),
      threads_(threads) {}

void ApiLane::Submit(std::function<void()> call) {
  waiting_.Increment();
  threads_.Submit([this, call = std::move(call)] {
    waiting_.Decrement();
    running_.Increment();
    call();
    running_.Decrement();
  });
}

}  // namespace locator
