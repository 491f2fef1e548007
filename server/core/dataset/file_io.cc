#include "server/core/dataset/file_io.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <system_error>
#include <utility>

#include "common/status_macros.h"
#include "server/core/dataset/dataset_text.h"

namespace locator {
namespace {

using dataset_text::Quoted;

std::string ErrorText(int err) { return std::generic_category().message(err); }

// Closes the descriptor when the scope ends.
struct FdCloser {
  int fd;
  ~FdCloser() {
    if (fd >= 0) ::close(fd);
  }
};

Status WriteAll(int fd, std::string_view bytes) {
  // write() may write less than asked (signals, full pipes), hence the loop.
  while (!bytes.empty()) {
    const ssize_t wrote = ::write(fd, bytes.data(), bytes.size());
    if (wrote < 0 && errno == EINTR) continue;
    if (wrote < 0) return Status::IOError(ErrorText(errno));
    bytes.remove_prefix(static_cast<size_t>(wrote));
  }
  return Status::OK();
}

std::string DirectoryOf(const std::string& path) {
  const size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

// A name no other writer uses at the same time: this process's id and a
// per-process counter.
std::string TemporaryNameFor(const std::string& path) {
  static std::atomic<uint64_t> counter{0};
  return path + ".tmp." + std::to_string(::getpid()) + "." +
         std::to_string(counter.fetch_add(1));
}

Status WriteAndSync(const std::string& path, const FileFiller& fill) {
  const int fd =
      ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    return Status::IOError("cannot create " + Quoted(path) + ": " +
                           ErrorText(errno));
  }
  FdCloser closer{fd};
  RETURN_IF_ERROR(fill([&](std::string_view bytes) {
    const Status status = WriteAll(fd, bytes);
    if (status.ok()) return status;
    return Status::IOError("cannot write " + Quoted(path) + ": " +
                           status.message());
  }));
  if (::fsync(fd) != 0) {
    return Status::IOError("cannot fsync " + Quoted(path) + ": " +
                           ErrorText(errno));
  }
  closer.fd = -1;
  if (::close(fd) != 0) {
    return Status::IOError("cannot close " + Quoted(path) + ": " +
                           ErrorText(errno));
  }
  return Status::OK();
}

// A regular file open for reading.
struct OpenedFile {
  std::string name;  // its role and path, for messages
  FdCloser closer{-1};
  uint64_t size = 0;
};

// Opens the regular file at `path` for reading. `what` names its role in
// messages: NotFound if it does not exist, IOError otherwise.
Status OpenRegularFile(const std::string& path, std::string_view what,
                       OpenedFile* file) {
  file->name = std::string(what) + " " + Quoted(path);
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int err = errno;
    const std::string msg = "cannot open " + file->name + ": " + ErrorText(err);
    return err == ENOENT ? Status::NotFound(msg) : Status::IOError(msg);
  }
  file->closer.fd = fd;
  struct stat st;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    return Status::IOError(file->name + " is not a readable regular file");
  }
  file->size = static_cast<uint64_t>(st.st_size);
  return Status::OK();
}

}  // namespace

Status ReadWholeFile(const std::string& path, std::string_view what,
                     std::string* contents, size_t max_bytes) {
  OpenedFile file;
  RETURN_IF_ERROR(OpenRegularFile(path, what, &file));
  const std::string& name = file.name;
  const int fd = file.closer.fd;
  const uint64_t file_size = file.size;
  if (file_size > max_bytes) {
    return Status::ResourceExhausted(
        name + " has " + std::to_string(file_size) + " bytes, more than " +
        std::to_string(max_bytes));
  }
  contents->resize(static_cast<size_t>(file_size));
  size_t done = 0;
  // read() may return less than asked (large files, signals), hence the loop.
  while (done < contents->size()) {
    const ssize_t got =
        ::read(fd, contents->data() + done, contents->size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) {
      return Status::IOError("cannot read " + name + ": " + ErrorText(errno));
    }
    if (got == 0) break;  // the file shrank since fstat
    done += static_cast<size_t>(got);
  }
  contents->resize(done);
  return Status::OK();
}

Status WriteFileAtomically(const std::string& path, std::string_view bytes) {
  return WriteFileAtomically(path, std::span(&bytes, 1));
}

Status WriteFileAtomically(const std::string& path,
                           std::span<const std::string_view> pieces) {
  return WriteFileAtomically(path, [pieces](const FileAppender& append) {
    for (const std::string_view bytes : pieces) RETURN_IF_ERROR(append(bytes));
    return Status::OK();
  });
}

Status WriteFileAtomically(const std::string& path, const FileFiller& fill) {
  const std::string temporary = TemporaryNameFor(path);
  Status status = WriteAndSync(temporary, fill);
  if (status.ok() && ::rename(temporary.c_str(), path.c_str()) != 0) {
    status = Status::IOError("cannot rename " + Quoted(temporary) + " to " +
                             Quoted(path) + ": " + ErrorText(errno));
  }
  if (!status.ok()) {
    ::unlink(temporary.c_str());
    return status;
  }
  // The rename is durable only once the directory entry is on disk.
  const std::string directory = DirectoryOf(path);
  const int dir_fd =
      ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd < 0) {
    return Status::IOError("cannot open directory " + Quoted(directory) + ": " +
                           ErrorText(errno));
  }
  FdCloser dir_closer{dir_fd};
  if (::fsync(dir_fd) != 0) {
    return Status::IOError("cannot fsync directory " + Quoted(directory) +
                           ": " + ErrorText(errno));
  }
  return Status::OK();
}

std::string DigestNamedPath(const std::string& dir, std::string_view prefix,
                            uint64_t digest, std::string_view suffix) {
  char hex[17];
  std::snprintf(hex, sizeof(hex), "%016" PRIx64, digest);
  std::string path = dir;
  if (!path.empty() && path.back() != '/') path.push_back('/');
  path.append(prefix).append(hex).append(suffix);
  return path;
}

MappedFile::~MappedFile() {
  if (data_ != nullptr) ::munmap(data_, size_);
}

MappedFile::MappedFile(MappedFile&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)) {}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this != &other) {
    if (data_ != nullptr) ::munmap(data_, size_);
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
  }
  return *this;
}

Status MappedFile::Open(const std::string& path, std::string_view what,
                        MappedFile* out, Pages pages) {
  OpenedFile file;
  RETURN_IF_ERROR(OpenRegularFile(path, what, &file));
  const std::string& name = file.name;
  const int fd = file.closer.fd;
  const uint64_t file_size = file.size;
  if (file_size == 0) return Status::IOError(name + " is empty");
  const size_t size = static_cast<size_t>(file_size);
  const int populate = pages == Pages::kAtOnce ? MAP_POPULATE : 0;
  void* data = ::mmap(nullptr, size, PROT_READ, MAP_SHARED | populate, fd, 0);
  if (data == MAP_FAILED) {
    return Status::IOError("cannot map " + name + ": " + ErrorText(errno));
  }
  MappedFile mapped;
  mapped.data_ = data;
  mapped.size_ = size;
  *out = std::move(mapped);
  return Status::OK();
}

}  // namespace locator
