#include "tests/server/main/e2e_support.h"

#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "server/core/cgal/triangulation.h"
#include "tests/testing/wait.h"

namespace locator::test {
namespace {

constexpr int kGridSide = 60;
// x offsets of the three parts, far enough apart that the exact grid's unit
// edges and the collinear run's segments are Delaunay edges.
constexpr double kCollinearX = 75;
constexpr int kCollinearPoints = 48;
constexpr double kJitteredX = 90;
constexpr int kRepeatedPerGrid = 30;
constexpr size_t kMaxReported = 8;

// The core's type of a wire value; a failure of the calling test if it has
// none.
LocationType KnownLocationType(int type) {
  const std::optional<LocationType> known = FromProtoLocationType(type);
  if (!known) ADD_FAILURE() << "the answer has location type " << type;
  return known.value_or(LocationType::kFace);
}

std::string Describe(const Point2& q) {
  std::ostringstream text;
  text.precision(17);
  text << "(" << q.x << ", " << q.y << ")";
  return text.str();
}

bool Near(double a, double b, double scale) {
  return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(scale));
}

}  // namespace

TestDatasetFile::TestDatasetFile() {
  static int files_made = 0;
  path_ = ::testing::TempDir() + "locatord_e2e_" + std::to_string(getpid()) +
          "_" + std::to_string(files_made++) + ".csv";
  std::vector<Point2> exact, collinear, jittered;
  for (int i = 0; i < kGridSide; ++i) {
    for (int j = 0; j < kGridSide; ++j) exact.push_back({1.0 * i, 1.0 * j});
  }
  // x = kCollinearX + y / 8: exactly representable, exactly collinear.
  for (int k = 0; k < kCollinearPoints; ++k) {
    collinear.push_back({kCollinearX + 0.125 * k, 1.0 * k});
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int i = 0; i < kGridSide; ++i) {
    for (int j = 0; j < kGridSide; ++j) {
      jittered.push_back({kJitteredX + i + jitter(rng), j + jitter(rng)});
    }
  }
  std::ofstream out(path_);
  out.precision(17);
  auto write = [&out](const Point2& p) {
    out << p.x << "," << p.y << "," << TestValue(p) << "\n";
  };
  out << "x,y,z\n# exact grid\n";
  for (const Point2& p : exact) write(p);
  out << "\n# collinear run\n";
  for (const Point2& p : collinear) write(p);
  out << "# jittered grid\n";
  for (const Point2& p : jittered) write(p);
  out << "# repeated points\n";
  for (int k = 0; k < kRepeatedPerGrid; ++k) {
    write(exact[k * 7]);
    write(jittered[k * 11]);
  }
}

TestDatasetFile::~TestDatasetFile() { std::remove(path_.c_str()); }

std::vector<Point2> TestQueries() {
  std::vector<Point2> queries;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> x(-10, kJitteredX + kGridSide + 10);
  std::uniform_real_distribution<double> y(-10, kGridSide + 10);
  for (int k = 0; k < 4000; ++k) queries.push_back({x(rng), y(rng)});
  for (int i = 0; i < kGridSide; ++i) {
    for (int j = 0; j < kGridSide; ++j) {
      const double xi = i, yj = j;
      if ((i + j) % 3 == 0) queries.push_back({xi, yj});  // vertex
      if (i + 1 < kGridSide && (i + j) % 2 == 0) {
        queries.push_back({xi + 0.5, yj});  // horizontal edge
      }
      if (j + 1 < kGridSide && (i + j) % 2 == 1) {
        queries.push_back({xi, yj + 0.5});  // vertical edge
      }
      if (i + 1 < kGridSide && j + 1 < kGridSide && (i + j) % 4 == 0) {
        queries.push_back({xi + 0.5, yj + 0.5});  // on the chosen diagonal
      }
    }
  }
  for (int k = 0; k < kCollinearPoints; ++k) {
    queries.push_back({kCollinearX + 0.125 * k, 1.0 * k});
    if (k + 1 < kCollinearPoints) {
      queries.push_back({kCollinearX + 0.125 * k + 0.0625, k + 0.5});
    }
  }
  // Beyond the hull, all around it, and along the lines of hull edges.
  for (int k = 1; k <= 100; ++k) {
    const double d = 0.37 * k;
    queries.push_back({-d, 0.31 * k});
    queries.push_back({0.9 * k, -d});
    queries.push_back({1.4 * k, kGridSide + d});
    queries.push_back({kJitteredX + kGridSide + d, 0.5 * k});
    queries.push_back({-d, 0});
    queries.push_back({0, kGridSide - 1 + d});
  }
  const double far = 1e300, tiny = 1e-300;
  for (const Point2& p : std::vector<Point2>{{far, 0},
                                             {-far, 0},
                                             {0, far},
                                             {0, -far},
                                             {far, far},
                                             {-far, -far},
                                             {far, -far},
                                             {-far, far},
                                             {far, 30},
                                             {kCollinearX, -far},
                                             {tiny, 0},
                                             {-tiny, 0},
                                             {0, tiny},
                                             {tiny, tiny}}) {
    queries.push_back(p);
  }
  return queries;
}

