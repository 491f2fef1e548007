// Several named datasets in one locatord, end to end: every RPC is routed
// by its dataset field (the default when empty, NOT_FOUND listing the names
// otherwise; each LocateStream message by its own), answers agree with CGAL
// on each dataset's own file, ListDatasets lists them, a Reload (good or
// bad) of one leaves the other as it was, SIGHUP reloads each, state files
// are kept apart, --max-dataset-points is a total, a bad dataset fails
// startup naming it, and health waits for the last dataset.

#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <csignal>
#include <fstream>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "client/health_check.h"
#include "tests/core/scratch_dir.h"
#include "tests/server/main/e2e_support.h"
#include "tests/testing/wait.h"

namespace locator::test {
namespace {

using ::testing::HasSubstr;
using Code = grpc::StatusCode;

constexpr auto kExitTimeout = std::chrono::seconds(60);
constexpr char kNames[] = "this server has: terrain (default), bedrock";

// A server with terrain=terrain.csv (1500 points) and bedrock=bedrock.csv
// (2500 points), each a CSV in a scratch dir.
class LocatordDatasetsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    terrain_ = dir_.path() + "/terrain.csv";
    bedrock_ = dir_.path() + "/bedrock.csv";
    WriteUniformCsv(terrain_, 1500, 1);
    WriteUniformCsv(bedrock_, 2500, 2);
  }

  void Start(std::vector<std::string> flags = {}) {
    flags.insert(flags.begin(), {"--dataset", "bedrock=" + bedrock_});
    ASSERT_TRUE(StartLocatord("terrain=" + terrain_, flags, &server_).ok());
    stub_ = NewStub(*server_);
  }

  ScratchDir dir_;
  std::string terrain_;
  std::string bedrock_;
  std::unique_ptr<ServerProcess> server_;
  std::unique_ptr<v1::Locator::Stub> stub_;
};

TEST_F(LocatordDatasetsTest, EachDatasetAnswersByNameAndTheFirstByDefault) {
  Start();
  ExpectAnswersAgree(*stub_, terrain_, "terrain");
  ExpectAnswersAgree(*stub_, terrain_, "");
  ExpectAnswersAgree(*stub_, bedrock_, "bedrock");

  const v1::GetStatsResponse terrain = GetStats(*stub_, "terrain");
  const v1::GetStatsResponse bedrock = GetStats(*stub_, "bedrock");
  EXPECT_EQ(terrain.dataset().name(), "terrain");
  EXPECT_EQ(terrain.dataset().input_points(), 1500u);
  EXPECT_EQ(bedrock.dataset().name(), "bedrock");
  EXPECT_EQ(bedrock.dataset().input_points(), 2500u);
  EXPECT_EQ(GetStats(*stub_).dataset().name(), "terrain");
  // Memory is accounted per dataset.
  EXPECT_GT(bedrock.memory().triangulation_bytes(),
            terrain.memory().triangulation_bytes());
  EXPECT_GT(terrain.memory().tuning_bytes(), 0u);
  // Each counts its own queries (ExpectAnswersAgree: 2100 per call).
  EXPECT_EQ(terrain.queries_served(), 4200u);
  EXPECT_EQ(bedrock.queries_served(), 2100u);
}

TEST_F(LocatordDatasetsTest, UnknownNamesAreNotFoundListingTheNames) {
  Start();
  v1::LocateResponse located;
  grpc::Status status = LocateOne(*stub_, {0.5, 0.5}, &located, "lava");
  EXPECT_EQ(status.error_code(), Code::NOT_FOUND);
  EXPECT_EQ(status.error_message(),
            std::string("unknown dataset 'lava'; ") + kNames);
  v1::ReloadResponse reloaded;
  status = Reload(*stub_, "", &reloaded, "lava");
  EXPECT_EQ(status.error_code(), Code::NOT_FOUND);
  EXPECT_THAT(status.error_message(), HasSubstr(kNames));
}

