#include "server/http/json/grid_json.h"

#include <algorithm>
#include <vector>

#include "common/json_writer.h"
#include "common/proto_json.h"
#include "common/status_macros.h"
#include "locator/v1/locator.pb.h"
#include "server/app/surface_convert.h"

namespace locator {
namespace {

// The most a value takes in the text: a sign, 17 digits, a point, an
// exponent such as "e-308", and the comma ("-Infinity" is shorter).
constexpr size_t kMaxBytesPerValue = 25;

}  // namespace

Status GridJson(const Engine& engine, const RasterSpec& spec,
                const CallDeadline& deadline, std::string* json) {
  v1::GridHeader header;
  ToGridHeader(spec, engine.dataset_info().crs, &header);
  JsonWriter out;
  // Reserved, not touched: only the pages written become resident.
  out.Reserve(spec.cells() * kMaxBytesPerValue + 4096);
  out.BeginObject()
      .Key("header")
      .Raw(ProtoJson(header))
      .Key("first_row")
      .Integer(0)
      .Key("rows")
      .Integer(spec.height)
      .Key("values")
      .BeginArray();
  const uint32_t rows_per_block = GridRowsPerBlock(spec);
  std::vector<double> block(size_t{rows_per_block} * spec.width);
  for (uint32_t first = 0; first < spec.height; first += rows_per_block) {
    if (deadline.Passed()) return deadline.ExceededStatus("rendering the grid");
    const uint32_t rows = std::min(rows_per_block, spec.height - first);
    RETURN_IF_ERROR(engine.RenderRows(spec, first, rows, block.data()));
    const size_t values = size_t{rows} * spec.width;
    for (size_t i = 0; i < values; ++i) out.ProtoNumber(block[i]);
  }
  out.EndArray().EndObject();
  *json = out.TakeText();
  return Status::OK();
}

}  // namespace locator