Status StartLocatord(const std::string& dataset,
                     const std::vector<std::string>& flags,
                     std::unique_ptr<test::ServerProcess>* server,
                     const ChannelSecurity& client_security) {
  std::vector<std::string> args = {"--dataset", dataset, "--listen",
                                   "127.0.0.1:0"};
  args.insert(args.end(), flags.begin(), flags.end());
  return test::ServerProcess::Start(LOCATORD_PATH, args, server,
                                    client_security);
}

std::unique_ptr<v1::Locator::Stub> NewStub(const test::ServerProcess& server) {
  return NewStub(server, server.client_security());
}

std::unique_ptr<v1::Locator::Stub> NewStub(const test::ServerProcess& server,
                                           const ChannelSecurity& security) {
  return v1::Locator::NewStub(CreateLocatorChannel({.target = server.target(),
                                                    .own_connection = true,
                                                    .security = security}));
}

v1::LocateRequest LocateRequestFor(const Point2& q,
                                   const std::string& dataset) {
  v1::LocateRequest request;
  request.mutable_point()->set_x(q.x);
  request.mutable_point()->set_y(q.y);
  request.set_dataset(dataset);
  return request;
}

grpc::Status LocateOne(v1::Locator::Stub& stub, const Point2& q,
                       v1::LocateResponse* response,
                       const std::string& dataset) {
  grpc::ClientContext context;
  return stub.Locate(&context, LocateRequestFor(q, dataset), response);
}

grpc::Status Reload(v1::Locator::Stub& stub, const std::string& dataset,
                    v1::ReloadResponse* response, const std::string& name) {
  grpc::ClientContext context;
  v1::ReloadRequest request;
  request.set_spec(dataset);
  request.set_name(name);
  return stub.Reload(&context, request, response);
}

v1::GetStatsResponse GetStats(v1::Locator::Stub& stub,
                              const std::string& dataset) {
  grpc::ClientContext context;
  v1::GetStatsRequest request;
  request.set_dataset(dataset);
  v1::GetStatsResponse stats;
  const grpc::Status status = stub.GetStats(&context, request, &stats);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return stats;
}

v1::GetStatsResponse WaitForStats(
    v1::Locator::Stub& stub,
    const std::function<bool(const v1::GetStatsResponse&)>& done,
    const std::string& dataset) {
  v1::GetStatsResponse stats;
  test::WaitUntil([&] {
    stats = GetStats(stub, dataset);
    return done(stats);
  });
  return stats;
}

void WriteUniformCsv(const std::string& path, size_t n, uint64_t seed) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary);
    out.precision(17);
    out << "x,y,z\n";
    for (const Point2& p : GenerateUniform(n, seed).points) {
      out << p.x << "," << p.y << "," << TestValue(p) << "\n";
    }
  }
  ASSERT_EQ(std::rename(temporary.c_str(), path.c_str()), 0);
}

