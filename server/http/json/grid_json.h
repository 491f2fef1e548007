// GridJson: the HTTP/JSON answer to a Grid call: one GridResponse holding
// the header and every row (first_row 0, rows = height), in protobuf's JSON
// mapping as ProtoJson prints it (NaN and infinities as strings), rendered
// and printed block by block (GridRowsPerBlock rows at a time), so
// that the only thing held whole is the text itself: building a
// GridResponse and printing it with protobuf took about 300 bytes per cell
// at its peak, this takes the text's ~20. It stops between blocks once the
// call's deadline has passed.
//
// Thread-safety: a pure function of its arguments (the engine is
// thread-safe).

#ifndef LOCATOR_SERVER_HTTP_GRID_JSON_H_
#define LOCATOR_SERVER_HTTP_GRID_JSON_H_

#include <string>

#include "locator/engine.h"
#include "locator/raster.h"
#include "locator/status.h"
#include "server/serving/call_deadline.h"

namespace locator {

// Renders `spec` (checked) with `engine` into `json`; DEADLINE_EXCEEDED if
// `deadline` passes first, or the engine's error.
Status GridJson(const Engine& engine, const RasterSpec& spec,
                const CallDeadline& deadline, std::string* json);

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_GRID_JSON_H_
