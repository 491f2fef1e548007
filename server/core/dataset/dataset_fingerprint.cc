#include "server/core/dataset/dataset_fingerprint.h"

#include <span>
#include <vector>

#include "server/core/geometry/xxh3_digest.h"

namespace locator {
namespace {

// Feeds a digest, each list preceded by its length so that moving an
// element from one list to the next changes the digest.
class Digest {
 public:
  template <class T>
  void Add(std::span<const T> values) {
    AddCount(values.size());
    digest_.Add(values.data(), values.size_bytes());
  }
  void Add(const std::vector<Polyline>& lines) {
    AddCount(lines.size());
    for (const Polyline& line : lines) {
      Add(std::span<const Point2>(line.points));
      Add(std::span<const double>(line.values));
    }
  }
  uint64_t value() const { return digest_.digest(); }

 private:
  void AddCount(uint64_t count) { digest_.Add(&count, sizeof(count)); }

  Xxh3Digest digest_;
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

uint64_t PointSetFingerprint::Finish() {
  // The five constraint lists of DatasetFingerprint, all empty.
  for (int list = 0; list < 5; ++list) Begin(0);
  return digest_.digest();
}

}  // namespace locator