void ExpectAnswersAgree(v1::Locator::Stub& stub,
                        const std::string& dataset_path,
                        const std::string& dataset) {
  std::unique_ptr<Reference> reference;
  ASSERT_TRUE(Reference::Build(dataset_path, &reference).ok());
  std::vector<Point2> queries =
      GenerateUniform(2000, 77).points;  // inside the hull, mostly
  for (Point2& q : queries) q = {1.2 * q.x - 0.1, 1.2 * q.y - 0.1};
  grpc::ClientContext context;
  v1::LocateBatchRequest request = BatchRequestFor(queries);
  request.set_dataset(dataset);
  v1::LocateBatchResponse batch;
  ASSERT_TRUE(stub.LocateBatch(&context, request, &batch).ok());
  std::vector<LocateResult> answers;
  for (size_t row = 0; row < queries.size(); ++row) {
    answers.push_back(FromBatchRow(batch, row));
  }
  EXPECT_EQ(reference->Disagreements(queries, answers, false), "");
  for (size_t i = 0; i < 100; ++i) {
    v1::LocateResponse unary;
    ASSERT_TRUE(LocateOne(stub, queries[i], &unary, dataset).ok());
    const LocateResult answer = FromLocateResponse(unary);
    EXPECT_EQ(reference->Disagreements(std::span(&queries[i], 1),
                                       std::span(&answer, 1), true),
              "");
  }
}

std::optional<LocationType> FromProtoLocationType(int type) {
  switch (type) {
    case v1::LOCATION_TYPE_FACE:
      return LocationType::kFace;
    case v1::LOCATION_TYPE_EDGE:
      return LocationType::kEdge;
    case v1::LOCATION_TYPE_VERTEX:
      return LocationType::kVertex;
    case v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL:
      return LocationType::kOutsideConvexHull;
    case v1::LOCATION_TYPE_OUTSIDE_DOMAIN:
      return LocationType::kOutsideDomain;
    default:
      return std::nullopt;
  }
}

LocateResult FromLocateResponse(const v1::LocateResponse& response) {
  LocateResult result;
  result.type = KnownLocationType(response.type());
  result.triangle_id = response.triangle_id();
  for (int corner = 0; corner < response.vertex_ids_size() && corner < 3;
       ++corner) {
    result.vertex_ids[corner] = response.vertex_ids(corner);
    result.vertices[corner] = {response.vertices(corner).x(),
                               response.vertices(corner).y()};
  }
  for (int corner = 0; corner < response.barycentric_size() && corner < 3;
       ++corner) {
    result.barycentric[corner] = response.barycentric(corner);
  }
  for (int end = 0; end < response.hull_edge_vertex_ids_size() && end < 2;
       ++end) {
    result.hull_edge_ids[end] = response.hull_edge_vertex_ids(end);
  }
  for (int end = 0; end < response.domain_edge_vertex_ids_size() && end < 2;
       ++end) {
    result.domain_edge_ids[end] = response.domain_edge_vertex_ids(end);
  }
  result.has_value = response.has_value();
  result.value = response.value();
  return result;
}

LocateResult FromBatchRow(const v1::LocateBatchResponse& response, size_t row) {
  const int i = static_cast<int>(row);
  LocateResult result;
  result.type = KnownLocationType(response.types(i));
  result.triangle_id = response.triangle_ids(i);
  for (int corner = 0; corner < 3; ++corner) {
    result.vertex_ids[corner] = response.vertex_ids(3 * i + corner);
    if (response.barycentric_size() > 0) {
      result.barycentric[corner] = response.barycentric(3 * i + corner);
    }
  }
  if (response.values_size() > 0) {
    result.has_value = !std::isnan(response.values(i));
    result.value = response.values(i);
  }
  return result;
}

v1::LocateBatchRequest BatchRequestFor(std::span<const Point2> points) {
  v1::LocateBatchRequest request;
  request.mutable_xs()->Reserve(static_cast<int>(points.size()));
  request.mutable_ys()->Reserve(static_cast<int>(points.size()));
  for (const Point2& p : points) {
    request.add_xs(p.x);
    request.add_ys(p.y);
  }
  request.set_include_vertex_ids(true);
  request.set_include_barycentric(true);
  request.set_include_values(true);
  return request;
}

std::vector<LocateResult> LocateEach(
    v1::Locator::Stub& stub, std::span<const Point2> queries,
    const std::function<void(const v1::LocateResponse&)>& inspect) {
  std::vector<LocateResult> answers;
  answers.reserve(queries.size());
  for (const Point2& q : queries) {
    v1::LocateResponse response;
    const grpc::Status status = LocateOne(stub, q, &response);
    if (!status.ok()) {
      ADD_FAILURE() << "Locate " << Describe(q) << ": "
                    << status.error_message();
      break;
    }
    if (inspect) inspect(response);
    answers.push_back(FromLocateResponse(response));
  }
  return answers;
}

