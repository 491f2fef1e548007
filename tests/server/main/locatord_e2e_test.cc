// locatord end to end: the real binary on a dataset file, answers checked
// against CGAL's own locate() in-process. Bad inputs and their status codes
// are the table of bad_input_table_test.cc and bad_dataset_table_test.cc.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "locator/engine.h"
#include "tests/server/main/e2e_support.h"

namespace locator::test {
namespace {

constexpr size_t kBatchSize = 2500;

class LocatordTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dataset_ = new TestDatasetFile();
    ASSERT_TRUE(Reference::Build(dataset_->path(), &reference_).ok());
    queries_ = new std::vector<Point2>(TestQueries());
    Status started = StartLocatord(dataset_->path(), {}, &server_);
    ASSERT_TRUE(started.ok()) << started.ToString();
  }
  static void TearDownTestSuite() {
    server_.reset();
    reference_.reset();
    delete queries_;
    delete dataset_;
  }

  void SetUp() override {
    ASSERT_NE(server_, nullptr);
    stub_ = NewStub(*server_);
  }

  grpc::Status LocateBatch(const v1::LocateBatchRequest& request,
                           v1::LocateBatchResponse* response) {
    grpc::ClientContext context;
    return stub_->LocateBatch(&context, request, response);
  }

  static TestDatasetFile* dataset_;
  static std::unique_ptr<Reference> reference_;
  static std::vector<Point2>* queries_;
  static std::unique_ptr<test::ServerProcess> server_;
  std::unique_ptr<v1::Locator::Stub> stub_;
};

TestDatasetFile* LocatordTest::dataset_ = nullptr;
std::unique_ptr<Reference> LocatordTest::reference_;
std::vector<Point2>* LocatordTest::queries_ = nullptr;
std::unique_ptr<test::ServerProcess> LocatordTest::server_;

