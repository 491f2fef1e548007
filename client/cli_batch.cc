// `locator batch FILE`: streams FILE through LocateBatch one chunk at a time,
// so memory stays bounded by the chunk size whatever the file's size. Rows
// of chunks already answered are on stdout when a later chunk fails.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "client/cli_commands.h"
#include "client/cli_format.h"
#include "client/points_reader.h"

namespace locator {
namespace {

// Every column of the CSV row is filled from the batch answer.
constexpr BatchColumns kAllColumns{
    .vertex_ids = true, .barycentric = true, .values = true};

// A server that answers fewer rows than asked must not crash the client.
bool IsComplete(const v1::LocateBatchResponse& response, size_t points) {
  const auto has = [](int size, size_t want) {
    return static_cast<size_t>(size) == want;
  };
  return has(response.types_size(), points) &&
         has(response.triangle_ids_size(), points) &&
         has(response.costs_size(), points) &&
         has(response.vertex_ids_size(), 3 * points) &&
         has(response.barycentric_size(), 3 * points) &&
         has(response.values_size(), points);
}

void WriteToStdout(const std::string& text) {
  std::fwrite(text.data(), 1, text.size(), stdout);
}

}  // namespace

int RunBatch(LocatorClient& client, const CliSettings& settings,
             const CliArgs& args) {
  if (args.size() != 1) return ReportUsageError(settings, "batch takes FILE");
  std::unique_ptr<PointsReader> reader;
  Status status = PointsReader::Open(args[0], &reader);
  if (!status.ok()) return ReportInputError(status.message());

  WriteToStdout(BatchCsvHeader());
  std::vector<double> xs, ys;
  v1::LocateBatchResponse response;
  std::string rows;
  while (true) {
    status = reader->ReadChunk(settings.chunk, &xs, &ys);
    if (!status.ok()) return ReportInputError(status.message());
    if (xs.empty()) break;
    const grpc::Status rpc = client.LocateBatch(xs, ys, kAllColumns, &response);
    if (!rpc.ok()) return ReportRpcError(rpc);
    if (!IsComplete(response, xs.size())) {
      return ReportRpcError(grpc::Status(
          grpc::StatusCode::INTERNAL,
          "the server's batch answer does not match the request's " +
              std::to_string(xs.size()) + " points"));
    }
    rows.clear();
    AppendBatchCsvRows(xs, ys, response, &rows);
    WriteToStdout(rows);
  }
  std::fflush(stdout);
  return kExitOk;
}

}  // namespace locator
