#include "tests/client/fake_locator_server.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>

#include "common/mutex.h"

namespace locator::test {

double FakeSurface(double x, double y) { return 1000 + x + 2 * y; }

double FakeGridValue(uint32_t col, uint32_t row, double nodata) {
  if ((col + row) % 5 == 0) return nodata;
  return row * 1000.0 + col + 0.5;
}

v1::ListDatasetsResponse FakeDatasetList() {
  v1::ListDatasetsResponse response;
  v1::DatasetEntry* terrain = response.add_datasets();
  terrain->set_name("terrain");
  terrain->set_is_default(true);
  terrain->set_serving(true);
  terrain->mutable_stats()->set_input_points(225);
  terrain->mutable_stats()->set_triangles(416);
  terrain->mutable_stats()->mutable_crs()->set_name("WGS 84 / UTM zone 33N");
  terrain->mutable_stats()->mutable_crs()->set_epsg_code(32633);
  response.add_datasets()->set_name("bedrock");
  return response;
}

v1::ProfileResponse FakeProfile(const v1::ProfileRequest& request) {
  v1::ProfileResponse response;
  const auto& vertices = request.vertices();
  std::vector<double> along = {0};  // distance of each vertex
  for (int i = 1; i < vertices.size(); ++i) {
    along.push_back(along.back() +
                    std::hypot(vertices[i].x() - vertices[i - 1].x(),
                               vertices[i].y() - vertices[i - 1].y()));
  }
  const double length = along.back();
  const double gap_from = 0.75 * length;
  response.set_length(length);
  const auto point_at = [&](v1::ProfilePoint* point, v1::ProfilePointKind kind,
                            double distance) {
    // The segment the distance lies on, and where on it.
    int segment = 0;
    while (segment + 2 < vertices.size() && along[segment + 1] <= distance) {
      ++segment;
    }
    const double span = along[segment + 1] - along[segment];
    const double t = span > 0 ? (distance - along[segment]) / span : 0;
    const v1::Point& a = vertices[segment];
    const v1::Point& b = vertices[segment + 1];
    point->set_kind(kind);
    point->mutable_point()->set_x(a.x() + t * (b.x() - a.x()));
    point->mutable_point()->set_y(a.y() + t * (b.y() - a.y()));
    point->set_distance(distance);
    point->set_segment(segment);
    const bool in_gap = distance >= gap_from;
    point->set_triangle_id(in_gap ? -1 : segment);
    if (!in_gap) {
      point->set_value(FakeSurface(point->point().x(), point->point().y()));
    }
  };
  for (int i = 0; i < vertices.size(); ++i) {
    if (i > 0) {
      point_at(response.add_breakpoints(), v1::PROFILE_POINT_KIND_EDGE_CROSSING,
               (along[i - 1] + along[i]) / 2);
    }
    point_at(response.add_breakpoints(), v1::PROFILE_POINT_KIND_LINE_VERTEX,
             along[i]);
  }
  for (int i = 0; i < response.breakpoints_size(); ++i) {
    v1::ProfilePoint* point = response.mutable_breakpoints(i);
    if (point->has_value()) point->set_triangle_id(i);
  }
  response.set_crossings(vertices.size() - 1);
  for (uint32_t i = 0; i < request.samples(); ++i) {
    const double distance =
        request.samples() == 1 ? 0 : length * i / (request.samples() - 1);
    point_at(response.add_samples(), v1::PROFILE_POINT_KIND_SAMPLE, distance);
  }
  v1::ProfileGap* gap = response.add_gaps();
  gap->set_from_distance(gap_from);
  gap->set_to_distance(length);
  gap->set_reason(v1::LOCATION_TYPE_OUTSIDE_CONVEX_HULL);
  return response;
}

namespace {

// The Grid header a request asks for.
grpc::Status GridHeaderFor(const v1::GridRequest& request,
                           const std::string& crs_wkt, v1::GridHeader* header) {
  v1::BoundingBox box = request.box();
  if (request.width() > 0 && request.height() > 0) {
    header->set_width(request.width());
    header->set_height(request.height());
    header->set_cell_width((box.max_x() - box.min_x()) / request.width());
    header->set_cell_height((box.max_y() - box.min_y()) / request.height());
  } else if (request.cell_size() > 0) {
    const double cell = request.cell_size();
    header->set_width(
        static_cast<uint32_t>(std::ceil((box.max_x() - box.min_x()) / cell)));
    header->set_height(
        static_cast<uint32_t>(std::ceil((box.max_y() - box.min_y()) / cell)));
    box.set_max_x(box.min_x() + header->width() * cell);
    box.set_min_y(box.max_y() - header->height() * cell);
    header->set_cell_width(cell);
    header->set_cell_height(cell);
  } else {
    return grpc::Status(grpc::StatusCode::INVALID_ARGUMENT,
                        "width and height, or cell_size, are required");
  }
  *header->mutable_box() = box;
  header->set_nodata(request.has_nodata()
                         ? request.nodata()
                         : std::numeric_limits<double>::quiet_NaN());
  header->set_crs_wkt(crs_wkt);
  return grpc::Status::OK;
}

}  // namespace

class FakeLocatorServer::Service final : public v1::Locator::Service {
 public:
  explicit Service(std::string crs_wkt) : crs_wkt_(std::move(crs_wkt)) {}

