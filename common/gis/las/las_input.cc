#include "common/gis/las/las_input.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace locator::gis::las {
namespace {

Status OutOfRange(const std::string& name, uint64_t offset, size_t length,
                  uint64_t size) {
  return Status::InvalidArgument(name + ": reading " + std::to_string(length) +
                                 " bytes at offset " + std::to_string(offset) +
                                 " runs past the end of the file (" +
                                 std::to_string(size) + " bytes)");
}

bool Inside(uint64_t offset, size_t length, uint64_t size) {
  return offset <= size && length <= size - offset;
}

class FileInput final : public LasInput {
 public:
  FileInput(int fd, uint64_t size, std::string name)
      : fd_(fd), size_(size), name_(std::move(name)) {}
  ~FileInput() override { ::close(fd_); }

  uint64_t size() const override { return size_; }
  const std::string& name() const override { return name_; }

  Status ReadAt(uint64_t offset, size_t length, void* out) override {
    if (!Inside(offset, length, size_)) {
      return OutOfRange(name_, offset, length, size_);
    }
    auto* bytes = static_cast<char*>(out);
    while (length > 0) {
      const ssize_t got =
          ::pread(fd_, bytes, length, static_cast<off_t>(offset));
      if (got < 0 && errno == EINTR) continue;
      if (got <= 0) {
        return Status::IOError(name_ + ": cannot read at offset " +
                               std::to_string(offset) + ": " +
                               (got == 0 ? "the file shrank while it was read"
                                         : std::strerror(errno)));
      }
      bytes += got;
      offset += static_cast<uint64_t>(got);
      length -= static_cast<size_t>(got);
    }
    return Status::OK();
  }

 private:
  const int fd_;
  const uint64_t size_;
  const std::string name_;
};

class MemoryInput final : public LasInput {
 public:
  MemoryInput(std::string_view bytes, std::string name)
      : bytes_(bytes), name_(std::move(name)) {}

  uint64_t size() const override { return bytes_.size(); }
  const std::string& name() const override { return name_; }

  Status ReadAt(uint64_t offset, size_t length, void* out) override {
    if (!Inside(offset, length, bytes_.size())) {
      return OutOfRange(name_, offset, length, bytes_.size());
    }
    // memcpy's pointers must not be null, even for no bytes.
    if (length > 0) std::memcpy(out, bytes_.data() + offset, length);
    return Status::OK();
  }

 private:
  const std::string_view bytes_;
  const std::string name_;
};

}  // namespace

StatusOr<std::unique_ptr<LasInput>> OpenLasFile(const std::string& path) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; it has no effect
  // on the regular file this must be.
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  if (fd < 0) {
    const int error = errno;
    const std::string message = path + ": " + std::strerror(error);
    return error == ENOENT ? Status::NotFound(message)
                           : Status::IOError("cannot open " + message);
  }
  struct stat info;
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    ::close(fd);
    return Status::IOError("cannot open " + path + ": not a regular file");
  }
  return std::make_unique<FileInput>(fd, static_cast<uint64_t>(info.st_size),
                                     path);
}

std::unique_ptr<LasInput> LasMemoryInput(std::string_view bytes,
                                         std::string name) {
  return std::make_unique<MemoryInput>(bytes, std::move(name));
}

}  // namespace locator::gis::las
