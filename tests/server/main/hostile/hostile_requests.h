// The hostile requests of each RPC, drawn by a CaseDraw, with what each may
// get (see hostile_values.h for the drawing and hostile_expect.h for the
// judging).
//
// Every request field has a list of hostile values (a HostileField; the
// *FieldCounts() functions give each RPC's list lengths, 0 for a field it
// lacks). A drawn case holds the request, its Expectation for the
// transport it will travel on (the HTTP server refuses oversized bodies
// and paths itself, and may hold grids to a lower cell limit), the oracle
// of the dataset it names, the query points where the test knows them in
// the dataset's coordinates, and a summary of its hostile fields.
//
// What the proto and issue 26 document, field by field:
//   - a non-finite coordinate: INVALID_ARGUMENT naming the point (profile:
//     the line, grid: the box or cell_size);
//   - a finite one: answered (Locate, batch, stream, with CGAL's location)
//     or, where arithmetic on it could overflow (profile, grid, a CRS
//     transform), answered or INVALID_ARGUMENT naming the field;
//   - an unknown dataset: NOT_FOUND naming it, before anything else;
//   - a CRS on a dataset without one, and every CRS that names a file, a
//     device or an operation, or is unknown or garbage: INVALID_ARGUMENT
//     (or PERMISSION_DENIED) naming the crs;
//   - a size past a limit: RESOURCE_EXHAUSTED naming it; at the limit: OK;
//   - an unknown interpolation: INVALID_ARGUMENT naming it.
//
// Thread-safety: free functions over their arguments.

#ifndef LOCATOR_TESTS_SERVER_HOSTILE_REQUESTS_H_
#define LOCATOR_TESTS_SERVER_HOSTILE_REQUESTS_H_

#include <optional>
#include <string>
#include <vector>

#include "locator/v1/locator.pb.h"
#include "tests/server/main/hostile/hostile_expect.h"
#include "tests/server/main/hostile/hostile_oracle.h"
#include "tests/server/main/hostile/hostile_server.h"
#include "tests/server/main/hostile/hostile_values.h"

namespace locator::test {

enum HostileField : int {
  kFieldX,              // x of the point (a profile vertex, the box)
  kFieldY,              // y likewise
  kFieldCrs,            // the request CRS
  kFieldDataset,        // the dataset name
  kFieldInterpolation,  // an unknown interpolation
  kFieldSize,           // how many points, vertices, cells, messages
  kFieldSamples,        // ProfileRequest.samples
  kFieldCellSize,       // GridRequest.cell_size
  kFieldNodata,         // GridRequest.nodata
  kFieldSpec,           // ReloadRequest.dataset
  kFieldCount,
};

template <typename Request>
struct HostileCase {
  Request request;
  Expectation expect;
  const DatasetOracle* oracle = nullptr;  // null: an unknown dataset
  // The query points (Locate: one; batch: each row), where known in the
  // dataset's coordinates.
  std::vector<std::optional<Point2>> points;
  std::string summary;
};

std::vector<size_t> LocateFieldCounts(const HostileServer& server);
HostileCase<v1::LocateRequest> DrawLocate(CaseDraw& draw,
                                          const HostileServer& server,
                                          Transport transport);

std::vector<size_t> BatchFieldCounts(const HostileServer& server);
HostileCase<v1::LocateBatchRequest> DrawBatch(CaseDraw& draw,
                                              const HostileServer& server,
                                              Transport transport);

// A LocateStream: its messages, each a Locate case. One message holds the
// focus; the others are benign but for a few hostile fields. Size values:
// a stream of kLongStream messages; a message past the message size limit.
inline constexpr size_t kLongStream = 3000;
std::vector<size_t> StreamFieldCounts(const HostileServer& server);
std::vector<HostileCase<v1::LocateRequest>> DrawStream(
    uint64_t seed, size_t index, Focus focus, const HostileServer& server);

std::vector<size_t> ProfileFieldCounts(const HostileServer& server);
HostileCase<v1::ProfileRequest> DrawProfile(CaseDraw& draw,
                                            const HostileServer& server,
                                            Transport transport);

std::vector<size_t> GridFieldCounts(const HostileServer& server);
HostileCase<v1::GridRequest> DrawGrid(CaseDraw& draw,
                                      const HostileServer& server,
                                      Transport transport);

// Reload: a hostile name, or a hostile spec (files outside the reload dir,
// devices, the FIFO, GIS options that run SQL or name other files, garbage,
// generator specs past the point limit); the benign spec is "" (the
// dataset's own, which must reload OK).
std::vector<size_t> ReloadFieldCounts(const HostileServer& server);
HostileCase<v1::ReloadRequest> DrawReload(CaseDraw& draw,
                                          const HostileServer& server);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_HOSTILE_REQUESTS_H_
