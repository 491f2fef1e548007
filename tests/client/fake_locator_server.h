// FakeLocatorServer: a locator.v1.Locator service with known answers,
// computed from the request by the formulas below, served on 127.0.0.1 on a
// port the OS picks, inside the test process. End-to-end tests run the real
// clients (the `locator` binary, locator-load) against it for what the real
// server does not do yet, or to see exactly which requests a client sends.
//
// Answers:
//   Locate, LocateBatch, LocateStream: FACE, triangle 1, value
//     FakeSurface(x, y) (the batch fills the columns it is asked for).
//   GetStats: source "fake", bounding box kFakeBox.
//   Retune: an empty tuning. Reload: the dataset source the request named.
//   ListDatasets: FakeDatasetList().
//   Profile: FakeProfile(request).
//   Grid: the header (the request's size, or for a cell size the box grown
//     east and south to whole cells; nodata as asked, else NaN; crs_wkt as
//     given to the server), then FakeGridValue(col, row, nodata) for every
//     cell, kGridRowsPerMessage rows a message, the LAST rows first (a client
//     must place rows by first_row, not by order of arrival).
// Every request is recorded; a test reads the last one of each kind, and
// can make the next Profile or Grid fail, or break the Grid stream.
//
// Owns the service and the server. Thread-safety: thread-safe (gRPC's
// threads answer; the test thread configures and reads under a mutex).

#ifndef LOCATOR_TESTS_CLIENT_FAKE_LOCATOR_SERVER_H_
#define LOCATOR_TESTS_CLIENT_FAKE_LOCATOR_SERVER_H_

#include <grpcpp/grpcpp.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "locator/v1/locator.grpc.pb.h"

namespace locator::test {

inline constexpr uint32_t kGridRowsPerMessage = 3;

// The dataset's bounding box (GetStats) and values (Locate, Profile).
inline constexpr double kFakeBox[4] = {100, 200, 160, 240};  // x0 y0 x1 y1
double FakeSurface(double x, double y);

// Cell (col, row) of a Grid answer: nodata on every fifth diagonal, else a
// value that names the cell.
double FakeGridValue(uint32_t col, uint32_t row, double nodata);

// The ListDatasets answer: "terrain" (default, serving, 225 points, 416
// triangles, WGS 84 / UTM zone 33N, EPSG:32633) and "bedrock" (loading).
v1::ListDatasetsResponse FakeDatasetList();

// The Profile answer to `request`: LINE_VERTEX breakpoints at the vertices
// and an EDGE_CROSSING at the middle of every segment (triangle id: the
// breakpoint's index), `samples` evenly spaced SAMPLE points (triangle id:
// the segment's index), and one gap over the last quarter of the line,
// where points have no value and triangle -1. Values are FakeSurface.
v1::ProfileResponse FakeProfile(const v1::ProfileRequest& request);

// How the next Grid stream misbehaves.
enum class GridFault {
  kNone,
  kFailAfterFirstMessage,  // status `grid_error` after one message of rows
  kDropLastMessage,        // ends OK without its last message
};

class FakeLocatorServer {
 public:
  // Starts serving; `crs_wkt` is the Grid header's CRS.
  explicit FakeLocatorServer(std::string crs_wkt = "");
  ~FakeLocatorServer();
  FakeLocatorServer(const FakeLocatorServer&) = delete;
  FakeLocatorServer& operator=(const FakeLocatorServer&) = delete;

  // "127.0.0.1:PORT".
  const std::string& target() const { return target_; }

  // The next Profile call answers `status` instead.
  void FailNextProfile(const grpc::Status& status);
  // The next Grid call answers `status` at once (kNone), or misbehaves as
  // `fault` says.
  void FailNextGrid(const grpc::Status& status,
                    GridFault fault = GridFault::kNone);

  // The last request of each kind (default messages before the first).
  v1::LocateRequest last_locate() const;
  v1::LocateBatchRequest last_locate_batch() const;
  // Every message of every LocateStream so far.
  std::vector<v1::LocateRequest> stream_requests() const;
  v1::GetStatsRequest last_get_stats() const;
  v1::RetuneRequest last_retune() const;
  v1::ReloadRequest last_reload() const;
  v1::ProfileRequest last_profile() const;
  v1::GridRequest last_grid() const;
  // How many calls of any kind the server has answered.
  uint64_t calls() const;

 private:
  class Service;

  std::unique_ptr<Service> service_;
  std::unique_ptr<grpc::Server> server_;
  std::string target_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_CLIENT_FAKE_LOCATOR_SERVER_H_
