#include "tests/server/main/hostile/hostile_server.h"

#include <google/protobuf/util/json_util.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <random>

#include "client/locator_client.h"
#include "common/gis/ogr_dataset.h"
#include "tests/common/gis/gis_fixtures.h"
#include "tests/server/http/http_test_client.h"
#include "tests/testing/process_memory.h"

namespace locator::test {
namespace {

constexpr int kHillSide = 15;  // 225 points, 400 m apart

// `bytes` of the server's memory as /proc gave them, if they mean something:
// not under a sanitizer, whose allocator keeps freed memory, and not 0
// (/proc said nothing).
std::optional<uint64_t> Meaningful(uint64_t bytes) {
#if defined(LOCATOR_SANITIZED_SERVER)
  (void)bytes;
  return std::nullopt;
#else
  return bytes > 0 ? std::optional<uint64_t>(bytes) : std::nullopt;
#endif
}

std::unique_ptr<Reference> ReferenceOf(Dataset dataset) {
  std::unique_ptr<Reference> reference;
  const Status built = Reference::FromDataset(std::move(dataset), &reference);
  EXPECT_TRUE(built.ok()) << built.ToString();
  return reference;
}

}  // namespace

// The slowest call the test makes on purpose (a grid at the cell limit with
// natural-neighbour interpolation) takes well under a second in a Release
// build, so that a call still running at its deadline hangs, even on a
// loaded machine. The server holds HTTP calls to it (--default-deadline-ms).
std::chrono::milliseconds HostileServer::CallDeadline() {
#if defined(LOCATOR_SANITIZED_SERVER)
  return std::chrono::seconds(30);
#else
  return std::chrono::seconds(10);
#endif
}

std::chrono::milliseconds HostileServer::ControlDeadline() {
  return CallDeadline() / 2;
}

std::unique_ptr<HostileServer> HostileServer::Create() {
  std::unique_ptr<HostileServer> server(new HostileServer());
  HostileServer& s = *server;
  s.reload_dir_ = s.scratch_.path() + "/reload";
  s.outside_dir_ = s.scratch_.path() + "/outside";
  for (const std::string& dir : {s.reload_dir_, s.outside_dir_}) {
    if (mkdir(dir.c_str(), 0755) != 0) ADD_FAILURE() << "mkdir " << dir;
  }
  s.gpkg_ = gis::testing::UtmHillGeoPackage(kHillSide, s.reload_dir_);
  // A FIFO in the reload directory (a Reload may name it) that nobody
  // writes: opening it for reading blocks for ever.
  s.fifo_ = s.reload_dir_ + "/fifo.csv";
  if (mkfifo(s.fifo_.c_str(), 0644) != 0) ADD_FAILURE() << "mkfifo";
  s.secret_ = s.outside_dir_ + "/secret.db";
  gis::testing::WriteFile(s.secret_, "the secret\n");
  s.outside_watch_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (inotify_add_watch(
          s.outside_watch_, s.outside_dir_.c_str(),
          IN_OPEN | IN_ACCESS | IN_CREATE | IN_MODIFY | IN_MOVED_TO) < 0) {
    ADD_FAILURE() << "cannot watch " << s.outside_dir_;
  }
  std::string garbage(4096, '\0');
  std::mt19937_64 rng(26);
  for (char& c : garbage) c = static_cast<char>(rng());
  gis::testing::WriteFile(s.reload_dir_ + "/garbage.gpkg", garbage);

  StatusOr<Dataset> plain = LoadDataset(s.csv_.path());
  if (!plain.ok()) {
    ADD_FAILURE() << plain.status().ToString();
    return nullptr;
  }
  Dataset hill;
  if (Status loaded = gis::LoadOgrDataset(s.gpkg_, &hill); !loaded.ok()) {
    ADD_FAILURE() << loaded.ToString();
    return nullptr;
  }
  s.plain_ = std::make_unique<DatasetOracle>(
      "plain", ReferenceOf(*std::move(plain)), /*plane=*/true);
  s.utm_ = std::make_unique<DatasetOracle>("utm", ReferenceOf(std::move(hill)),
                                           /*plane=*/false);
  s.request_crs_ =
      RequestCrsList(s.fifo_, s.secret_, gis::testing::EpsgWkt2(32633),
                     gis::testing::EpsgWkt2(4326));

  s.flags_ = {"--dataset",
              "utm=" + s.gpkg_,
              "--reload-dir",
              s.reload_dir_,
              "--max-batch-points",
              std::to_string(HostileLimits::kBatchPoints),
              "--max-profile-crossings",
              std::to_string(HostileLimits::kProfileCrossings),
              "--max-profile-samples",
              std::to_string(HostileLimits::kProfileSamples),
              "--max-grid-cells",
              std::to_string(HostileLimits::kGridCells),
              "--http-max-grid-cells",
              std::to_string(HostileLimits::kHttpGridCells),
              "--max-message-bytes",
              std::to_string(HostileLimits::kMessageBytes),
              "--http-max-body-bytes",
              std::to_string(HostileLimits::kHttpBodyBytes),
              "--max-dataset-points",
              std::to_string(HostileLimits::kDatasetPoints),
              "--http-cors-origin",
              kCorsOrigin,
              "--default-deadline-ms",
              std::to_string(CallDeadline().count()),
              "--threads",
              "2"};
  if (Status started = s.Start(); !started.ok()) {
    ADD_FAILURE() << started.ToString();
    return nullptr;
  }
  return server;
}

HostileServer::~HostileServer() {
  if (outside_watch_ >= 0) close(outside_watch_);
}

std::string HostileServer::TouchedOutside() {
  alignas(inotify_event) char buffer[4096];
  std::string touched;
  for (ssize_t n; (n = read(outside_watch_, buffer, sizeof buffer)) > 0;) {
    for (ssize_t at = 0; at < n;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      at += sizeof(inotify_event) + event->len;
      if ((event->mask & IN_ISDIR) != 0) continue;
      const char* what = (event->mask & IN_OPEN)     ? "opened "
                         : (event->mask & IN_ACCESS) ? "read "
                         : (event->mask & IN_CREATE) ? "created "
                                                     : "wrote ";
      const std::string entry =
          what + std::string(event->len > 0 ? event->name : "?");
      if (touched.find(entry) == std::string::npos) {
        touched += (touched.empty() ? "" : ", ") + entry;
      }
    }
  }
  return touched.empty() ? "" : "the server " + touched + " in " + outside_dir_;
}

Status HostileServer::Start() {
  Status status =
      LocatordWithHttp::Start("plain=" + csv_.path(), flags_, &server_);
  if (status.ok()) status = server_->WaitUntilServes("utm");
  if (!status.ok()) return status;
  stub_ = v1::Locator::NewStub(CreateLocatorChannel(
      {.target = server_->grpc_target(), .own_connection = true}));
  for (DatasetOracle* oracle : {plain_.get(), utm_.get()}) {
    grpc::ClientContext context;
    SetDeadlineFromNow(&context, ControlDeadline());
    v1::GetStatsRequest request;
    request.set_dataset(oracle->name());
    v1::GetStatsResponse stats;
    const grpc::Status got = stub_->GetStats(&context, request, &stats);
    if (!got.ok()) return Status::Unavailable(got.error_message());
    oracle->SetServedTriangles(stats.dataset().triangles());
  }
  return Status::OK();
}

const DatasetOracle* HostileServer::OracleFor(const std::string& name) const {
  if (name.empty() || name == plain_->name()) return plain_.get();
  if (name == utm_->name()) return utm_.get();
  return nullptr;
}

std::string HostileServer::Control() {
  if (server_ == nullptr) return "no server";
  if (const auto exit =
          server_->process().WaitForExit(std::chrono::milliseconds(0))) {
    return "the server exited with " + std::to_string(*exit) + "; stderr:\n" +
           server_->process().StderrText().substr(0, 4000);
  }
  for (const DatasetOracle* oracle : {plain_.get(), utm_.get()}) {
    const Point2 q = oracle->Inside(0.37, 0.61);
    grpc::ClientContext context;
    SetDeadlineFromNow(&context, ControlDeadline());
    v1::LocateResponse response;
    const grpc::Status status =
        stub_->Locate(&context, LocateRequestFor(q, oracle->name()), &response);
    if (!status.ok()) {
      return "the control Locate on " + oracle->name() +
             " failed: " + std::to_string(status.error_code()) + " " +
             status.error_message().substr(0, 300);
    }
    const std::string problem = oracle->CheckLocation(
        q, v1::INTERPOLATION_LINEAR, FromLocateResponse(response), {});
    if (!problem.empty()) {
      return "the control Locate on " + oracle->name() + ": " + problem;
    }
  }
  // The HTTP API has threads of its own, which a call may hang apart from
  // gRPC's.
  const Point2 q = plain_->Inside(0.37, 0.61);
  std::string body;
  if (!google::protobuf::util::MessageToJsonString(LocateRequestFor(q), &body)
           .ok()) {
    return "cannot print the control request";
  }
  HttpReply reply;
  const Status sent =
      SendHttp(http_port(), "POST", "/v1/datasets/plain:locate", &reply, body,
               {{"Content-Type", "application/json"}});
  v1::LocateResponse response;
  if (!sent.ok() || reply.status != 200 ||
      !google::protobuf::util::JsonStringToMessage(reply.body, &response)
           .ok()) {
    return "the control :locate over HTTP failed: " + sent.ToString() +
           " HTTP " + std::to_string(reply.status) + " " +
           reply.body.substr(0, 300);
  }
  const std::string problem = plain_->CheckLocation(
      q, v1::INTERPOLATION_LINEAR, FromLocateResponse(response), {});
  return problem.empty() ? "" : "the control :locate over HTTP: " + problem;
}

Status HostileServer::Restart() {
  if (server_ != nullptr) server_->process().SendSignal(SIGKILL);
  stub_.reset();
  server_.reset();
  return Start();
}

std::optional<uint64_t> HostileServer::ResidentBytes() const {
  if (server_ == nullptr) return std::nullopt;
  return Meaningful(test::ResidentBytes(server_->process().pid()));
}

std::optional<uint64_t> HostileServer::PeakResidentBytes() const {
  if (server_ == nullptr) return std::nullopt;
  return Meaningful(test::PeakResidentBytes(server_->process().pid()));
}

}  // namespace locator::test
