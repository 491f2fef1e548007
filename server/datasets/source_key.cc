#include "server/datasets/source_key.h"

#include <sys/stat.h>

#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <type_traits>

#include "server/core/dataset/file_io.h"

#define XXH_INLINE_ALL
#include <xxhash.h>

namespace locator {
namespace {

// Bump when the format or what a key stands for changes.
constexpr std::string_view kMagic = "locator source key 1\n";
// A key larger than this is not one (a CRS's WKT is a few kilobytes).
constexpr size_t kMaxKeyBytes = 4 << 20;

std::string WorkingDirectory() {
  std::error_code error;
  const std::filesystem::path cwd = std::filesystem::current_path(error);
  return error ? std::string() : cwd.string();
}

// "<length>:<bytes>", so that any bytes (a path with spaces or newlines, a
// WKT) round-trip.
void AppendText(std::string_view text, std::string* out) {
  *out += std::to_string(text.size());
  *out += ':';
  out->append(text);
}

std::string Hex(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016" PRIx64, value);
  return text;
}

// Doubles as C99 hex floats: exact.
std::string Exact(double value) {
  char text[40];
  std::snprintf(text, sizeof(text), "%a", value);
  return text;
}

std::string Encode(std::string_view spec, const std::string& cwd,
                   const SourceKey& key) {
  std::string out(kMagic);
  out += "spec ";
  AppendText(spec, &out);
  out += "\ncwd ";
  AppendText(cwd, &out);
  out += '\n';
  for (const FileIdentity& f : key.files) {
    out += "file " + std::to_string(f.exists) + " " + std::to_string(f.size) +
           " " + std::to_string(f.mtime_ns) + " " + std::to_string(f.device) +
           " " + std::to_string(f.inode) + " ";
    AppendText(f.path, &out);
    out += '\n';
  }
  out += "fingerprint " + Hex(key.fingerprint) + "\ncrs ";
  AppendText(key.crs, &out);
  out += '\n';
  if (const auto& s = key.simplification) {
    out += "simplification " + std::to_string(s->source_samples) + " " +
           std::to_string(s->unserved_samples) + " " +
           std::to_string(s->vertices) + " " + std::to_string(s->triangles) +
           " " + Exact(s->max_error) + " " + Exact(s->target_error) + " " +
           std::to_string(s->max_points) + " " + Exact(s->build_seconds) + "\n";
  }
  out += "checksum " + Hex(XXH3_64bits(out.data(), out.size())) + "\n";
  return out;
}

// Reads the fields of a key's text, left to right; any mismatch makes it
// fail for good, naming what it expected.
class KeyReader {
 public:
  explicit KeyReader(std::string_view text) : rest_(text) {}

  bool ok() const { return error_.empty(); }
  const std::string& error() const { return error_; }
  bool AtWord(std::string_view word) const {
    return ok() && rest_.starts_with(word) &&
           rest_.substr(word.size()).starts_with(' ');
  }
  void Literal(std::string_view literal) {
    if (!ok()) return;
    if (!rest_.starts_with(literal)) return Fail(std::string(literal));
    rest_.remove_prefix(literal.size());
  }
  uint64_t Unsigned(int base = 10) { return Number<uint64_t>(base); }
  int64_t Signed() { return Number<int64_t>(10); }
  double Double() { return Number<double>(0); }
  std::string Text() {
    const uint64_t length = Unsigned();
    Literal(":");
    if (!ok() || length > rest_.size()) {
      Fail("a text of the stated length");
      return "";
    }
    std::string text(rest_.substr(0, length));
    rest_.remove_prefix(length);
    return text;
  }

 private:
  template <typename T>
  T Number(int base) {
    if (!ok()) return 0;
    // The text is bounded by a separator, never by the end of the buffer.
    const std::string field(rest_.substr(0, rest_.find_first_of(" :\n")));
    char* end = nullptr;
    errno = 0;
    T value;
    if constexpr (std::is_same_v<T, double>) {
      value = std::strtod(field.c_str(), &end);
    } else if constexpr (std::is_signed_v<T>) {
      value = std::strtoll(field.c_str(), &end, base);
    } else {
      value = std::strtoull(field.c_str(), &end, base);
    }
    if (field.empty() || errno != 0 || end != field.c_str() + field.size() ||
        (std::is_unsigned_v<T> && field[0] == '-')) {
      Fail("a number");
      return 0;
    }
    rest_.remove_prefix(field.size());
    return value;
  }
  void Fail(const std::string& expected) {
    if (!ok()) return;
    const std::string_view next = rest_.substr(0, 24);
    error_ = "expected " + expected + " before '" + std::string(next) + "'";
  }