std::vector<LocateResult> LocateInBatches(v1::Locator::Stub& stub,
                                          std::span<const Point2> queries,
                                          size_t batch_size) {
  std::vector<LocateResult> answers;
  answers.reserve(queries.size());
  for (size_t begin = 0; begin < queries.size(); begin += batch_size) {
    const std::span<const Point2> batch =
        queries.subspan(begin, std::min(batch_size, queries.size() - begin));
    grpc::ClientContext context;
    v1::LocateBatchResponse response;
    const grpc::Status status =
        stub.LocateBatch(&context, BatchRequestFor(batch), &response);
    if (!status.ok()) {
      ADD_FAILURE() << "LocateBatch: " << status.error_message();
      break;
    }
    if (response.types_size() != static_cast<int>(batch.size()) ||
        response.vertex_ids_size() != static_cast<int>(3 * batch.size())) {
      ADD_FAILURE() << "LocateBatch of " << batch.size() << " points answered "
                    << response.types_size() << " types and "
                    << response.vertex_ids_size() << " vertex ids";
      break;
    }
    uint64_t cost_sum = 0;
    for (size_t row = 0; row < batch.size(); ++row) {
      answers.push_back(FromBatchRow(response, row));
      cost_sum += response.costs(static_cast<int>(row));
    }
    EXPECT_EQ(response.total_cost(), cost_sum);
  }
  return answers;
}

grpc::Status StreamGrid(v1::Locator::Stub& stub, const v1::GridRequest& request,
                        v1::GridResponse* whole, int* messages) {
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() +
                       std::chrono::seconds(60));
  auto reader = stub.Grid(&context, request);
  v1::GridResponse message;
  std::vector<std::vector<double>> rows;
  int count = 0;
  while (reader->Read(&message)) {
    EXPECT_EQ(message.has_header(), count == 0);
    if (message.has_header()) {
      *whole->mutable_header() = message.header();
      rows.resize(message.header().height());
    }
    const uint32_t width = whole->header().width();
    EXPECT_EQ(message.values_size(), int64_t{message.rows()} * width);
    for (uint32_t r = 0; r < message.rows(); ++r) {
      std::vector<double>& row = rows.at(message.first_row() + r);
      EXPECT_TRUE(row.empty()) << "row " << message.first_row() + r;
      row.assign(message.values().begin() + r * width,
                 message.values().begin() + (r + 1) * width);
    }
    ++count;
  }
  const grpc::Status status = reader->Finish();
  if (!status.ok()) return status;
  whole->set_first_row(0);
  whole->set_rows(static_cast<uint32_t>(rows.size()));
  for (const std::vector<double>& row : rows) {
    EXPECT_FALSE(row.empty());
    whole->mutable_values()->Add(row.begin(), row.end());
  }
  if (messages != nullptr) *messages = count;
  return status;
}

std::vector<LocateResult> LocateOverStream(v1::Locator::Stub& stub,
                                           std::span<const Point2> queries) {
  std::vector<LocateResult> answers;
  answers.reserve(queries.size());
  const grpc::Status status =
      StreamPoints(stub, queries, [&](const v1::LocateResponse& response) {
        answers.push_back(FromLocateResponse(response));
      });
  EXPECT_TRUE(status.ok()) << status.error_message();
  return answers;
}

grpc::Status StreamPoints(
    v1::Locator::Stub& stub, std::span<const Point2> queries,
    const std::function<void(const v1::LocateResponse&)>& answered) {
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() +
                       std::chrono::seconds(60));
  auto stream = stub.LocateStream(&context);
  std::thread writer([&] {
    for (const Point2& q : queries) {
      if (!stream->Write(LocateRequestFor(q))) return;
    }
    stream->WritesDone();
  });
  v1::LocateResponse response;
  while (stream->Read(&response)) answered(response);
  writer.join();
  return stream->Finish();
}

Reference::~Reference() = default;

LocateResult Reference::Locate(const Point2& q) const {
  return triangulation_->ReferenceLocate(q);
}

std::vector<LocateResult> Reference::LocateAll(
    std::span<const Point2> queries) const {
  std::vector<LocateResult> answers;
  answers.reserve(queries.size());
  for (const Point2& q : queries) answers.push_back(Locate(q));
  return answers;
}