  grpc::Status Locate(grpc::ServerContext*, const v1::LocateRequest* request,
                      v1::LocateResponse* response) override {
    Record(&last_locate_, *request);
    Answer(request->point(), response);
    return grpc::Status::OK;
  }

  grpc::Status LocateBatch(grpc::ServerContext*,
                           const v1::LocateBatchRequest* request,
                           v1::LocateBatchResponse* response) override {
    Record(&last_locate_batch_, *request);
    for (int i = 0; i < request->xs_size(); ++i) {
      response->add_types(v1::LOCATION_TYPE_FACE);
      response->add_triangle_ids(1);
      response->add_costs(1);
      for (int k = 0; k < 3; ++k) {
        if (request->include_vertex_ids()) response->add_vertex_ids(k);
        if (request->include_barycentric()) response->add_barycentric(1.0 / 3);
      }
      if (request->include_values()) {
        response->add_values(FakeSurface(request->xs(i), request->ys(i)));
      }
    }
    response->set_total_cost(request->xs_size());
    return grpc::Status::OK;
  }

  grpc::Status LocateStream(
      grpc::ServerContext*,
      grpc::ServerReaderWriter<v1::LocateResponse, v1::LocateRequest>* stream)
      override {
    v1::LocateRequest request;
    while (stream->Read(&request)) {
      {
        MutexLock lock(&mu_);
        ++calls_;
        stream_requests_.push_back(request);
      }
      v1::LocateResponse response;
      Answer(request.point(), &response);
      if (!stream->Write(response)) break;
    }
    return grpc::Status::OK;
  }

  grpc::Status GetStats(grpc::ServerContext*,
                        const v1::GetStatsRequest* request,
                        v1::GetStatsResponse* response) override {
    Record(&last_get_stats_, *request);
    response->mutable_dataset()->set_source("fake");
    v1::BoundingBox* box = response->mutable_dataset()->mutable_bounding_box();
    box->set_min_x(kFakeBox[0]);
    box->set_min_y(kFakeBox[1]);
    box->set_max_x(kFakeBox[2]);
    box->set_max_y(kFakeBox[3]);
    return grpc::Status::OK;
  }

  grpc::Status Retune(grpc::ServerContext*, const v1::RetuneRequest* request,
                      v1::RetuneResponse*) override {
    Record(&last_retune_, *request);
    return grpc::Status::OK;
  }

  grpc::Status Reload(grpc::ServerContext*, const v1::ReloadRequest* request,
                      v1::ReloadResponse* response) override {
    Record(&last_reload_, *request);
    response->mutable_dataset()->set_source(request->spec());
    response->set_generation(2);
    return grpc::Status::OK;
  }

  grpc::Status ListDatasets(grpc::ServerContext*,
                            const v1::ListDatasetsRequest*,
                            v1::ListDatasetsResponse* response) override {
    {
      MutexLock lock(&mu_);
      ++calls_;
    }
    *response = FakeDatasetList();
    return grpc::Status::OK;
  }

  grpc::Status Profile(grpc::ServerContext*, const v1::ProfileRequest* request,
                       v1::ProfileResponse* response) override {
    Record(&last_profile_, *request);
    grpc::Status failure;
    {
      MutexLock lock(&mu_);
      failure = std::exchange(profile_failure_, grpc::Status::OK);
    }
    if (!failure.ok()) return failure;
    *response = FakeProfile(*request);
    return grpc::Status::OK;
  }

  grpc::Status Grid(grpc::ServerContext*, const v1::GridRequest* request,
                    grpc::ServerWriter<v1::GridResponse>* writer) override {
    Record(&last_grid_, *request);
    grpc::Status failure;
    GridFault fault;
    {
      MutexLock lock(&mu_);
      failure = std::exchange(grid_failure_, grpc::Status::OK);
      fault = std::exchange(grid_fault_, GridFault::kNone);
    }
    if (!failure.ok() && fault == GridFault::kNone) return failure;
    v1::GridHeader header;
    if (grpc::Status status = GridHeaderFor(*request, crs_wkt_, &header);
        !status.ok()) {
      return status;
    }
    std::vector<uint32_t> firsts;  // the last rows first
    for (uint32_t row = 0; row < header.height(); row += kGridRowsPerMessage) {
      firsts.insert(firsts.begin(), row);
    }
    for (size_t i = 0; i < firsts.size(); ++i) {
      if (fault == GridFault::kDropLastMessage && i + 1 == firsts.size()) break;
      v1::GridResponse message;
      if (i == 0) *message.mutable_header() = header;
      const uint32_t rows =
          std::min(kGridRowsPerMessage, header.height() - firsts[i]);
      message.set_first_row(firsts[i]);
      message.set_rows(rows);
      for (uint32_t row = firsts[i]; row < firsts[i] + rows; ++row) {
        for (uint32_t col = 0; col < header.width(); ++col) {
          message.add_values(FakeGridValue(col, row, header.nodata()));
        }
      }
      if (!writer->Write(message)) break;
      if (fault == GridFault::kFailAfterFirstMessage) return failure;
    }
    return grpc::Status::OK;
  }

