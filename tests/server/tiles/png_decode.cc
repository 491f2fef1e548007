#include "tests/server/tiles/png_decode.h"

#include <png.h>

#include <cstring>
#include <string>

namespace locator::test {

Status DecodeRgbaPng(std::string_view png, RgbaImage* image) {
  png_image decoder;
  std::memset(&decoder, 0, sizeof decoder);
  decoder.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&decoder, png.data(), png.size())) {
    return Status::InvalidArgument(std::string("not a PNG: ") +
                                   decoder.message);
  }
  decoder.format = PNG_FORMAT_RGBA;
  image->width = decoder.width;
  image->height = decoder.height;
  image->rgba.assign(PNG_IMAGE_SIZE(decoder), 0);
  if (!png_image_finish_read(&decoder, nullptr, image->rgba.data(), 0,
                             nullptr)) {
    const std::string message = decoder.message;
    png_image_free(&decoder);
    return Status::InvalidArgument("bad PNG: " + message);
  }
  return Status::OK();
}

}  // namespace locator::test
