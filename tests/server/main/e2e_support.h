// Shared pieces of the locatord end-to-end tests: the dataset file they
// serve, the query points they send, the in-process CGAL reference, and the
// conversion of answers received over the wire back into LocateResults.
//
// The dataset mixes an exact integer grid (so that vertices and edge
// midpoints are exactly representable queries), an exactly collinear run,
// a jittered grid and repeated points; every point carries the value
// z = 2x + 3y + 1, so interpolated values are checkable anywhere in the hull.
//
// Thread-safety: Reference is immutable after Build(); its const methods may
// be called from any number of threads.

#ifndef LOCATOR_TESTS_SERVER_E2E_SUPPORT_H_
#define LOCATOR_TESTS_SERVER_E2E_SUPPORT_H_

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "client/locator_client.h"
#include "locator/dataset_sources.h"
#include "locator/geometry.h"
#include "locator/locate_result.h"
#include "locator/v1/locator.grpc.pb.h"
#include "tests/testing/server_process.h"

namespace locator {
class Triangulation;
}  // namespace locator

namespace locator::test {

// The value every dataset point carries, hence the exact interpolant.
inline double TestValue(const Point2& p) { return 2 * p.x + 3 * p.y + 1; }

// The dataset described above, written as CSV to a fresh file in the test
// temp dir, which is removed again on destruction.
class TestDatasetFile {
 public:
  TestDatasetFile();
  ~TestDatasetFile();
  TestDatasetFile(const TestDatasetFile&) = delete;
  TestDatasetFile& operator=(const TestDatasetFile&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// >= 10^4 queries: uniform points in and around the hull, every kind of
// vertex, edge midpoints, points beyond the hull (some collinear with hull
// edges) and points 1e300 away.
std::vector<Point2> TestQueries();

// Starts the locatord under test on 127.0.0.1:0 serving `dataset`, with
// `flags` added; waits until it is SERVING (probing with `client_security`,
// the credentials the server accepts).
Status StartLocatord(const std::string& dataset,
                     const std::vector<std::string>& flags,
                     std::unique_ptr<test::ServerProcess>* server,
                     const ChannelSecurity& client_security = {});
// A stub on a channel of its own (its own TCP connection, as a separate
// client would have) to `server`, with the server's client credentials or
// with `security`.
std::unique_ptr<v1::Locator::Stub> NewStub(const test::ServerProcess& server);
std::unique_ptr<v1::Locator::Stub> NewStub(const test::ServerProcess& server,
                                           const ChannelSecurity& security);

// `q` as a Locate or LocateStream request for dataset `dataset` ("": the
// default).
v1::LocateRequest LocateRequestFor(const Point2& q,
                                   const std::string& dataset = "");
// Calls Locate for `q` on `dataset`.
grpc::Status LocateOne(v1::Locator::Stub& stub, const Point2& q,
                       v1::LocateResponse* response,
                       const std::string& dataset = "");
// Calls Reload of the dataset named `name` ("": the default) with the spec
// `dataset` ("": its configured one).
grpc::Status Reload(v1::Locator::Stub& stub, const std::string& dataset,
                    v1::ReloadResponse* response, const std::string& name = "");

// Calls GetStats for `dataset`; a failed call is a test failure (and an
// empty answer).
v1::GetStatsResponse GetStats(v1::Locator::Stub& stub,
                              const std::string& dataset = "");
// Polls GetStats for `dataset` until `done` holds or test::kGenerousWait
// passes; returns the last answer.
v1::GetStatsResponse WaitForStats(
    v1::Locator::Stub& stub,
    const std::function<bool(const v1::GetStatsResponse&)>& done,
    const std::string& dataset = "");

// Writes `n` uniform points of the unit square with values TestValue(p) as
// CSV to `path`, replacing it atomically.
void WriteUniformCsv(const std::string& path, size_t n, uint64_t seed);
// Checks unary and batch answers of `dataset` ("": the default) for points
// in and around the unit square against CGAL on `dataset_path`.
void ExpectAnswersAgree(v1::Locator::Stub& stub,
                        const std::string& dataset_path,
                        const std::string& dataset = "");

// The core's location type of a wire value; nullopt for UNSPECIFIED or a
// value the API does not define.
std::optional<LocationType> FromProtoLocationType(int type);
// An answer that came over the wire, as the core would have returned it (a
// type FromProtoLocationType does not know is a test failure).
LocateResult FromLocateResponse(const v1::LocateResponse& response);
// Row `row` of a batch answer sent with include_vertex_ids (and optionally
// the other columns). hull_edge_ids are not part of a batch answer.
LocateResult FromBatchRow(const v1::LocateBatchResponse& response, size_t row);
// Packs `points` into a columnar request with every optional column on.
v1::LocateBatchRequest BatchRequestFor(std::span<const Point2> points);

// The answers to `queries` over each way a client can send them, in query
// order. An RPC that fails is a test failure, and the answers end there.
// One unary Locate per query; `inspect`, if set, sees every response.
std::vector<LocateResult> LocateEach(
    v1::Locator::Stub& stub, std::span<const Point2> queries,
    const std::function<void(const v1::LocateResponse&)>& inspect = nullptr);
// LocateBatch calls of at most `batch_size` points with every column on;
// each response's total_cost must be the sum of its costs.
std::vector<LocateResult> LocateInBatches(v1::Locator::Stub& stub,
                                          std::span<const Point2> queries,
                                          size_t batch_size);
// The whole stream of a Grid call as one message (the HTTP form): the
// header and every row in order, and in *messages (if not null) how many
// messages came. Each row must come exactly once, the header first.
grpc::Status StreamGrid(v1::Locator::Stub& stub, const v1::GridRequest& request,
                        v1::GridResponse* whole, int* messages = nullptr);
// One LocateStream carrying every query (written from a second thread, as
// the server stops reading while its answers wait unread).
std::vector<LocateResult> LocateOverStream(v1::Locator::Stub& stub,
                                           std::span<const Point2> queries);
// One LocateStream carrying every query, as LocateOverStream, whatever its
// end: `answered` sees each answer, and the stream's status is returned.
grpc::Status StreamPoints(
    v1::Locator::Stub& stub, std::span<const Point2> queries,
    const std::function<void(const v1::LocateResponse&)>& answered);

// CGAL's own answers for the same dataset file, built in-process.
class Reference {
 public:
  // Loads the dataset file at `dataset_path` and triangulates it.
  static Status Build(const std::string& dataset_path,
                      std::unique_ptr<Reference>* reference);
  // Triangulates `dataset`, already loaded.
  static Status FromDataset(Dataset dataset,
                            std::unique_ptr<Reference>* reference);

  ~Reference();

  const Dataset& dataset() const { return dataset_; }
  // CGAL's own locate() of q.
  LocateResult Locate(const Point2& q) const;
  // Locate() of every query, in order.
  std::vector<LocateResult> LocateAll(std::span<const Point2> queries) const;
  // Triangulation::Agrees: `got` and `want` are equally right answers for q.
  bool Agrees(const Point2& q, const LocateResult& got,
              const LocateResult& want) const;

  // Checks answers[i] for queries[i]: same type, Triangulation::Agrees, the
  // same triangle id for FACE, no value OUTSIDE_DOMAIN, and (inside the hull
  // and the domain) barycentric weights and values consistent with the
  // dataset. A batch answer names no hull or domain edge; for it
  // (`hull_edge_known` false) some edge of the reported hull triangle must
  // see q, and OUTSIDE_DOMAIN is checked by its type. Returns the first few
  // disagreements, "" if there are none.
  std::string Disagreements(std::span<const Point2> queries,
                            std::span<const LocateResult> answers,
                            bool hull_edge_known) const;
  // As above, with CGAL's answers already known: wants[i] is
  // Locate(queries[i]).
  std::string Disagreements(std::span<const Point2> queries,
                            std::span<const LocateResult> answers,
                            std::span<const LocateResult> wants,
                            bool hull_edge_known) const;

 private:
  std::string Disagreement(const Point2& q, const LocateResult& got,
                           const LocateResult& want,
                           bool hull_edge_known) const;

  Dataset dataset_;
  std::unique_ptr<Triangulation> triangulation_;
};

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_E2E_SUPPORT_H_
