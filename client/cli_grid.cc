// `locator grid`: renders a raster with the Grid RPC and writes it through
// GDAL (common/gis/raster_writer.h) as the rows arrive, so the client holds
// one message of rows at a time (a COG is written to a temporary GTiff
// first, on disk). A failed run leaves no raster file behind.

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <span>
#include <string>

#include "client/cli_commands.h"
#include "client/cli_format.h"
#include "client/grid_stream_check.h"
#include "common/status_macros.h"
#include "common/str_cat.h"

namespace locator {
namespace {

// Where the stream's rows go: checked, counted, written.
class GridFile {
 public:
  explicit GridFile(const GridSettings& settings) : settings_(settings) {}

  // Takes the next message; false (with error() set) stops the stream.
  bool Take(const v1::GridResponse& message) {
    error_ = check_.Check(message);
    if (error_.ok() && message.has_header()) error_ = Open(message.header());
    if (error_.ok()) {
      error_ =
          writer_->WriteRows(message.first_row(), message.rows(),
                             std::span<const double>(message.values().data(),
                                                     message.values().size()));
    }
    if (!error_.ok()) return false;
    const double nodata = check_.header().nodata();
    for (double value : message.values()) {
      if (!(value == nodata || (std::isnan(value) && std::isnan(nodata)))) {
        ++cells_with_values_;
      }
    }
    return true;
  }

  // After a stream that ended OK: every row has come and the file is
  // complete.
  Status Finish() {
    RETURN_IF_ERROR(check_.CheckComplete());
    return writer_->Close();
  }

  // Why Take() stopped the stream.
  const Status& error() const { return error_; }
  const v1::GridHeader& header() const { return check_.header(); }
  uint64_t cells_with_values() const { return cells_with_values_; }

 private:
  Status Open(const v1::GridHeader& header) {
    gis::RasterShape shape;
    shape.width = header.width();
    shape.height = header.height();
    shape.box = {header.box().min_x(), header.box().min_y(),
                 header.box().max_x(), header.box().max_y()};
    shape.cell_width = header.cell_width();
    shape.cell_height = header.cell_height();
    shape.nodata = header.nodata();
    shape.crs_wkt = header.crs_wkt();
    return gis::RasterWriter::Open(settings_.out, shape, settings_.format,
                                   &writer_);
  }

  const GridSettings& settings_;
  GridStreamCheck check_;
  std::unique_ptr<gis::RasterWriter> writer_;
  Status error_;
  uint64_t cells_with_values_ = 0;
};

// The request's box: --te, else the dataset's bounding box.
grpc::Status RequestBox(LocatorClient& client, const GridSettings& settings,
                        v1::BoundingBox* box) {
  if (settings.box.has_value()) {
    box->set_min_x(settings.box->min_x);
    box->set_min_y(settings.box->min_y);
    box->set_max_x(settings.box->max_x);
    box->set_max_y(settings.box->max_y);
    return grpc::Status::OK;
  }
  v1::GetStatsResponse stats;
  const grpc::Status status = client.GetStats(&stats);
  if (status.ok()) *box = stats.dataset().bounding_box();
  return status;
}

// A protocol error of the server is an RPC error; a file GDAL cannot write
// is the user's.
int ReportGridError(const Status& error) {
  if (error.code() == Status::Code::kInternal) {
    return ReportRpcError(
        grpc::Status(grpc::StatusCode::INTERNAL, error.message()));
  }
  return ReportInputError(error.message());
}

}  // namespace

int RunGrid(LocatorClient& client, const CliSettings& settings,
            const CliArgs& args) {
  if (!TakesNoArguments(settings, "grid", args)) return kExitUsage;
  const GridSettings& grid = settings.grid;
  const auto start = std::chrono::steady_clock::now();
  v1::GridRequest request;
  if (grpc::Status status = RequestBox(client, grid, request.mutable_box());
      !status.ok()) {
    return ReportRpcError(status);
  }
  request.set_width(grid.width);
  request.set_height(grid.height);
  request.set_cell_size(grid.cell_size);
  if (grid.nodata.has_value()) request.set_nodata(*grid.nodata);

  GridFile file(grid);
  const grpc::Status status = client.Grid(
      request,
      [&file](const v1::GridResponse& message) { return file.Take(message); });
  if (!file.error().ok()) return ReportGridError(file.error());
  if (!status.ok()) return ReportRpcError(status);
  if (Status finished = file.Finish(); !finished.ok()) {
    return ReportGridError(finished);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  const v1::GridHeader& header = file.header();
  std::cout << StrCat(
      {"wrote ", grid.out, ": ", std::to_string(header.width()), " x ",
       std::to_string(header.height()), " ", grid.format.driver, ", ",
       std::to_string(file.cells_with_values()), " cells with values, ",
       FormatFixed(seconds, 2), " s\n"});
  return kExitOk;
}

}  // namespace locator
