// Whole-file reads and crash-safe whole-file writes, with errors as values
// that name the file.
//
// Thread-safety: free functions. Concurrent WriteFileAtomically() calls for
// the same path are safe: each writes its own temporary file, and the last
// rename wins whole.

#ifndef LOCATOR_CORE_FILE_IO_H_
#define LOCATOR_CORE_FILE_IO_H_

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "locator/status.h"

namespace locator {

// Reads the regular file at `path` into *contents. `what` names the file's
// role in messages ("cannot open dataset 'x': ..."). NotFound if it does not
// exist; ResourceExhausted if it is larger than `max_bytes`; IOError
// otherwise.
Status ReadWholeFile(const std::string& path, std::string_view what,
                     std::string* contents,
                     size_t max_bytes = std::numeric_limits<size_t>::max());

// Replaces the file at `path` with `bytes` so that a crash at any moment
// leaves either the old file or the new one, never a mix: writes a temporary
// file in the same directory, fsyncs it, renames it over `path` and fsyncs
// the directory. The temporary file is removed on failure. IOError naming
// the step that failed.
Status WriteFileAtomically(const std::string& path, std::string_view bytes);
// As above, the file being `pieces` one after another (large files written
// without first concatenating them in memory).
Status WriteFileAtomically(const std::string& path,
                           std::span<const std::string_view> pieces);

// As above, the file's bytes being what `fill` appends, in order, through
// the function it is given (which fails with IOError if a write does):
// files written from other files without holding them. A failure of
// `fill` is returned as it is.
using FileAppender = std::function<Status(std::string_view bytes)>;
using FileFiller = std::function<Status(const FileAppender& append)>;
Status WriteFileAtomically(const std::string& path, const FileFiller& fill);

// "DIR/PREFIX<digest as 16 hex digits>SUFFIX": the file in `dir` named by a
// 64-bit digest (just the name for an empty `dir`; one '/' when `dir` ends
// in one).
std::string DigestNamedPath(const std::string& dir, std::string_view prefix,
                            uint64_t digest, std::string_view suffix);

// A regular file mapped read-only and shared (MAP_SHARED: processes mapping
// the same file share its pages). Unmapped when destroyed. Move-only.
class MappedFile {
 public:
  MappedFile() = default;
  ~MappedFile();
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;

  // How a mapping's pages come in.
  enum class Pages {
    kAtOnce,    // read in at once (MAP_POPULATE): the file is read anyway
    kOnDemand,  // as they are touched: files larger than RAM
  };

  // Maps `path`. `what` names the file in messages. NotFound if it does not
  // exist; IOError otherwise (not a regular file, empty, mmap failed).
  static Status Open(const std::string& path, std::string_view what,
                     MappedFile* out, Pages pages = Pages::kAtOnce);

  std::string_view bytes() const {
    return {static_cast<const char*>(data_), size_};
  }

 private:
  void* data_ = nullptr;
  size_t size_ = 0;
};

}  // namespace locator

#endif  // LOCATOR_CORE_FILE_IO_H_
