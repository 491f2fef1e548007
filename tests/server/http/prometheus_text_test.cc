// The test-side Prometheus reader must reject what Prometheus would, or the
// /metrics tests could not fail.

#include "tests/server/http/prometheus_text.h"

#include <gtest/gtest.h>

#include <cmath>

namespace locator::test {
namespace {

TEST(PrometheusTextTest, ReadsFamiliesAndSamples) {
  PrometheusText text;
  const Status s = ParsePrometheusText(
      "# HELP a_total Things.\n# TYPE a_total counter\n"
      "a_total{code=\"OK\",m=\"x\\\"y\"} 3\na_total{code=\"NO\"} 1e3\n"
      "# TYPE h histogram\nh_bucket{le=\"1\"} 2\nh_bucket{le=\"+Inf\"} 4\n"
      "h_sum 7.5\nh_count 4\n# TYPE g gauge\ng NaN\ng{x=\"\"} +Inf 123\n",
      &text);
  ASSERT_TRUE(s.ok()) << s.ToString();
  EXPECT_EQ(text.types.at("h"), "histogram");
  EXPECT_EQ(text.Value("a_total", {{"code", "OK"}}), 3);
  EXPECT_EQ(text.Value("a_total", {{"m", "x\"y"}}), 3);
  EXPECT_EQ(text.Value("a_total", {{"code", "NO"}}), 1000);
  EXPECT_EQ(text.Value("a_total"), std::nullopt);  // two match
  EXPECT_EQ(text.Value("h_bucket", {{"le", "+Inf"}}), 4);
  EXPECT_TRUE(std::isinf(*text.Value("g", {{"x", ""}})));
}

TEST(PrometheusTextTest, RejectsMalformedText) {
  const char* bad[] = {
      "a 1\n",                                      // no TYPE
      "# TYPE a counter\na 1",                      // no final newline
      "# TYPE a counter\na{b=\"c} 1\n",             // unterminated value
      "# TYPE a counter\na{b=c} 1\n",               // unquoted value
      "# TYPE a counter\na{b=\"c\",} 1\n",          // trailing comma
      "# TYPE a counter\na{b=\"c\",b=\"d\"} 1\n",   // repeated label
      "# TYPE a counter\na 1.2.3\n",                // bad value
      "# TYPE a counter\na inf\n",                  // Inf is spelled +Inf
      "# TYPE a counter\na\n",                      // no value
      "# TYPE a counter\n1a 1\n",                   // bad name
      "# TYPE a counter\n# TYPE a gauge\n",         // TYPE twice
      "# TYPE a counter\na 1\n# TYPE a counter\n",  // TYPE after samples
      "# TYPE a meter\n",                           // unknown type
      "# TYPE h histogram\nh_bucket 1\n",           // bucket without le
      "# TYPE a counter\na{b=\"\\x\"} 1\n",         // bad escape
  };
  for (const char* text : bad) {
    PrometheusText parsed;
    EXPECT_FALSE(ParsePrometheusText(text, &parsed).ok()) << text;
  }
}

}  // namespace
}  // namespace locator::test
