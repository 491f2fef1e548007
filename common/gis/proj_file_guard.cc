#include "common/gis/proj_file_guard.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <utility>

#include "common/input_text.h"
#include "common/mutex.h"

namespace locator::gis {
namespace {

namespace fs = std::filesystem;

// Whether `path` is `dir` or below it; both canonical.
bool IsInside(const fs::path& path, const fs::path& dir) {
  return std::mismatch(dir.begin(), dir.end(), path.begin(), path.end())
             .first == dir.end();
}

std::vector<std::string> FindDataDirectories() {
  std::vector<std::string> dirs;
  const PJ_INFO info = proj_info();
  std::string_view rest = info.searchpath == nullptr ? "" : info.searchpath;
  while (!rest.empty()) {
    const size_t colon = rest.find(':');
    const std::string_view entry = rest.substr(0, colon);
    rest = colon == std::string_view::npos ? "" : rest.substr(colon + 1);
    std::error_code error;
    const fs::path dir = fs::weakly_canonical(fs::path(entry), error);
    if (entry.empty() || error) continue;
    if (std::find(dirs.begin(), dirs.end(), dir.string()) == dirs.end()) {
      dirs.push_back(dir.string());
    }
  }
  return dirs;
}

struct AdmittedFiles {
  Mutex mu;
  std::set<std::string> paths GUARDED_BY(mu);
};

AdmittedFiles& Admitted() {
  static AdmittedFiles* const admitted = new AdmittedFiles();
  return *admitted;
}

bool IsAdmitted(const fs::path& path) {
  AdmittedFiles& admitted = Admitted();
  MutexLock lock(&admitted.mu);
  return admitted.paths.count(path.string()) != 0;
}

GuardedProjContext* Guard(void* user_data) {
  return static_cast<GuardedProjContext*>(user_data);
}

FILE* Stream(PROJ_FILE_HANDLE* handle) {
  return reinterpret_cast<FILE*>(handle);
}

PROJ_FILE_HANDLE* Open(PJ_CONTEXT*, const char* name, PROJ_OPEN_ACCESS access,
                       void* user_data) {
  if (access != PROJ_OPEN_ACCESS_READ_ONLY) return nullptr;
  return reinterpret_cast<PROJ_FILE_HANDLE*>(
      Guard(user_data)->OpenForProj(name));
}

size_t Read(PJ_CONTEXT*, PROJ_FILE_HANDLE* handle, void* buffer, size_t size,
            void*) {
  return std::fread(buffer, 1, size, Stream(handle));
}

size_t Write(PJ_CONTEXT*, PROJ_FILE_HANDLE*, const void*, size_t, void*) {
  return 0;
}

int Seek(PJ_CONTEXT*, PROJ_FILE_HANDLE* handle, long long offset, int whence,
         void*) {
  return ::fseeko(Stream(handle), static_cast<off_t>(offset), whence) == 0;
}

unsigned long long Tell(PJ_CONTEXT*, PROJ_FILE_HANDLE* handle, void*) {
  const off_t at = ::ftello(Stream(handle));
  return at < 0 ? 0 : static_cast<unsigned long long>(at);
}

void Close(PJ_CONTEXT*, PROJ_FILE_HANDLE* handle, void*) {
  std::fclose(Stream(handle));
}

int Exists(PJ_CONTEXT*, const char* name, void* user_data) {
  return Guard(user_data)->ExistsForProj(name);
}

int Refused(PJ_CONTEXT*, const char*, void*) { return 0; }

int RefusedRename(PJ_CONTEXT*, const char*, const char*, void*) { return 0; }

constexpr PROJ_FILE_API kFileApi = {
    .version = 1,
    .open_cbk = Open,
    .read_cbk = Read,
    .write_cbk = Write,
    .seek_cbk = Seek,
    .tell_cbk = Tell,
    .close_cbk = Close,
    .exists_cbk = Exists,
    .mkdir_cbk = Refused,
    .unlink_cbk = Refused,
    .rename_cbk = RefusedRename,
};

}  // namespace

const std::vector<std::string>& ProjDataDirectories() {
  static const std::vector<std::string>* const dirs =
      new std::vector<std::string>(FindDataDirectories());
  return *dirs;
}

void AdmitProjFile(const std::string& path) {
  std::error_code error;
  const fs::path canonical = fs::canonical(path, error);
  if (error) return;
  AdmittedFiles& admitted = Admitted();
  MutexLock lock(&admitted.mu);
  admitted.paths.insert(canonical.string());
}

GuardedProjContext::GuardedProjContext(ProjFileScope scope)
    : scope_(scope), context_(proj_context_create()) {
  // First, so that PROJ's one-time look-up of its own directories (cached
  // process-wide) is made by proj_info() with PROJ's plain file access.
  const std::vector<std::string>& dirs = ProjDataDirectories();
  // Errors come back as Status messages; a hostile request must not fill
  // the log through PROJ's stderr logger.
  proj_log_func(context_, this, &GuardedProjContext::KeepError);
  proj_context_set_enable_network(context_, 0);
  proj_context_set_fileapi(context_, &kFileApi, this);
  if (scope_ == ProjFileScope::kDataDirectories) {
    // Without this, a grid name found nowhere is tried in the working
    // directory last.
    std::vector<const char*> paths;
    for (const std::string& dir : dirs) paths.push_back(dir.c_str());
    proj_context_set_search_paths(context_, static_cast<int>(paths.size()),
                                  paths.data());
  }
}

GuardedProjContext::~GuardedProjContext() { proj_context_destroy(context_); }

void GuardedProjContext::KeepError(void* self, int level, const char* message) {
  if (level != PJ_LOG_ERROR || message == nullptr) return;
  std::string_view text(message);
  // "proj_create: ...": the function is PROJ's business, not the caller's.
  if (const size_t colon = text.find(": ");
      colon != std::string_view::npos &&
      text.substr(0, colon).find(' ') == std::string_view::npos) {
    text.remove_prefix(colon + 2);
  }
  // PROJ may quote the request's text: one line, bounded.
  std::string kept = TruncatedMessage(text, kMaxLoggedError);
  for (char& c : kept) {
    if (IsControlByte(c)) c = ' ';
  }
  static_cast<GuardedProjContext*>(self)->logged_error_ = std::move(kept);
}

std::string GuardedProjContext::TakeLoggedError() {
  return std::exchange(logged_error_, std::string());
}

std::string GuardedProjContext::TakeRefusal() {
  std::string refusal;
  refusal.swap(refusal_);
  return refusal;
}

bool GuardedProjContext::Permits(std::string_view name) {
  if (scope_ == ProjFileScope::kAnyRegularFile) return true;
  if (name.starts_with('@')) name.remove_prefix(1);  // an optional grid
  // Where PROJ's look-up goes for `name` (pj_open_lib): the path itself for
  // "/", "./" and "../" names, the home directory for "~/", else the
  // search path, the data directories here.
  std::vector<std::string> candidates;
  if (name.starts_with('/') || name.starts_with("./") ||
      name.starts_with("../")) {
    candidates.emplace_back(name);
  } else if (name.starts_with("~/")) {
    const char* home = std::getenv("HOME");
    candidates.push_back(std::string(home == nullptr ? "" : home) +
                         std::string(name.substr(1)));
  } else {
    for (const std::string& dir : ProjDataDirectories()) {
      candidates.push_back(dir + "/" + std::string(name));
    }
  }
  return std::all_of(
      candidates.begin(), candidates.end(),
      [this](const std::string& path) { return !Vet(path.c_str()).empty(); });
}

std::FILE* GuardedProjContext::OpenForProj(const char* name) {
  const std::string path = Vet(name);
  struct stat before;
  if (path.empty() || ::stat(path.c_str(), &before) != 0) return nullptr;
  // Opening a device can have effects of its own, and reading a FIFO or a
  // terminal blocks: only regular files are opened, without blocking, and
  // checked again in case the name changed in between.
  const int fd =
      S_ISREG(before.st_mode)
          ? ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)
          : -1;
  struct stat after;
  const bool same_file =
      fd >= 0 && ::fstat(fd, &after) == 0 && S_ISREG(after.st_mode) &&
      after.st_dev == before.st_dev && after.st_ino == before.st_ino;
  std::FILE* stream = same_file ? ::fdopen(fd, "rb") : nullptr;
  if (stream == nullptr && fd >= 0) ::close(fd);
  if (!same_file) Refuse(name, "not a regular file");
  return stream;
}