  template <typename Request>
  Request Last(const Request Service::*member) const {
    MutexLock lock(&mu_);
    return this->*member;
  }

  mutable Mutex mu_;
  const std::string crs_wkt_;
  uint64_t calls_ GUARDED_BY(mu_) = 0;
  v1::LocateRequest last_locate_ GUARDED_BY(mu_);
  v1::LocateBatchRequest last_locate_batch_ GUARDED_BY(mu_);
  std::vector<v1::LocateRequest> stream_requests_ GUARDED_BY(mu_);
  v1::GetStatsRequest last_get_stats_ GUARDED_BY(mu_);
  v1::RetuneRequest last_retune_ GUARDED_BY(mu_);
  v1::ReloadRequest last_reload_ GUARDED_BY(mu_);
  v1::ProfileRequest last_profile_ GUARDED_BY(mu_);
  v1::GridRequest last_grid_ GUARDED_BY(mu_);
  grpc::Status profile_failure_ GUARDED_BY(mu_);
  grpc::Status grid_failure_ GUARDED_BY(mu_);
  GridFault grid_fault_ GUARDED_BY(mu_) = GridFault::kNone;

 private:
  template <typename Request>
  void Record(Request* last, const Request& request) EXCLUDES(mu_) {
    MutexLock lock(&mu_);
    ++calls_;
    *last = request;
  }

  static void Answer(const v1::Point& point, v1::LocateResponse* response) {
    response->set_type(v1::LOCATION_TYPE_FACE);
    response->set_triangle_id(1);
    response->set_value(FakeSurface(point.x(), point.y()));
    response->mutable_cost()->set_total(1);
  }
};

FakeLocatorServer::FakeLocatorServer(std::string crs_wkt)
    : service_(std::make_unique<Service>(std::move(crs_wkt))) {
  grpc::ServerBuilder builder;
  int port = 0;
  builder.AddListeningPort("127.0.0.1:0", grpc::InsecureServerCredentials(),
                           &port);
  builder.RegisterService(service_.get());
  server_ = builder.BuildAndStart();
  EXPECT_NE(server_, nullptr) << "the fake server did not start";
  EXPECT_GT(port, 0);
  target_ = "127.0.0.1:" + std::to_string(port);
}

FakeLocatorServer::~FakeLocatorServer() {
  if (server_ != nullptr) {
    server_->Shutdown();
    server_->Wait();
  }
}

void FakeLocatorServer::FailNextProfile(const grpc::Status& status) {
  MutexLock lock(&service_->mu_);
  service_->profile_failure_ = status;
}

void FakeLocatorServer::FailNextGrid(const grpc::Status& status,
                                     GridFault fault) {
  MutexLock lock(&service_->mu_);
  service_->grid_failure_ = status;
  service_->grid_fault_ = fault;
}

v1::LocateRequest FakeLocatorServer::last_locate() const {
  return service_->Last(&Service::last_locate_);
}
v1::LocateBatchRequest FakeLocatorServer::last_locate_batch() const {
  return service_->Last(&Service::last_locate_batch_);
}
std::vector<v1::LocateRequest> FakeLocatorServer::stream_requests() const {
  return service_->Last(&Service::stream_requests_);
}
v1::GetStatsRequest FakeLocatorServer::last_get_stats() const {
  return service_->Last(&Service::last_get_stats_);
}
v1::RetuneRequest FakeLocatorServer::last_retune() const {
  return service_->Last(&Service::last_retune_);
}
v1::ReloadRequest FakeLocatorServer::last_reload() const {
  return service_->Last(&Service::last_reload_);
}
v1::ProfileRequest FakeLocatorServer::last_profile() const {
  return service_->Last(&Service::last_profile_);
}
v1::GridRequest FakeLocatorServer::last_grid() const {
  return service_->Last(&Service::last_grid_);
}
uint64_t FakeLocatorServer::calls() const {
  MutexLock lock(&service_->mu_);
  return service_->calls_;
}

}  // namespace locator::test
