#include "server/core/dataset/dataset_fingerprint.h"

#include <memory>
#include <span>
#include <vector>

#define XXH_INLINE_ALL
#include <xxhash.h>

namespace locator {
namespace {

// Feeds a digest, each list preceded by its length so that moving an
// element from one list to the next changes the digest.
class Digest {
 public:
  Digest() : state_(XXH3_createState()) { XXH3_64bits_reset(state_.get()); }

  template <class T>
  void Add(std::span<const T> values) {
    AddCount(values.size());
    XXH3_64bits_update(state_.get(), values.data(), values.size_bytes());
  }
  void Add(const std::vector<Polyline>& lines) {
    AddCount(lines.size());
    for (const Polyline& line : lines) {
      Add(std::span<const Point2>(line.points));
      Add(std::span<const double>(line.values));
    }
  }
  uint64_t value() const { return XXH3_64bits_digest(state_.get()); }

 private:
  void AddCount(uint64_t count) {
    XXH3_64bits_update(state_.get(), &count, sizeof(count));
  }

  struct Free {
    void operator()(XXH3_state_t* state) const { XXH3_freeState(state); }
  };
  std::unique_ptr<XXH3_state_t, Free> state_;
};

}  // namespace

uint64_t DatasetFingerprint(const Dataset& dataset) {
  Digest digest;
  digest.Add(std::span<const Point2>(dataset.points));
  digest.Add(std::span<const double>(dataset.values));
  const DatasetConstraints& c = dataset.constraints;
  digest.Add(c.breaklines);
  digest.Add(c.rings);
  digest.Add(c.segments);
  digest.Add(std::span<const Point2>(c.hole_seeds));
  digest.Add(std::span<const std::array<uint32_t, 3>>(c.triangles));
  return digest.value();
}

}  // namespace locator
