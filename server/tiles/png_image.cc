#include "server/tiles/png_image.h"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <string>
#include <utility>
#include <vector>

namespace locator {
namespace {

// Where libpng's callbacks write: the file so far and libpng's error.
struct PngOutput {
  std::string bytes;
  std::string error;
};

void AppendBytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<PngOutput*>(png_get_io_ptr(png));
  out->bytes.append(reinterpret_cast<const char*>(data), length);
}

void NoFlush(png_structp) {}

// libpng's error callback must not return: it records the message and
// jumps back to EncodePng's setjmp.
[[noreturn]] void RecordError(png_structp png, png_const_charp message) {
  auto* out = static_cast<PngOutput*>(png_get_error_ptr(png));
  out->error = message;
  png_longjmp(png, 1);
}

void IgnoreWarning(png_structp, png_const_charp) {}

}  // namespace

StatusOr<std::string> EncodePng(std::span<const uint8_t> pixels, uint32_t width,
                                uint32_t height, PngColor color) {
  const size_t pixel_bytes = BytesPerPixel(color);
  if (pixels.size() != size_t{width} * height * pixel_bytes) {
    return Status::InvalidArgument(
        "an image of " + std::to_string(width) + " x " +
        std::to_string(height) + " pixels needs " +
        std::to_string(pixel_bytes) + " bytes a pixel");
  }
  PngOutput out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &out,
                                            RecordError, IgnoreWarning);
  if (png == nullptr) return Status::Internal("libpng: out of memory");
  png_infop info = png_create_info_struct(png);
  // Row pointers outlive the jump: made before setjmp, not changed after.
  std::vector<png_bytep> rows(height);
  for (uint32_t r = 0; r < height; ++r) {
    rows[r] =
        const_cast<png_bytep>(pixels.data() + size_t{r} * width * pixel_bytes);
  }
  if (info == nullptr || setjmp(png_jmpbuf(png)) != 0) {
    png_destroy_write_struct(&png, &info);
    return Status::Internal("libpng could not encode the tile: " +
                            (out.error.empty() ? "out of memory" : out.error));
  }
  png_set_write_fn(png, &out, AppendBytes, NoFlush);
  png_set_IHDR(png, info, width, height, 8,
               color == PngColor::kRgba ? PNG_COLOR_TYPE_RGB_ALPHA
                                        : PNG_COLOR_TYPE_GRAY_ALPHA,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(png, Z_BEST_SPEED);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_rows(png, info, rows.data());
  png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::move(out.bytes);
}

}  // namespace locator
