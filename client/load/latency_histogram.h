// LatencyHistogram: an HDR-style log-linear histogram of latencies in
// microseconds.
//
// Values below 128 us are counted exactly. Above, each power-of-two range
// [2^k, 2^(k+1)) is split into 64 equal buckets, so a reported percentile is
// at most 1/64 (1.6%) above the true value and never below it. Values past
// about 38 hours (2^37 us) are counted in the last bucket. Histograms with
// different contents merge exactly, so per-interval histograms can be added
// into a run total.
//
// Owns its bucket counts (~16 KiB). Thread-safety: not thread-safe; callers
// lock or keep one per thread and Merge().

#ifndef LOCATOR_CLIENT_LOAD_LATENCY_HISTOGRAM_H_
#define LOCATOR_CLIENT_LOAD_LATENCY_HISTOGRAM_H_

#include <cstddef>
#include <cstdint>
#include <vector>

namespace locator {

class LatencyHistogram {
 public:
  LatencyHistogram();

  // Counts one latency of `micros` microseconds.
  void Record(uint64_t micros);
  // Adds every count of `other` to this one.
  void Merge(const LatencyHistogram& other);

  uint64_t count() const { return count_; }
  // Exact minimum, maximum and mean of the recorded values (0 when empty).
  uint64_t min() const { return count_ == 0 ? 0 : min_; }
  uint64_t max() const { return max_; }
  double mean() const;
  // The value at or below which `percent` (0..100] of the recorded values
  // lie: the highest value of that bucket, capped at max(). 0 when empty.
  uint64_t Percentile(double percent) const;

 private:
  static size_t BucketOf(uint64_t micros);
  static uint64_t HighestValueIn(size_t bucket);

  std::vector<uint64_t> buckets_;
  uint64_t count_ = 0;
  uint64_t min_ = UINT64_MAX;
  uint64_t max_ = 0;
  uint64_t sum_ = 0;
};

}  // namespace locator

#endif  // LOCATOR_CLIENT_LOAD_LATENCY_HISTOGRAM_H_