TEST_F(LocatordDatasetsTest, ListDatasetsListsThemInFlagOrder) {
  Start();
  grpc::ClientContext context;
  v1::ListDatasetsResponse list;
  ASSERT_TRUE(stub_->ListDatasets(&context, {}, &list).ok());
  ASSERT_EQ(list.datasets_size(), 2);
  const v1::DatasetEntry& terrain = list.datasets(0);
  EXPECT_EQ(terrain.name(), "terrain");
  EXPECT_TRUE(terrain.is_default());
  EXPECT_TRUE(terrain.serving());
  EXPECT_EQ(terrain.strategy(), "self-tuning");
  EXPECT_EQ(terrain.generation(), 1u);
  EXPECT_EQ(terrain.stats().name(), "terrain");
  EXPECT_EQ(terrain.stats().source(), terrain_);
  EXPECT_EQ(terrain.stats().input_points(), 1500u);
  const v1::DatasetEntry& bedrock = list.datasets(1);
  EXPECT_EQ(bedrock.name(), "bedrock");
  EXPECT_FALSE(bedrock.is_default());
  EXPECT_EQ(bedrock.stats().input_points(), 2500u);
}

TEST_F(LocatordDatasetsTest, StreamMessagesAreRoutedByTheirOwnField) {
  Start();
  std::unique_ptr<Reference> terrain, bedrock;
  ASSERT_TRUE(Reference::Build(terrain_, &terrain).ok());
  ASSERT_TRUE(Reference::Build(bedrock_, &bedrock).ok());
  const std::vector<Point2> queries = GenerateUniform(60, 8).points;
  grpc::ClientContext context;
  auto stream = stub_->LocateStream(&context);
  for (size_t i = 0; i < queries.size(); ++i) {
    const char* name = i % 3 == 0 ? "bedrock" : i % 3 == 1 ? "" : "terrain";
    v1::LocateResponse response;
    ASSERT_TRUE(stream->Write(LocateRequestFor(queries[i], name)) &&
                stream->Read(&response));
    const LocateResult answer = FromLocateResponse(response);
    const Reference& reference = i % 3 == 0 ? *bedrock : *terrain;
    EXPECT_EQ(reference.Disagreements(std::span(&queries[i], 1),
                                      std::span(&answer, 1), true),
              "")
        << "message " << i << " for '" << name << "'";
  }
  // A message naming an unknown dataset ends the stream with NOT_FOUND.
  ASSERT_TRUE(stream->Write(LocateRequestFor({0.5, 0.5}, "lava")));
  stream->WritesDone();
  v1::LocateResponse response;
  EXPECT_FALSE(stream->Read(&response));
  const grpc::Status status = stream->Finish();
  EXPECT_EQ(status.error_code(), Code::NOT_FOUND);
  EXPECT_THAT(status.error_message(), HasSubstr(kNames));
}