  std::string_view rest_;
  std::string error_;
};

Status Decode(std::string_view text, SourceKey* key, std::string* spec,
              std::string* cwd) {
  if (!text.starts_with(kMagic)) {
    return Status::InvalidArgument("not a source key of this version");
  }
  const size_t checksum_at = text.rfind("checksum ");
  if (checksum_at == std::string_view::npos ||
      text.substr(checksum_at) !=
          "checksum " + Hex(XXH3_64bits(text.data(), checksum_at)) + "\n") {
    return Status::InvalidArgument("its checksum does not match");
  }
  KeyReader r(text.substr(kMagic.size(), checksum_at - kMagic.size()));
  r.Literal("spec ");
  *spec = r.Text();
  r.Literal("\ncwd ");
  *cwd = r.Text();
  r.Literal("\n");
  while (r.AtWord("file")) {
    FileIdentity f;
    r.Literal("file ");
    f.exists = r.Unsigned() != 0;
    r.Literal(" ");
    f.size = r.Unsigned();
    r.Literal(" ");
    f.mtime_ns = r.Signed();
    r.Literal(" ");
    f.device = r.Unsigned();
    r.Literal(" ");
    f.inode = r.Unsigned();
    r.Literal(" ");
    f.path = r.Text();
    r.Literal("\n");
    key->files.push_back(std::move(f));
  }
  r.Literal("fingerprint ");
  key->fingerprint = r.Unsigned(16);
  r.Literal("\ncrs ");
  key->crs = r.Text();
  r.Literal("\n");
  if (r.AtWord("simplification")) {
    SimplificationStats s;
    r.Literal("simplification ");
    s.source_samples = r.Unsigned();
    r.Literal(" ");
    s.unserved_samples = r.Unsigned();
    r.Literal(" ");
    s.vertices = r.Unsigned();
    r.Literal(" ");
    s.triangles = r.Unsigned();
    r.Literal(" ");
    s.max_error = r.Double();
    r.Literal(" ");
    s.target_error = r.Double();
    r.Literal(" ");
    s.max_points = r.Unsigned();
    r.Literal(" ");
    s.build_seconds = r.Double();
    r.Literal("\n");
    key->simplification = s;
  }
  if (!r.ok()) return Status::InvalidArgument(r.error());
  return Status::OK();
}

}  // namespace

FileIdentity IdentifyFile(const std::string& path) {
  FileIdentity identity;
  identity.path = path;
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) return identity;
  identity.exists = true;
  identity.size = static_cast<uint64_t>(info.st_size);
  identity.mtime_ns =
      int64_t{info.st_mtim.tv_sec} * 1'000'000'000 + info.st_mtim.tv_nsec;
  identity.device = static_cast<uint64_t>(info.st_dev);
  identity.inode = static_cast<uint64_t>(info.st_ino);
  return identity;
}

std::string SourceKeyPath(const std::string& cache_dir, std::string_view spec) {
  std::string named(kMagic);
  AppendText(spec, &named);
  AppendText(WorkingDirectory(), &named);
  return DigestNamedPath(cache_dir, "source-",
                         XXH3_64bits(named.data(), named.size()), ".key");
}

Status ReadSourceKey(const std::string& cache_dir, std::string_view spec,
                     SourceKey* out) {
  const std::string path = SourceKeyPath(cache_dir, spec);
  std::string text;
  if (Status s = ReadWholeFile(path, "source key", &text, kMaxKeyBytes);
      !s.ok()) {
    return s;
  }
  SourceKey key;
  std::string key_spec, key_cwd;
  Status status = Decode(text, &key, &key_spec, &key_cwd);
  if (status.ok() && (key_spec != spec || key_cwd != WorkingDirectory())) {
    status = Status::InvalidArgument("it is the key of another spec");
  }
  if (!status.ok()) {
    return Status::InvalidArgument("source key " + path + ": " +
                                   status.message());
  }
  *out = std::move(key);
  return Status::OK();
}

Status CheckSourceFiles(const SourceKey& key) {
  for (const FileIdentity& recorded : key.files) {
    const FileIdentity now = IdentifyFile(recorded.path);
    if (now == recorded) continue;
    const char* what = !recorded.exists ? "appeared"
                       : !now.exists    ? "is gone"
                                        : "changed";
    return Status::FailedPrecondition(recorded.path + " " + what +
                                      " since the mesh was built");
  }
  return Status::OK();
}

Status WriteSourceKey(const std::string& cache_dir, std::string_view spec,
                      const SourceKey& key) {
  return WriteFileAtomically(SourceKeyPath(cache_dir, spec),
                             Encode(spec, WorkingDirectory(), key));
}

}  // namespace locator
