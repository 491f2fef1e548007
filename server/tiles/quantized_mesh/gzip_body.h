// GzipBody: a response body compressed as gzip (RFC 1952) with zlib, for a
// client whose Accept-Encoding takes it.
//
// Thread-safety: a pure function (zlib keeps its state per call).

#ifndef LOCATOR_SERVER_TILES_QUANTIZED_MESH_GZIP_BODY_H_
#define LOCATOR_SERVER_TILES_QUANTIZED_MESH_GZIP_BODY_H_

#include <string>
#include <string_view>

#include "locator/status_or.h"

namespace locator {

// `body` gzipped (zlib level 6); Internal with zlib's message if zlib fails.
StatusOr<std::string> GzipBody(std::string_view body);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_QUANTIZED_MESH_GZIP_BODY_H_
