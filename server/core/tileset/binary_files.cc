#include "server/core/tileset/binary_files.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace locator {
namespace {

Status FileError(const std::string& what, const std::string& path) {
  return Status::IOError(what + " '" + path + "': " + std::strerror(errno));
}

}  // namespace

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

Status AppendFile::Create(const std::string& path, size_t buffer_bytes) {
  path_ = path;
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) return FileError("cannot create", path);
  buffer_.resize(buffer_bytes > 0 ? buffer_bytes : 1);
  used_ = 0;
  return Status::OK();
}

Status AppendFile::AppendBytes(const void* data, size_t size) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    if (used_ == buffer_.size()) {
      Status flushed = Flush();
      if (!flushed.ok()) return flushed;
    }
    const size_t take = std::min(size, buffer_.size() - used_);
    std::memcpy(buffer_.data() + used_, bytes, take);
    used_ += take;
    bytes += take;
    size -= take;
  }
  return Status::OK();
}

Status AppendFile::Flush() {
  size_t done = 0;
  while (done < used_) {
    const ssize_t wrote = ::write(fd_, buffer_.data() + done, used_ - done);
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote <= 0) return FileError("cannot write", path_);
    done += static_cast<size_t>(wrote);
  }
  used_ = 0;
  return Status::OK();
}

Status AppendFile::Close() {
  Status flushed = Flush();
  const int closed = ::close(fd_);
  fd_ = -1;
  if (!flushed.ok()) return flushed;
  if (closed != 0) return FileError("cannot close", path_);
  return Status::OK();
}

RandomAccessFile::~RandomAccessFile() {
  if (fd_ >= 0) ::close(fd_);
}

Status RandomAccessFile::Open(const std::string& path) {
  path_ = path;
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) {
    return errno == ENOENT ? Status::NotFound("no file '" + path + "'")
                           : FileError("cannot open", path);
  }
  struct stat st;
  if (::fstat(fd_, &st) != 0) return FileError("cannot stat", path);
  size_ = static_cast<uint64_t>(st.st_size);
  return Status::OK();
}

Status RandomAccessFile::ReadAt(uint64_t offset, void* out, size_t size) const {
  char* bytes = static_cast<char*>(out);
  while (size > 0) {
    const ssize_t got = ::pread(fd_, bytes, size, static_cast<off_t>(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) return FileError("cannot read", path_);
    if (got == 0) {
      return Status::IOError("'" + path_ + "' ends before byte " +
                             std::to_string(offset + size));
    }
    bytes += got;
    offset += static_cast<uint64_t>(got);
    size -= static_cast<size_t>(got);
  }
  return Status::OK();
}

}  // namespace locator