bool Reference::Agrees(const Point2& q, const LocateResult& got,
                       const LocateResult& want) const {
  return triangulation_->Agrees(q, got, want);
}

Status Reference::Build(const std::string& dataset_path,
                        std::unique_ptr<Reference>* reference) {
  StatusOr<Dataset> dataset = LoadDataset(dataset_path);
  if (!dataset.ok()) return dataset.status();
  return FromDataset(*std::move(dataset), reference);
}

Status Reference::FromDataset(Dataset dataset,
                              std::unique_ptr<Reference>* reference) {
  std::unique_ptr<Reference> built(new Reference());
  built->dataset_ = std::move(dataset);
  StatusOr<std::unique_ptr<Triangulation>> triangulation =
      Triangulation::Build(built->dataset_);
  if (!triangulation.ok()) return triangulation.status();
  built->triangulation_ = *std::move(triangulation);
  *reference = std::move(built);
  return Status::OK();
}

std::string Reference::Disagreements(std::span<const Point2> queries,
                                     std::span<const LocateResult> answers,
                                     bool hull_edge_known) const {
  return Disagreements(queries, answers, LocateAll(queries), hull_edge_known);
}

std::string Reference::Disagreements(std::span<const Point2> queries,
                                     std::span<const LocateResult> answers,
                                     std::span<const LocateResult> wants,
                                     bool hull_edge_known) const {
  if (queries.size() != answers.size() || queries.size() != wants.size()) {
    return std::to_string(answers.size()) + " answers (and " +
           std::to_string(wants.size()) + " references) for " +
           std::to_string(queries.size()) + " queries";
  }
  std::string report;
  size_t count = 0;
  for (size_t i = 0; i < queries.size(); ++i) {
    const std::string problem =
        Disagreement(queries[i], answers[i], wants[i], hull_edge_known);
    if (problem.empty()) continue;
    if (++count <= kMaxReported) {
      report += "query " + std::to_string(i) + " " + Describe(queries[i]) +
                ": " + problem + "\n";
    }
  }
  if (count > kMaxReported) {
    report += "... " + std::to_string(count) + " disagreements in all\n";
  }
  return report;
}

std::string Reference::Disagreement(const Point2& q, const LocateResult& got,
                                    const LocateResult& want,
                                    bool hull_edge_known) const {
  if (got.type != want.type) {
    return std::string("type ") + std::string(LocationTypeName(got.type)) +
           ", CGAL says " + std::string(LocationTypeName(want.type));
  }
  if (want.type == LocationType::kFace && got.triangle_id != want.triangle_id) {
    return "triangle " + std::to_string(got.triangle_id) + ", CGAL says " +
           std::to_string(want.triangle_id);
  }
  // A batch answer names no domain edge: the type is all there is.
  if (want.type == LocationType::kOutsideDomain && !hull_edge_known) {
    return got.has_value ? "a value outside the domain" : "";
  }
  bool agrees = triangulation_->Agrees(q, got, want);
  if (!hull_edge_known && want.type == LocationType::kOutsideConvexHull) {
    // Some edge of the hull triangle, taken counter-clockwise, must see q.
    for (int corner = 0; corner < 3 && !agrees; ++corner) {
      LocateResult with_edge = got;
      with_edge.hull_edge_ids = {got.vertex_ids[corner],
                                 got.vertex_ids[(corner + 1) % 3]};
      agrees = triangulation_->Agrees(q, with_edge, want);
    }
  }
  if (!agrees) return "not the location CGAL reports";
  if (want.type == LocationType::kOutsideConvexHull ||
      want.type == LocationType::kOutsideDomain) {
    return got.has_value ? "a value outside the hull or the domain" : "";
  }
  const double weight_sum =
      got.barycentric[0] + got.barycentric[1] + got.barycentric[2];
  if (!Near(weight_sum, 1, 1)) {
    return "barycentric weights sum to " + std::to_string(weight_sum);
  }
  if (!got.has_value || !Near(got.value, TestValue(q), TestValue(q))) {
    return "value " + std::to_string(got.value) + ", want " +
           std::to_string(TestValue(q));
  }
  return "";
}

}  // namespace locator::test
