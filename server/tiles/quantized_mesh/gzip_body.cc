#include "server/tiles/quantized_mesh/gzip_body.h"

#include <zlib.h>

namespace locator {

StatusOr<std::string> GzipBody(std::string_view body) {
  z_stream stream{};
  // 15 + 16: a window of 2^15 with a gzip header and trailer.
  if (deflateInit2(&stream, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) !=
      Z_OK) {
    return Status::Internal("zlib could not start gzip");
  }
  std::string out(deflateBound(&stream, body.size()), '\0');
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(body.data()));
  stream.avail_in = static_cast<uInt>(body.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int result = deflate(&stream, Z_FINISH);
  const std::string message = stream.msg != nullptr ? stream.msg : "";
  deflateEnd(&stream);
  if (result != Z_STREAM_END) {
    return Status::Internal("zlib could not gzip a body of " +
                            std::to_string(body.size()) + " bytes: " + message);
  }
  out.resize(stream.total_out);
  return out;
}

}  // namespace locator
