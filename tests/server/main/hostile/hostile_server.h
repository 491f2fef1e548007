// HostileServer: the real locatord the hostile-input test attacks, with the
// files the attacks name.
//
// It serves two datasets: "plain" (the default; the end-to-end CSV, no CRS,
// values on the plane TestValue) and "utm" (a GeoPackage in EPSG:32633 made
// by ogr2ogr, in --reload-dir), with gRPC and HTTP on ports the OS picks,
// every limit small enough to be reached quickly (HostileLimits) and
// --default-deadline-ms at CallDeadline(), which holds HTTP calls to it.
// In the reload directory lie a FIFO nobody writes and a garbage .gpkg;
// beside it, in a directory of its own, a "secret" file, which the test
// watches (inotify): an attack that makes the server open, read or write
// anything there is a hole.
//
// Control() is the control query the test runs after every batch of
// hostile calls: the server is alive and answers a Locate on each dataset
// as CGAL does, over gRPC and over HTTP. Restart() replaces a server that
// crashed or hangs, so that one hole does not hide the next. ResidentBytes()
// reads the server's /proc status.
//
// Owns the scratch directory, the oracles and the server process.
// Thread-safety: none; one test thread.

#ifndef LOCATOR_TESTS_SERVER_HOSTILE_SERVER_H_
#define LOCATOR_TESTS_SERVER_HOSTILE_SERVER_H_

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "locator/status.h"
#include "locator/v1/locator.grpc.pb.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"
#include "tests/server/main/hostile/hostile_oracle.h"
#include "tests/server/main/hostile/hostile_values.h"
#include "tests/server/http/status_e2e_support.h"

namespace locator::test {

// The server's limits, small enough to be reached quickly.
struct HostileLimits {
  static constexpr size_t kBatchPoints = 2000;
  static constexpr uint64_t kProfileCrossings = 3000;
  static constexpr uint32_t kProfileSamples = 4096;
  static constexpr uint64_t kGridCells = 65536;
  static constexpr uint64_t kHttpGridCells = 4096;
  static constexpr size_t kMessageBytes = size_t{4} << 20;
  static constexpr size_t kHttpBodyBytes = size_t{2} << 20;
  static constexpr uint64_t kDatasetPoints = 100000;
};

class HostileServer {
 public:
  static constexpr char kCorsOrigin[] = "https://app.example";

  // Makes the files and starts the server. A failure is a test failure
  // (and a null server).
  static std::unique_ptr<HostileServer> Create();
  ~HostileServer();

  // The deadline of every hostile call and of the control query.
  static std::chrono::milliseconds CallDeadline();
  static std::chrono::milliseconds ControlDeadline();

  const DatasetOracle& plain() const { return *plain_; }
  const DatasetOracle& utm() const { return *utm_; }
  // The oracle of dataset `name` ("" is plain); null for an unknown name.
  const DatasetOracle* OracleFor(const std::string& name) const;

  v1::Locator::Stub& stub() { return *stub_; }
  int http_port() const { return server_->http_port(); }
  const std::string& grpc_target() const { return server_->grpc_target(); }
  bool running() const { return server_ != nullptr; }

  // The request CRSs, hostile ones included (see RequestCrsList).
  const std::vector<RequestCrs>& request_crs() const { return request_crs_; }
  const std::string& reload_dir() const { return reload_dir_; }
  const std::string& outside_dir() const { return outside_dir_; }
  const std::string& gpkg() const { return gpkg_; }
  const std::string& fifo() const { return fifo_; }
  const std::string& secret() const { return secret_; }

  // "" if the server is alive and answers the control Locates right, else
  // what is wrong.
  std::string Control();
  // Kills the server (SIGKILL: a hung one ignores SIGTERM) and starts a new
  // one with the same flags.
  Status Restart();
  // What the server did in the outside directory since the last call
  // ("opened secret.db, created out.db"), "" if nothing.
  std::string TouchedOutside();
  // The server's VmRSS and VmHWM in bytes; nullopt where they cannot be
  // read or mean nothing (under a sanitizer, whose allocator keeps freed
  // memory).
  std::optional<uint64_t> ResidentBytes() const;
  std::optional<uint64_t> PeakResidentBytes() const;

 private:
  HostileServer() = default;
  Status Start();

  ScratchDir scratch_;
  TestDatasetFile csv_;
  std::string reload_dir_, outside_dir_, gpkg_, fifo_, secret_;
  std::vector<std::string> flags_;
  std::unique_ptr<DatasetOracle> plain_, utm_;
  std::vector<RequestCrs> request_crs_;
  std::unique_ptr<LocatordWithHttp> server_;
  std::unique_ptr<v1::Locator::Stub> stub_;
  int outside_watch_ = -1;  // inotify descriptor
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HOSTILE_SERVER_H_
