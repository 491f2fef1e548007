// LasInput: the bytes of a LAS file, read at any offset, so that the reader
// streams a file of any size in chunks (pread) and the fuzzer feeds it
// memory through the same code.
//
// Thread-safety: an input is used by one thread at a time.

#ifndef LOCATOR_COMMON_GIS_LAS_LAS_INPUT_H_
#define LOCATOR_COMMON_GIS_LAS_LAS_INPUT_H_

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis::las {

class LasInput {
 public:
  virtual ~LasInput() = default;

  // The input's length in bytes.
  virtual uint64_t size() const = 0;
  // Reads `length` bytes at `offset` into `out`. InvalidArgument when they
  // are not all inside the input; IOError when reading fails.
  virtual Status ReadAt(uint64_t offset, size_t length, void* out) = 0;
  // The input's name in messages (the file's path).
  virtual const std::string& name() const = 0;
};

// The regular file at `path`, opened for reading. NotFound if it does not
// exist; IOError if it cannot be opened or is not a regular file.
StatusOr<std::unique_ptr<LasInput>> OpenLasFile(const std::string& path);

// `bytes` (which must outlive the input) named `name`.
std::unique_ptr<LasInput> LasMemoryInput(std::string_view bytes,
                                         std::string name);

}  // namespace locator::gis::las

#endif  // LOCATOR_COMMON_GIS_LAS_LAS_INPUT_H_