bool GuardedProjContext::ExistsForProj(const char* name) {
  const std::string path = Vet(name);
  struct stat status;
  return !path.empty() && ::stat(path.c_str(), &status) == 0;
}

std::string GuardedProjContext::Vet(const char* name) {
  std::error_code error;
  const fs::path path = fs::weakly_canonical(fs::path(name), error);
  if (error) {
    Refuse(name, "cannot be resolved");
    return "";
  }
  if (scope_ == ProjFileScope::kDataDirectories && !IsAdmitted(path)) {
    const std::vector<std::string>& dirs = ProjDataDirectories();
    if (std::none_of(dirs.begin(), dirs.end(), [&](const std::string& dir) {
          return IsInside(path, fs::path(dir));
        })) {
      Refuse(name, "outside PROJ's data directories");
      return "";
    }
  }
  return path.string();
}

void GuardedProjContext::Refuse(const char* name, const char* why) {
  // Names are quoted short: they come from a request. Appended piece by
  // piece: GCC 12 warns (-Wrestrict, falsely) on "'" + std::string(...).
  constexpr size_t kQuotedChars = 160;
  if (!refusal_.empty()) return;
  const std::string_view text(name);
  std::string quoted(1, '\'');
  quoted.append(text.substr(0, kQuotedChars));
  quoted.append(text.size() > kQuotedChars ? "...' (" : "' (");
  quoted.append(why);
  quoted.push_back(')');
  refusal_ = std::move(quoted);
}

}  // namespace locator::gis
