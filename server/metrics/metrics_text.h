// The Prometheus text exposition (format 0.0.4) of a set of collectables.
//
// Thread-safety: as safe as the collectables' Collect().

#ifndef LOCATOR_SERVER_METRICS_METRICS_TEXT_H_
#define LOCATOR_SERVER_METRICS_METRICS_TEXT_H_

#include <prometheus/collectable.h>

#include <memory>
#include <string>
#include <vector>

namespace locator {

// The Content-Type of MetricsText()'s answer to GET /metrics.
inline constexpr char kMetricsContentType[] =
    "text/plain; version=0.0.4; charset=utf-8";

// Collects every collectable, in order, and serializes all their families.
std::string MetricsText(
    const std::vector<std::shared_ptr<prometheus::Collectable>>& collectables);

}  // namespace locator

#endif  // LOCATOR_SERVER_METRICS_METRICS_TEXT_H_
