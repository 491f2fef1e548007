// Plain binary files for the out-of-core build's working data: an append-
// only writer with its own buffer, and a reader of byte ranges at offsets
// (pread, so that threads may share one). Errors name the file.
//
// Thread-safety: an AppendFile on one thread at a time; a RandomAccessFile
// from any thread.

#ifndef LOCATOR_CORE_TILESET_BINARY_FILES_H_
#define LOCATOR_CORE_TILESET_BINARY_FILES_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "locator/status.h"

namespace locator {

class AppendFile {
 public:
  AppendFile() = default;
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  // Creates (or truncates) `path`, buffering `buffer_bytes` before each
  // write. IOError if it cannot be created.
  [[nodiscard]] Status Create(const std::string& path, size_t buffer_bytes);
  // Appends the bytes of `items`. IOError if a write fails.
  template <class T>
  [[nodiscard]] Status Append(std::span<const T> items) {
    return AppendBytes(items.data(), items.size_bytes());
  }
  [[nodiscard]] Status AppendBytes(const void* data, size_t size);
  // Writes what is buffered and closes the file. IOError if that fails.
  [[nodiscard]] Status Close();

 private:
  Status Flush();

  std::string path_;
  int fd_ = -1;
  std::vector<char> buffer_;
  size_t used_ = 0;
};

class RandomAccessFile {
 public:
  RandomAccessFile() = default;
  ~RandomAccessFile();
  RandomAccessFile(const RandomAccessFile&) = delete;
  RandomAccessFile& operator=(const RandomAccessFile&) = delete;

  // Opens `path` for reading. NotFound if it does not exist, IOError
  // otherwise.
  [[nodiscard]] Status Open(const std::string& path);
  uint64_t size() const { return size_; }
  // Reads exactly `size` bytes at `offset` into `out`. IOError if the
  // file is shorter or the read fails.
  [[nodiscard]] Status ReadAt(uint64_t offset, void* out, size_t size) const;
  // Reads items [first, first + out.size()) of an array of T at the start
  // of the file.
  template <class T>
  [[nodiscard]] Status ReadItems(uint64_t first, std::span<T> out) const {
    return ReadAt(first * sizeof(T), out.data(), out.size_bytes());
  }

 private:
  std::string path_;
  int fd_ = -1;
  uint64_t size_ = 0;
};

}  // namespace locator

#endif  // LOCATOR_CORE_TILESET_BINARY_FILES_H_
