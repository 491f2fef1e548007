// A strict reader of the Prometheus text exposition format 0.0.4, for tests
// that check /metrics: every line is "# HELP name text", "# TYPE name type"
// or a sample "name{label="value",...} value [timestamp]"; names and label
// names are well-formed, label values correctly escaped, values numbers
// (or +Inf, -Inf, NaN); a family's TYPE comes before its samples, at most
// once; every sample belongs to a declared family (a histogram's also as
// name_bucket, name_sum, name_count).
//
// Thread-safety: plain data.

#ifndef LOCATOR_TESTS_SERVER_HTTP_PROMETHEUS_TEXT_H_
#define LOCATOR_TESTS_SERVER_HTTP_PROMETHEUS_TEXT_H_

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "locator/status.h"

namespace locator::test {

struct PrometheusSample {
  std::string name;
  std::map<std::string, std::string> labels;
  double value = 0;
};

struct PrometheusText {
  std::map<std::string, std::string> types;  // family name -> type
  std::vector<PrometheusSample> samples;

  // The value of the one sample named `name` whose labels include every
  // one of `labels`; nullopt if there is none (or more than one).
  std::optional<double> Value(
      std::string_view name,
      const std::map<std::string, std::string>& labels = {}) const;
};

// Parses `text`; InvalidArgument naming the first bad line otherwise.
Status ParsePrometheusText(std::string_view text, PrometheusText* out);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HTTP_PROMETHEUS_TEXT_H_
