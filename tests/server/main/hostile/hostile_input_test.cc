// The hostile-input property test (issue 26), part 1: the calls that locate
// points and render the surface. Every request field gets every hostile
// value (hostile_values.h) on its own and in random company, on both
// datasets and with every interpolation, over gRPC (a deadline on every
// call) and HTTP/JSON: each call must answer OK or the precise refusal the
// proto and the issue document (hostile_requests.h), within its deadline;
// OK answers must agree with CGAL where the test knows the query in the
// dataset's coordinates, and be well formed everywhere; and after every
// batch of calls the server must be up, answer a control query right and
// keep its memory (hostile_run.h).
//
// A failure names the seed and the case; LOCATOR_HOSTILE_SEED=<seed>
// reproduces the run, LOCATOR_HOSTILE_REPEATS scales it. Under a sanitizer
// each case travels on one transport (CaseTransports).

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "tests/server/main/e2e_support.h"
#include "tests/server/main/hostile/hostile_calls.h"
#include "tests/server/main/hostile/hostile_requests.h"
#include "tests/server/main/hostile/hostile_run.h"

namespace locator::test {
namespace {

using Code = grpc::StatusCode;

std::string CheckLocate(const HostileCase<v1::LocateRequest>& c,
                        const v1::LocateResponse& response) {
  if (!FromProtoLocationType(response.type())) {
    return "location type " + std::to_string(response.type());
  }
  if (response.vertex_ids_size() != 3 || response.vertices_size() != 3) {
    return std::to_string(response.vertex_ids_size()) + " vertex ids";
  }
  return c.oracle->CheckLocation(c.points[0], c.request.interpolation(),
                                 FromLocateResponse(response), AnswerParts());
}

std::string CheckBatch(const HostileCase<v1::LocateBatchRequest>& c,
                       const v1::LocateBatchResponse& response) {
  const v1::LocateBatchRequest& request = c.request;
  const int n = request.xs_size();
  const auto sized = [n](int size, bool included, int per_point) {
    return size == (included ? n * per_point : 0);
  };
  if (!sized(response.types_size(), true, 1) ||
      !sized(response.triangle_ids_size(), true, 1) ||
      !sized(response.costs_size(), true, 1) ||
      !sized(response.vertex_ids_size(), request.include_vertex_ids(), 3) ||
      !sized(response.barycentric_size(), request.include_barycentric(), 3) ||
      !sized(response.values_size(), request.include_values(), 1)) {
    return "columns of the wrong length for " + std::to_string(n) + " points";
  }
  uint64_t total = 0;
  for (int i = 0; i < n; ++i) {
    total += response.costs(i);
    const std::optional<LocationType> type =
        FromProtoLocationType(response.types(i));
    if (!type) return "point " + std::to_string(i) + ": a bad type";
    LocateResult row;
    row.type = *type;
    row.triangle_id = response.triangle_ids(i);
    for (int k = 0; k < 3; ++k) {
      if (request.include_vertex_ids()) {
        row.vertex_ids[k] = response.vertex_ids(3 * i + k);
      }
      if (request.include_barycentric()) {
        row.barycentric[k] = response.barycentric(3 * i + k);
      }
    }
    if (request.include_values()) {
      row.has_value = !std::isnan(response.values(i));
      row.value = response.values(i);
    }
    const std::string problem =
        c.oracle->CheckLocation(c.points[i], request.interpolation(), row,
                                {.hull_edge = false,
                                 .vertex_ids = request.include_vertex_ids(),
                                 .barycentric = request.include_barycentric(),
                                 .value = request.include_values()});
    if (!problem.empty()) return "point " + std::to_string(i) + ": " + problem;
  }
  if (total != response.total_cost()) return "total_cost is not the sum";
  return "";
}

// Runs `run(index, focus)` over every focus Coverage() lists for `counts`.
template <typename Run>
void ForEachCase(HostileRun& hostile, const std::vector<size_t>& counts,
                 uint64_t seed, Run run) {
  const std::vector<Focus> foci = Coverage(counts, HostileRepeats(), seed);
  for (size_t i = 0; i < foci.size() && !hostile.stopped(); ++i) {
    run(i, foci[i]);
  }
}

// Judges `outcome` and, when it is OK, `check()`s the answer.
template <typename Case, typename Check>
void Judge(HostileRun& run, size_t index, Transport transport, const Case& c,
           const char* rpc, const Outcome& outcome, Check check) {
  std::string problem = c.expect.Judge(outcome);
  if (problem.empty() && outcome.code == Code::OK) {
    run.Answered();
    problem = check();
  }
  run.Record(
      index,
      std::string(rpc) + " over " + TransportName(transport) + ": " + c.summary,
      outcome, problem);
}

TEST_F(HostileTest, Locate) {
  HostileRun run(server_, "Locate", seed());
  ForEachCase(
      run, LocateFieldCounts(*server_), seed(), [&](size_t i, Focus focus) {
        for (Transport t : CaseTransports(i)) {
          CaseDraw draw(seed(), i, focus);
          const auto c = DrawLocate(draw, *server_, t);
          v1::LocateResponse response;
          const Outcome outcome = CallLocate(*server_, t, c.request, &response);
          Judge(run, i, t, c, "Locate", outcome,
                [&] { return CheckLocate(c, response); });
        }
      });
}

TEST_F(HostileTest, LocateBatch) {
  HostileRun run(server_, "LocateBatch", seed());
  ForEachCase(run, BatchFieldCounts(*server_), seed(),
              [&](size_t i, Focus focus) {
                for (Transport t : CaseTransports(i)) {
                  CaseDraw draw(seed(), i, focus);
                  const auto c = DrawBatch(draw, *server_, t);
                  v1::LocateBatchResponse response;
                  const Outcome outcome =
                      CallLocateBatch(*server_, t, c.request, &response);
                  Judge(run, i, t, c, "LocateBatch", outcome,
                        [&] { return CheckBatch(c, response); });
                }
              });
}

// A stream's answers come in order, one per message, up to the first
// message refused; that message's expectation judges how the stream ends.
std::string CheckStream(const std::vector<HostileCase<v1::LocateRequest>>& sent,
                        const std::vector<v1::LocateResponse>& answers,
                        const Outcome& outcome, std::string* summary) {
  if (answers.size() > sent.size()) return "more answers than messages";
  for (size_t k = 0; k < answers.size(); ++k) {
    const HostileCase<v1::LocateRequest>& c = sent[k];
    if (!c.expect.ok_allowed() || c.oracle == nullptr) {
      *summary = c.summary;
      return "message " + std::to_string(k) + " was answered, want " +
             c.expect.Describe();
    }
    const std::string problem = CheckLocate(c, answers[k]);
    if (!problem.empty()) {
      *summary = c.summary;
      return "message " + std::to_string(k) + ": " + problem;
    }
  }
  if (answers.size() == sent.size()) {
    return outcome.code == Code::OK
               ? ""
               : "every message answered, then " + CodeName(outcome.code) +
                     " \"" + Shorten(outcome.message) + "\"";
  }
  // The stream ended at message answers.size(), which must have been
  // refused as its expectation says.
  const HostileCase<v1::LocateRequest>& refused = sent[answers.size()];
  *summary = refused.summary;
  if (outcome.code == Code::OK) {
    return std::to_string(answers.size()) + " answers to " +
           std::to_string(sent.size()) + " messages, and OK";
  }
  const std::string problem = refused.expect.Judge(outcome);
  return problem.empty()
             ? ""
             : "message " + std::to_string(answers.size()) + ": " + problem;
}

TEST_F(HostileTest, LocateStream) {
  HostileRun run(server_, "LocateStream", seed());
  ForEachCase(
      run, StreamFieldCounts(*server_), seed(), [&](size_t i, Focus focus) {
        const auto sent = DrawStream(seed(), i, focus, *server_);
        std::vector<v1::LocateRequest> requests;
        for (const auto& c : sent) requests.push_back(c.request);
        std::vector<v1::LocateResponse> answers;
        const Outcome outcome = CallStream(*server_, requests, &answers);
        std::string summary;
        const std::string problem =
            CheckStream(sent, answers, outcome, &summary);
        if (!answers.empty()) run.Answered();
        run.Record(i,
                   "LocateStream of " + std::to_string(sent.size()) +
                       " messages; " + summary,
                   outcome, problem);
      });
}

TEST_F(HostileTest, Profile) {
  HostileRun run(server_, "Profile", seed());
  ForEachCase(
      run, ProfileFieldCounts(*server_), seed(), [&](size_t i, Focus focus) {
        for (Transport t : CaseTransports(i)) {
          CaseDraw draw(seed(), i, focus);
          const auto c = DrawProfile(draw, *server_, t);
          v1::ProfileResponse response;
          const Outcome outcome =
              CallProfile(*server_, t, c.request, &response);
          Judge(run, i, t, c, "Profile", outcome,
                [&] { return c.oracle->CheckProfile(c.request, response); });
        }
      });
}

TEST_F(HostileTest, Grid) {
  HostileRun run(server_, "Grid", seed());
  ForEachCase(
      run, GridFieldCounts(*server_), seed(), [&](size_t i, Focus focus) {
        for (Transport t : CaseTransports(i)) {
          CaseDraw draw(seed(), i, focus);
          const auto c = DrawGrid(draw, *server_, t);
          v1::GridResponse response;
          const Outcome outcome = CallGrid(*server_, t, c.request, &response);
          Judge(run, i, t, c, "Grid", outcome,
                [&] { return c.oracle->CheckGrid(c.request, response); });
        }
      });
}

}  // namespace
}  // namespace locator::test
