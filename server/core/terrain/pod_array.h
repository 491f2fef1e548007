// PodArray: a growable array of trivially copyable values for the big,
// ever-growing arrays of greedy insertion (a mesh of millions of
// triangles). It grows with realloc, which moves a large block by
// remapping its pages rather than copying them, so growing costs neither
// a copy nor a second first touch of every page, as std::vector's does.
//
// Thread-safety: none; a plain container.

#ifndef LOCATOR_CORE_TERRAIN_POD_ARRAY_H_
#define LOCATOR_CORE_TERRAIN_POD_ARRAY_H_

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <type_traits>
#include <utility>

namespace locator {

template <class T>
class PodArray {
  static_assert(std::is_trivially_copyable_v<T>);

 public:
  PodArray() = default;
  PodArray(PodArray&& o) noexcept
      : data_(std::exchange(o.data_, nullptr)),
        size_(std::exchange(o.size_, 0)),
        capacity_(std::exchange(o.capacity_, 0)) {}
  PodArray& operator=(PodArray&& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    std::swap(capacity_, o.capacity_);
    return *this;
  }
  PodArray(const PodArray&) = delete;
  PodArray& operator=(const PodArray&) = delete;
  ~PodArray() { std::free(data_); }

  size_t size() const { return size_; }
  size_t capacity() const { return capacity_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](size_t i) { return data_[i]; }
  const T& operator[](size_t i) const { return data_[i]; }
  T& back() { return data_[size_ - 1]; }

  void push_back(const T& value) {
    if (size_ == capacity_) Grow(size_ + 1);
    data_[size_++] = value;
  }
  // Grows to n elements, the new ones set to `value`, or shrinks to n.
  void resize(size_t n, const T& value = T()) {
    if (n > capacity_) Grow(n);
    std::fill(data_ + std::min(size_, n), data_ + n, value);
    size_ = n;
  }
  void clear() { size_ = 0; }
  void reserve(size_t n) {
    if (n > capacity_) Reallocate(n);
  }
  void shrink_to_fit() {
    if (size_ < capacity_) Reallocate(size_);
  }

 private:
  void Grow(size_t needed) {
    Reallocate(std::max({needed, 2 * capacity_, size_t{16}}));
  }
  void Reallocate(size_t capacity) {
    if (capacity == 0) {
      std::free(data_);
      data_ = nullptr;
      capacity_ = 0;
      return;
    }
    void* grown = std::realloc(data_, capacity * sizeof(T));
    if (grown == nullptr) throw std::bad_alloc();
    data_ = static_cast<T*>(grown);
    capacity_ = capacity;
  }

  T* data_ = nullptr;
  size_t size_ = 0;
  size_t capacity_ = 0;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_POD_ARRAY_H_