TEST_F(LocatordDatasetsTest, AReloadOfOneLeavesTheOtherAsItWas) {
  Start();
  v1::LocateBatchRequest probe =
      BatchRequestFor(GenerateUniform(500, 4).points);
  probe.set_dataset("terrain");
  const auto terrain_answers = [&] {
    grpc::ClientContext context;
    v1::LocateBatchResponse answers;
    EXPECT_TRUE(stub_->LocateBatch(&context, probe, &answers).ok());
    answers.clear_costs();  // the walk's work depends on the tuning
    answers.clear_total_cost();
    return answers.SerializeAsString();
  };
  const std::string terrain_before = terrain_answers();

  WriteUniformCsv(bedrock_, 3000, 12);
  v1::ReloadResponse reloaded;
  grpc::Status status = Reload(*stub_, "", &reloaded, "bedrock");
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(reloaded.generation(), 2u);
  EXPECT_EQ(reloaded.dataset().name(), "bedrock");
  EXPECT_EQ(reloaded.dataset().input_points(), 3000u);
  ExpectAnswersAgree(*stub_, bedrock_, "bedrock");
  EXPECT_EQ(GetStats(*stub_, "terrain").generation(), 1u);
  EXPECT_EQ(terrain_answers(), terrain_before);

  // A bad file: the reload fails naming it, and both keep serving as
  // they were.
  {
    std::ofstream out(bedrock_);
    out << "x,y,z\n0,0,0\n1,oops,2\n";
  }
  status = Reload(*stub_, "", &reloaded, "bedrock");
  EXPECT_EQ(status.error_code(), Code::INVALID_ARGUMENT);
  EXPECT_THAT(status.error_message(), HasSubstr(bedrock_ + ":3:"));
  const v1::GetStatsResponse bedrock = GetStats(*stub_, "bedrock");
  EXPECT_EQ(bedrock.generation(), 2u);
  EXPECT_EQ(bedrock.dataset().input_points(), 3000u);
  EXPECT_FALSE(bedrock.reload_in_progress());
  EXPECT_EQ(GetStats(*stub_, "terrain").generation(), 1u);
  EXPECT_EQ(terrain_answers(), terrain_before);
  v1::LocateResponse located;
  EXPECT_TRUE(LocateOne(*stub_, {0.5, 0.5}, &located, "bedrock").ok());
  EXPECT_THAT(server_->StderrText(),
              HasSubstr("[bedrock] reload failed, still serving the previous "
                        "dataset"));
}

TEST_F(LocatordDatasetsTest, SighupReloadsEveryDataset) {
  Start();
  WriteUniformCsv(terrain_, 1700, 5);
  WriteUniformCsv(bedrock_, 2700, 6);
  server_->SendSignal(SIGHUP);
  for (const auto& [name, points] :
       {std::pair<std::string, uint64_t>{"terrain", 1700},
        std::pair<std::string, uint64_t>{"bedrock", 2700}}) {
    const v1::GetStatsResponse stats = WaitForStats(
        *stub_,
        [](const v1::GetStatsResponse& s) { return s.generation() == 2; },
        name);
    EXPECT_EQ(stats.generation(), 2u) << name << server_->StderrText();
    EXPECT_EQ(stats.dataset().input_points(), points) << name;
  }
  EXPECT_THAT(server_->StderrText(),
              HasSubstr("[terrain] SIGHUP: reloading " + terrain_));
  EXPECT_THAT(server_->StderrText(),
              HasSubstr("[bedrock] SIGHUP: reloading " + bedrock_));
  ExpectAnswersAgree(*stub_, bedrock_, "bedrock");
}

TEST_F(LocatordDatasetsTest, DatasetsWithTheSamePointsKeepTheirOwnStateFiles) {
  ScratchDir state_dir;
  // Both datasets the same file: their tuning fingerprints are equal.
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(StartLocatord("a=" + terrain_,
                            {"--dataset", "b=" + terrain_, "--state-dir",
                             state_dir.path()},
                            &server)
                  .ok());
  auto stub = NewStub(*server);
  const std::string a =
      GetStats(*stub, "a").tuning().persistence().state_path();
  const std::string b =
      GetStats(*stub, "b").tuning().persistence().state_path();
  EXPECT_THAT(a, ::testing::StartsWith(state_dir.path() + "/a/tuning-"));
  EXPECT_THAT(b, ::testing::StartsWith(state_dir.path() + "/b/tuning-"));
  EXPECT_EQ(a.substr(a.rfind('/')), b.substr(b.rfind('/')));
}

