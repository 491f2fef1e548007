#include "client/load/latency_histogram.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace locator {
namespace {

// Buckets below 2^kLinearBits hold one value each; above, every octave has
// 2^(kLinearBits - 1) buckets.
constexpr int kLinearBits = 7;
constexpr uint64_t kBucketsPerOctave = uint64_t{1} << (kLinearBits - 1);
constexpr int kOctaveBits = 37;
constexpr uint64_t kLargestMicros = (uint64_t{1} << kOctaveBits) - 1;
constexpr size_t kBucketCount =
    (kOctaveBits - kLinearBits + 2) * kBucketsPerOctave;

}  // namespace

LatencyHistogram::LatencyHistogram() : buckets_(kBucketCount, 0) {}

size_t LatencyHistogram::BucketOf(uint64_t micros) {
  micros = std::min(micros, kLargestMicros);
  // How far `micros` must shift right to fit the top linear octave.
  const int shift =
      std::max(0, static_cast<int>(std::bit_width(micros)) - kLinearBits);
  return shift * kBucketsPerOctave + (micros >> shift);
}

uint64_t LatencyHistogram::HighestValueIn(size_t bucket) {
  if (bucket < kBucketsPerOctave) return bucket;
  const int shift = static_cast<int>(bucket / kBucketsPerOctave) - 1;
  const uint64_t top_bits = bucket - shift * kBucketsPerOctave;
  return ((top_bits + 1) << shift) - 1;
}

void LatencyHistogram::Record(uint64_t micros) {
  ++buckets_[BucketOf(micros)];
  ++count_;
  min_ = std::min(min_, micros);
  max_ = std::max(max_, micros);
  sum_ += micros;
}

void LatencyHistogram::Merge(const LatencyHistogram& other) {
  for (size_t i = 0; i < kBucketCount; ++i) buckets_[i] += other.buckets_[i];
  count_ += other.count_;
  min_ = std::min(min_, other.min_);
  max_ = std::max(max_, other.max_);
  sum_ += other.sum_;
}

double LatencyHistogram::mean() const {
  return count_ == 0 ? 0.0 : static_cast<double>(sum_) / count_;
}

uint64_t LatencyHistogram::Percentile(double percent) const {
  if (count_ == 0) return 0;
  const uint64_t rank = std::clamp<uint64_t>(
      static_cast<uint64_t>(std::ceil(percent / 100.0 * count_)), 1, count_);
  uint64_t seen = 0;
  for (size_t bucket = 0; bucket < kBucketCount; ++bucket) {
    seen += buckets_[bucket];
    if (seen >= rank) return std::min(HighestValueIn(bucket), max_);
  }
  return max_;
}

}  // namespace locator
