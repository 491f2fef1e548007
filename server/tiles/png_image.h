// EncodePng: an 8-bit RGBA, RGB or grey-and-alpha image as a PNG file in
// memory: the chunks written here, the image data deflated by libdeflate.
// Compressed for speed (libdeflate's level 1, the Sub filter, which suits
// smooth terrain), since a tile is made per request.
//
// Thread-safety: safe to call from any thread (each thread keeps its own
// compressor).

#ifndef LOCATOR_SERVER_TILES_PNG_IMAGE_H_
#define LOCATOR_SERVER_TILES_PNG_IMAGE_H_

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "locator/status_or.h"

namespace locator {

// The colour of a pixel: red, green, blue and alpha (terrain), the same
// without alpha (terrain with no transparent pixel: a quarter fewer bytes
// to deflate), or grey and alpha (shaded relief), a byte each.
enum class PngColor { kRgba, kRgb, kGrayAlpha };

// The number of bytes a pixel of `color` takes.
constexpr size_t BytesPerPixel(PngColor color) {
  return color == PngColor::kRgba ? 4 : color == PngColor::kRgb ? 3 : 2;
}

// The PNG of the `width` x `height` image `pixels` (BytesPerPixel(color)
// bytes a pixel, row by row, north first); InvalidArgument if the image is
// empty or `pixels` does not hold width * height pixels, Internal if the
// compressor cannot be made.
StatusOr<std::string> EncodePng(std::span<const uint8_t> pixels, uint32_t width,
                                uint32_t height, PngColor color);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_PNG_IMAGE_H_