// --mesh-cache: the first start triangulates both datasets and writes their
// mesh files; after a restart both are mapped, and answer as before (and as
// CGAL does). (The tuning state restored onto a mapped mesh:
// tests/core/mesh/mesh_file_test.cc.)
TEST_F(LocatordDatasetsTest, ARestartMapsEveryDatasetsMeshFile) {
  ScratchDir cache;
  const std::vector<std::string> flags = {"--mesh-cache", cache.path()};
  Start(flags);
  for (const std::string name : {"terrain", "bedrock"}) {
    const v1::MeshCacheStats first =
        GetStats(*stub_, name).dataset().mesh_cache();
    EXPECT_FALSE(first.mapped()) << name;
    EXPECT_THAT(first.path(), ::testing::StartsWith(cache.path() + "/mesh-"));
    EXPECT_EQ(first.load_error() + first.save_error(), "") << name;
  }
  // A mesh file and a source key (source_key.h) per dataset.
  const std::vector<std::string> entries = cache.Entries();
  ASSERT_EQ(entries.size(), 4u);
  EXPECT_THAT(entries[0], ::testing::StartsWith("mesh-"));
  EXPECT_THAT(entries[1], ::testing::StartsWith("mesh-"));
  EXPECT_THAT(entries[2], ::testing::StartsWith("source-"));
  EXPECT_THAT(entries[3], ::testing::StartsWith("source-"));
  v1::LocateResponse before;
  ASSERT_TRUE(LocateOne(*stub_, {0.3, 0.6}, &before, "bedrock").ok());
  server_->SendSignal(SIGTERM);
  ASSERT_EQ(server_->WaitForExit(kExitTimeout), 0);

  Start(flags);
  for (const std::string name : {"terrain", "bedrock"}) {
    const v1::GetStatsResponse stats = GetStats(*stub_, name);
    EXPECT_TRUE(stats.dataset().mesh_cache().mapped()) << name;
    EXPECT_EQ(stats.dataset().mesh_cache().load_error(), "") << name;
  }
  EXPECT_THAT(server_->StderrText(), HasSubstr("mapped the serving mesh"));
  v1::LocateResponse after;
  ASSERT_TRUE(LocateOne(*stub_, {0.3, 0.6}, &after, "bedrock").ok());
  EXPECT_EQ(after.triangle_id(), before.triangle_id());
  ExpectAnswersAgree(*stub_, terrain_, "terrain");
  ExpectAnswersAgree(*stub_, bedrock_, "bedrock");
}

// A generator spec's mesh is mapped on a restart without generating its
// points, and still within --max-dataset-points.
TEST(LocatordDatasetsStartupTest, AGeneratorSpecRestartsWithoutGenerating) {
  ScratchDir cache;
  const std::vector<std::string> flags = {"--mesh-cache", cache.path()};
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(StartLocatord("uniform:20000:3", flags, &server).ok());
  EXPECT_FALSE(GetStats(*NewStub(*server)).dataset().mesh_cache().mapped());
  server->SendSignal(SIGTERM);
  ASSERT_EQ(server->WaitForExit(kExitTimeout), 0);

  ASSERT_TRUE(StartLocatord("uniform:20000:3", flags, &server).ok());
  const v1::DatasetStats stats = GetStats(*NewStub(*server)).dataset();
  EXPECT_TRUE(stats.mesh_cache().mapped());
  EXPECT_EQ(stats.input_points(), 20000u);
  EXPECT_EQ(stats.source(), "uniform:20000:3");
  EXPECT_THAT(server->StderrText(),
              HasSubstr("found the mesh of uniform:20000:3 without "
                        "generating it"));
  EXPECT_THAT(server->StderrText(),
              ::testing::Not(HasSubstr("loading dataset")));
  server->SendSignal(SIGTERM);
  ASSERT_EQ(server->WaitForExit(kExitTimeout), 0);

  ASSERT_TRUE(ServerProcess::Spawn(
                  LOCATORD_PATH,
                  {"--dataset", "uniform:20000:3", "--mesh-cache", cache.path(),
                   "--max-dataset-points", "1000", "--listen", "127.0.0.1:0"},
                  &server)
                  .ok());
  EXPECT_EQ(server->WaitForExit(kExitTimeout), 1);
  EXPECT_THAT(server->StderrText(),
              HasSubstr("more than 1000 points (max_points limit)"));
}