TEST_F(LocatordTest, QuerySetCoversEveryLocationType) {
  ASSERT_GE(queries_->size(), 10'000u);
  size_t by_type[4] = {};
  for (const Point2& q : *queries_) {
    ++by_type[static_cast<int>(reference_->Locate(q).type)];
  }
  for (size_t count : by_type) EXPECT_GE(count, 100u);
}

TEST_F(LocatordTest, ReferenceCheckCatchesWrongAnswers) {
  auto first_of = [&](LocationType type) {
    for (const Point2& q : *queries_) {
      if (reference_->Locate(q).type == type) return q;
    }
    return Point2{};
  };
  auto rejects = [&](const Point2& q, const LocateResult& wrong) {
    return !reference_
                ->Disagreements(std::span(&q, 1), std::span(&wrong, 1),
                                /*hull_edge_known=*/true)
                .empty();
  };
  const Point2 face = first_of(LocationType::kFace);
  LocateResult wrong = reference_->Locate(face);
  EXPECT_FALSE(rejects(face, wrong));
  wrong.triangle_id += 1;
  EXPECT_TRUE(rejects(face, wrong));
  wrong = reference_->Locate(face);
  wrong.value += 1e-3;
  EXPECT_TRUE(rejects(face, wrong));

  const Point2 edge = first_of(LocationType::kEdge);
  wrong = reference_->Locate(edge);
  wrong.vertex_ids = reference_->Locate(face).vertex_ids;
  EXPECT_TRUE(rejects(edge, wrong));

  const Point2 outside = first_of(LocationType::kOutsideConvexHull);
  wrong = reference_->Locate(outside);
  EXPECT_FALSE(rejects(outside, wrong));
  std::swap(wrong.hull_edge_ids[0], wrong.hull_edge_ids[1]);
  EXPECT_TRUE(rejects(outside, wrong));
}

TEST_F(LocatordTest, UnaryAnswersMatchReference) {
  const std::vector<LocateResult> answers =
      LocateEach(*stub_, *queries_, [&](const v1::LocateResponse& response) {
        // Unary answers carry the corners' coordinates; they are dataset
        // points.
        for (int corner = 0; corner < 3; ++corner) {
          const Point2& p = reference_->dataset().points.at(
              static_cast<size_t>(response.vertex_ids(corner)));
          ASSERT_EQ(response.vertices(corner).x(), p.x);
          ASSERT_EQ(response.vertices(corner).y(), p.y);
        }
        ASSERT_EQ(response.cost().total(), response.cost().faces_visited() +
                                               response.cost().comparisons() +
                                               response.cost().table_lookups());
      });
  EXPECT_EQ(reference_->Disagreements(*queries_, answers,
                                      /*hull_edge_known=*/true),
            "");
}

TEST_F(LocatordTest, BatchAnswersMatchReference) {
  EXPECT_EQ(reference_->Disagreements(
                *queries_, LocateInBatches(*stub_, *queries_, kBatchSize),
                /*hull_edge_known=*/false),
            "");
}

TEST_F(LocatordTest, LargeBatchSplitAcrossThreadsMatchesReference) {
  // Every query, four times over: large enough for several shards.
  std::vector<Point2> points;
  for (int copy = 0; copy < 4; ++copy) {
    points.insert(points.end(), queries_->begin(), queries_->end());
  }
  v1::LocateBatchRequest request = BatchRequestFor(points);
  request.set_include_barycentric(false);
  request.set_include_values(false);
  v1::LocateBatchResponse response;
  const grpc::Status status = LocateBatch(request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(response.barycentric_size(), 0);
  EXPECT_EQ(response.values_size(), 0);
  std::vector<LocateResult> answers;
  for (size_t row = 0; row < points.size(); ++row) {
    LocateResult answer = FromBatchRow(response, row);
    // Not requested, so not checkable: take the reference's.
    const LocateResult want = reference_->Locate(points[row]);
    answer.barycentric = want.barycentric;
    answer.has_value = want.has_value;
    answer.value = want.value;
    answers.push_back(answer);
  }
  EXPECT_EQ(reference_->Disagreements(points, answers,
                                      /*hull_edge_known=*/false),
            "");
}

// Grids (streamed in blocks rendered on the server's pool) and profiles,
// both linear and natural neighbour, while other calls locate: every value
// is the plane the dataset's values lie on (both interpolations reproduce
// it), nodata exactly where CGAL finds no value. Under ThreadSanitizer in CI.
TEST_F(LocatordTest, GridsAndProfilesServeWhileOthersLocate) {
  constexpr double kTolerance = 1e-9 * 500;
  constexpr int kWidth = 2048;
  auto grids = [] {
    auto stub = NewStub(*server_);
    for (const v1::Interpolation how :
         {v1::INTERPOLATION_NATURAL_NEIGHBOR, v1::INTERPOLATION_LINEAR}) {
      v1::GridRequest request;
      request.mutable_box()->set_min_x(-3);
      request.mutable_box()->set_min_y(-2);
      request.mutable_box()->set_max_x(155);
      request.mutable_box()->set_max_y(62);
      request.set_width(kWidth);
      request.set_height(97);  // 4 blocks of 32 rows
      request.set_nodata(-1);
      request.set_interpolation(how);
      grpc::ClientContext context;
      auto reader = stub->Grid(&context, request);
      v1::GridResponse message;
      v1::GridHeader header;
      int rows = 0;
      while (reader->Read(&message)) {
        if (message.has_header()) header = message.header();
        rows += message.rows();
        for (int i = 0; i < message.values_size(); i += 11) {
          const Point2 q{-3 + (i % kWidth + 0.5) * header.cell_width(),
                         62 - (message.first_row() + i / kWidth + 0.5) *
                                  header.cell_height()};
          const LocateResult want = reference_->Locate(q);
          EXPECT_NEAR(message.values(i), want.has_value ? TestValue(q) : -1,
                      kTolerance)
              << q.x << ", " << q.y;
        }
      }
      EXPECT_TRUE(reader->Finish().ok());
      EXPECT_EQ(rows, 97);
    }
  };
  auto profiles = [] {
    auto stub = NewStub(*server_);
    for (int i = 0; i < 20; ++i) {
      v1::ProfileRequest request;
      for (const Point2& p : {Point2{0.5 + i, 3.25}, Point2{140.5, 55.0 - i}}) {
        v1::Point* vertex = request.add_vertices();
        vertex->set_x(p.x);
        vertex->set_y(p.y);
      }
      request.set_samples(9);
      request.set_interpolation(i % 2 ? v1::INTERPOLATION_NATURAL_NEIGHBOR
                                      : v1::INTERPOLATION_LINEAR);
      grpc::ClientContext context;
      v1::ProfileResponse response;
      ASSERT_TRUE(stub->Profile(&context, request, &response).ok());
      EXPECT_GT(response.crossings(), 100u);
      for (const v1::ProfilePoint& p : response.breakpoints()) {
        if (!p.has_value()) continue;
        EXPECT_NEAR(p.value(), TestValue({p.point().x(), p.point().y()}),
                    kTolerance);
      }
    }
  };
  std::thread grid_thread(grids);
  std::thread profile_thread(profiles);
  const v1::LocateBatchRequest request = BatchRequestFor(*queries_);
  v1::LocateBatchResponse response;
  ASSERT_TRUE(LocateBatch(request, &response).ok());
  std::vector<LocateResult> answers;
  for (size_t row = 0; row < queries_->size(); ++row) {
    answers.push_back(FromBatchRow(response, row));
  }
  EXPECT_EQ(reference_->Disagreements(*queries_, answers,
                                      /*hull_edge_known=*/false),
            "");
  grid_thread.join();
  profile_thread.join();
}

TEST_F(LocatordTest, StreamAnswersMatchReferenceInOrder) {
  EXPECT_EQ(
      reference_->Disagreements(*queries_, LocateOverStream(*stub_, *queries_),
                                /*hull_edge_known=*/true),
      "");
}

TEST_F(LocatordTest, GetStatsDescribesDatasetAndCountsQueries) {
  const StatusOr<std::unique_ptr<Engine>> engine =
      Engine::Create(reference_->dataset(), EngineOptions());
  ASSERT_TRUE(engine.ok());
  const DatasetInfo& want = (*engine)->dataset_info();

  const v1::GetStatsResponse before = GetStats(*stub_);
  v1::LocateResponse unary;
  ASSERT_TRUE(LocateOne(*stub_, {10.25, 20.5}, &unary).ok());
  v1::LocateBatchResponse batch;
  ASSERT_TRUE(
      LocateBatch(
          BatchRequestFor(std::span<const Point2>(*queries_).subspan(0, 100)),
          &batch)
          .ok());
  const v1::GetStatsResponse stats = GetStats(*stub_);

  EXPECT_EQ(stats.dataset().source(), dataset_->path());
  EXPECT_EQ(stats.dataset().input_points(), want.input_points);
  EXPECT_EQ(stats.dataset().vertices(), want.vertices);
  EXPECT_EQ(stats.dataset().duplicates_merged(), 60u);
  EXPECT_EQ(stats.dataset().triangles(), want.triangles);
  EXPECT_TRUE(stats.dataset().has_values());
  EXPECT_GT(stats.dataset().build_seconds(), 0);
  EXPECT_EQ(stats.dataset().bounding_box().min_x(), 0);
  EXPECT_EQ(stats.dataset().bounding_box().min_y(), want.bounding_box.min_y);
  EXPECT_EQ(stats.dataset().bounding_box().max_x(), want.bounding_box.max_x);
  EXPECT_EQ(stats.dataset().bounding_box().max_y(), want.bounding_box.max_y);
  EXPECT_EQ(stats.strategy(), "self-tuning");
  EXPECT_EQ(stats.queries_served(), before.queries_served() + 101);
  EXPECT_GT(stats.mean_cost_lifetime(), 0);
  EXPECT_GT(stats.recent_window(), 0u);
  EXPECT_GT(stats.tuning().grid_size(), 0u);
  EXPECT_EQ(stats.tuning().histogram_size(),
            static_cast<int>(stats.tuning().grid_size() *
                             stats.tuning().grid_size()));
  EXPECT_GT(stats.memory().triangulation_bytes(), 0u);
}

TEST_F(LocatordTest, RetuneReturnsTuningWithoutHistogram) {
  grpc::ClientContext context;
  v1::RetuneResponse response;
  ASSERT_TRUE(stub_->Retune(&context, {}, &response).ok());
  EXPECT_GE(response.tuning().retune_count(), 1u);
  EXPECT_EQ(response.tuning().histogram_size(), 0);
}

}  // namespace
}  // namespace locator::test
