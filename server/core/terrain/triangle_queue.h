// TriangleQueue: the triangles of a TinMesh by their largest error, largest
// first, as greedy insertion pops them; a triangle rewritten by an
// insertion is removed by its index and pushed again with its new error.
//
// A binary heap of triangle indices with their errors beside them (so a
// comparison reads one array), and each triangle's position in it. Ties
// are broken by the heap's own (deterministic) order.
//
// Thread-safety: none.

#ifndef LOCATOR_CORE_TERRAIN_TRIANGLE_QUEUE_H_
#define LOCATOR_CORE_TERRAIN_TRIANGLE_QUEUE_H_

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "server/core/mesh/large_vector.h"

namespace locator {

class TriangleQueue {
 public:
  bool empty() const { return heap_.empty(); }
  size_t size() const { return heap_.size(); }
  // The triangle of largest error and that error. Precondition: !empty().
  uint32_t Top() const { return heap_[0]; }
  double TopError() const { return errors_[0]; }

  // Adds triangle t, which is not in the queue.
  void Push(uint32_t t, double error) {
    if (t >= position_.size()) position_.resize(t + 1, kAbsent);
    position_[t] = static_cast<uint32_t>(heap_.size());
    heap_.push_back(t);
    errors_.push_back(error);
    Up(heap_.size() - 1);
  }
  // Removes and returns the triangle of largest error.
  uint32_t Pop() {
    const uint32_t t = heap_[0];
    RemoveAt(0);
    return t;
  }
  // Queues triangle t with `error`, or moves it there if it is queued.
  void Set(uint32_t t, double error) {
    if (t >= position_.size() || position_[t] == kAbsent) {
      Push(t, error);
      return;
    }
    const size_t i = position_[t];
    errors_[i] = error;
    Up(i);
    Down(position_[t]);
  }
  // Removes triangle t if it is in the queue.
  void Remove(uint32_t t) {
    if (t < position_.size() && position_[t] != kAbsent) {
      RemoveAt(position_[t]);
    }
  }
  void Clear() {
    heap_.clear();
    errors_.clear();
    position_.clear();
  }
  size_t MemoryBytes() const {
    return heap_.capacity() * 4 + errors_.capacity() * 8 +
           position_.capacity() * 4;
  }

 private:
  static constexpr uint32_t kAbsent = 0xffffffffu;

  void Swap(size_t i, size_t j) {
    std::swap(heap_[i], heap_[j]);
    std::swap(errors_[i], errors_[j]);
    position_[heap_[i]] = static_cast<uint32_t>(i);
    position_[heap_[j]] = static_cast<uint32_t>(j);
  }
  void Up(size_t i) {
    while (i > 0) {
      const size_t parent = (i - 1) / 2;
      if (!(errors_[i] > errors_[parent])) return;
      Swap(i, parent);
      i = parent;
    }
  }
  void Down(size_t i) {
    const size_t n = heap_.size();
    for (;;) {
      size_t largest = i;
      const size_t left = 2 * i + 1;
      if (left < n && errors_[left] > errors_[largest]) largest = left;
      if (left + 1 < n && errors_[left + 1] > errors_[largest]) {
        largest = left + 1;
      }
      if (largest == i) return;
      Swap(i, largest);
      i = largest;
    }
  }
  void RemoveAt(size_t i) {
    const size_t last = heap_.size() - 1;
    position_[heap_[i]] = kAbsent;
    if (i != last) {
      heap_[i] = heap_[last];
      errors_[i] = errors_[last];
      position_[heap_[i]] = static_cast<uint32_t>(i);
    }
    heap_.resize(last);
    errors_.resize(last);
    if (i < heap_.size()) {
      Up(i);
      Down(i);
    }
  }

  LargeVector<uint32_t> heap_;
  LargeVector<double> errors_;
  LargeVector<uint32_t> position_;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_TRIANGLE_QUEUE_H_