TEST(LocatordDatasetsStartupTest, MaxDatasetPointsIsATotal) {
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(ServerProcess::Spawn(LOCATORD_PATH,
                                   {"--dataset", "a=uniform:600:1", "--dataset",
                                    "b=uniform:500:2", "--max-dataset-points",
                                    "1000", "--listen", "127.0.0.1:0"},
                                   &server)
                  .ok());
  EXPECT_EQ(server->WaitForExit(kExitTimeout), 1);
  EXPECT_THAT(server->StderrText(),
              HasSubstr("cannot serve dataset b='uniform:500:2': "
                        "RESOURCE_EXHAUSTED: uniform:500:2: more than 400 "
                        "points (max_points limit) (see --max-dataset-points: "
                        "a total of 1000 points over all datasets, of which "
                        "the others hold 600)"));
  // At the total they serve.
  ASSERT_TRUE(StartLocatord("a=uniform:600:1",
                            {"--dataset", "b=uniform:400:2",
                             "--max-dataset-points", "1000"},
                            &server)
                  .ok());
  auto stub = NewStub(*server);
  EXPECT_EQ(GetStats(*stub, "b").dataset().input_points(), 400u);
}

TEST(LocatordDatasetsStartupTest, ABadDatasetAnywhereFailsStartupNamingIt) {
  ScratchDir dir;
  const std::string missing = dir.path() + "/missing.csv";
  std::unique_ptr<ServerProcess> server;
  ASSERT_TRUE(ServerProcess::Spawn(LOCATORD_PATH,
                                   {"--dataset", "a=uniform:600:1", "--dataset",
                                    "b=" + missing, "--listen", "127.0.0.1:0"},
                                   &server)
                  .ok());
  EXPECT_EQ(server->WaitForExit(kExitTimeout), 1);
  EXPECT_THAT(server->StderrText(),
              HasSubstr("cannot serve dataset b='" + missing + "': NOT_FOUND"));
}

TEST(LocatordDatasetsStartupTest, HealthServesOnceTheLastDatasetServes) {
  std::unique_ptr<ServerProcess> server;
  // The second dataset takes seconds to build; the first serves meanwhile.
  ASSERT_TRUE(
      ServerProcess::Spawn(LOCATORD_PATH,
                           {"--dataset", "small=uniform:2000:1", "--dataset",
                            "big=uniform:300000:2", "--listen", "127.0.0.1:0"},
                           &server)
          .ok());
  ASSERT_TRUE(server->WaitForListening().ok());
  auto stub = NewStub(*server);
  v1::ListDatasetsResponse list;
  ASSERT_TRUE(WaitUntil([&] {
    grpc::ClientContext context;
    list.Clear();
    return stub->ListDatasets(&context, {}, &list).ok() &&
           list.datasets(0).serving();
  }));
  ASSERT_EQ(list.datasets_size(), 2);
  EXPECT_FALSE(list.datasets(1).serving());
  EXPECT_FALSE(list.datasets(1).has_stats());
  HealthStatus health = HealthStatus::kUnknown;
  ASSERT_TRUE(server->CheckHealth(&health).ok());
  EXPECT_EQ(health, HealthStatus::kNotServing);
  v1::LocateResponse located;
  EXPECT_TRUE(LocateOne(*stub, {0.5, 0.5}, &located, "small").ok());
  const grpc::Status loading = LocateOne(*stub, {0.5, 0.5}, &located, "big");
  EXPECT_EQ(loading.error_code(), Code::UNAVAILABLE);
  EXPECT_EQ(loading.error_message(), "dataset 'big' is still loading");

  ASSERT_TRUE(server->WaitUntilServing().ok());
  EXPECT_TRUE(LocateOne(*stub, {0.5, 0.5}, &located, "big").ok());
}

}  // namespace
}  // namespace locator::test
