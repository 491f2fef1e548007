// GuardedProjContext: a PROJ context whose every file access goes through
// this class, so that no CRS can make PROJ open a device or a FIFO, and a
// request's CRS cannot make it open anything outside PROJ's own data.
//
// PROJ opens the files a CRS names: grids (+nadgrids, +geoidgrids, a WKT's
// PARAMETERFILE, a PROJJSON transformation's parameter file), +init files,
// and its own proj.ini and proj.db. A context of this class
// (proj_context_set_fileapi) opens, in its scope:
//   kAnyRegularFile   any regular file, wherever PROJ's normal lookup finds
//                     it: for the operator's own CRSs;
//   kDataDirectories  regular files inside PROJ's data directories (the
//                     search path proj_info() reports, where PROJ finds
//                     proj.db and its grids) or admitted by AdmitProjFile()
//                     (grids the operator's dataset CRSs name): for a
//                     request's CRS. Relative names are looked up in the
//                     data directories only, never in the working directory.
// A file is checked with stat() before it is opened, opened read-only and
// non-blocking, and checked again; nothing is written, created, renamed or
// deleted, and the network is off. The first name refused since the last
// TakeRefusal() is kept for the caller's message.
//
// Thread-safety: a context is used by one thread at a time (PROJ's rule).
// ProjDataDirectories() and AdmitProjFile() may be called from any thread.

#ifndef LOCATOR_COMMON_GIS_PROJ_FILE_GUARD_H_
#define LOCATOR_COMMON_GIS_PROJ_FILE_GUARD_H_

#include <proj.h>

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace locator::gis {

enum class ProjFileScope { kAnyRegularFile, kDataDirectories };

class GuardedProjContext {
 public:
  static constexpr size_t kMaxLoggedError = 200;

  explicit GuardedProjContext(ProjFileScope scope);
  ~GuardedProjContext();
  GuardedProjContext(const GuardedProjContext&) = delete;
  GuardedProjContext& operator=(const GuardedProjContext&) = delete;

  // The PROJ context; never null, owned by this object.
  PJ_CONTEXT* get() const { return context_; }

  // The first file PROJ asked for and was refused since the last call, as
  // "'NAME' (WHY)", or "" if none was; forgets it.
  std::string TakeRefusal();

  // The last error PROJ logged since the last call (without the name of
  // the PROJ function that logged it, on one line, cut to kMaxLoggedError
  // bytes), or "" if none was; forgets it. PROJ's error code alone is no
  // substitute: proj_create() leaves an earlier failure's code in the
  // context.
  std::string TakeLoggedError();

  // Whether PROJ's look-up of the grid or file `name`, as a CRS names it,
  // stays where this scope lets PROJ read (a name without a directory is
  // looked up in the data directories); records the refusal if not. It
  // checks the name only, opening nothing.
  bool Permits(std::string_view name);

  // For the file API's callbacks only: `name` opened read-only if this
  // scope lets PROJ read it (else null, the refusal recorded), and whether
  // `name` exists where this scope lets PROJ look.
  std::FILE* OpenForProj(const char* name);
  bool ExistsForProj(const char* name);

 private:
  // The path PROJ may use for `name`, or "" with the refusal recorded.
  std::string Vet(const char* name);
  void Refuse(const char* name, const char* why);
  // PROJ's logger: keeps the last error.
  static void KeepError(void* self, int level, const char* message);

  const ProjFileScope scope_;
  std::string refusal_;
  std::string logged_error_;
  PJ_CONTEXT* const context_;
};

// PROJ's data directories, canonical: proj_info()'s search path, computed
// once per process.
const std::vector<std::string>& ProjDataDirectories();

// Lets kDataDirectories contexts open the regular file `path` too (a grid
// the operator's dataset CRS names). For the process's lifetime.
void AdmitProjFile(const std::string& path);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_PROJ_FILE_GUARD_H_
