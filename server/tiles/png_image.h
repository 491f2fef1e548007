// EncodeRgbaPng: an 8-bit RGBA image as a PNG file in memory, with libpng.
// Compressed for speed (zlib level 1, the Sub filter, which suits smooth
// terrain), since a tile is made per request.
//
// Thread-safety: a pure function (libpng keeps its state per call).

#ifndef LOCATOR_SERVER_TILES_PNG_IMAGE_H_
#define LOCATOR_SERVER_TILES_PNG_IMAGE_H_

#include <cstdint>
#include <span>
#include <string>

#include "locator/status_or.h"

namespace locator {

// The PNG of the `width` x `height` image `rgba` (4 bytes a pixel, row by
// row, north first); Internal with libpng's message if libpng fails,
// InvalidArgument if `rgba` does not hold width * height pixels.
StatusOr<std::string> EncodeRgbaPng(std::span<const uint8_t> rgba,
                                    uint32_t width, uint32_t height);

}  // namespace locator

#endif  // LOCATOR_SERVER_TILES_PNG_IMAGE_H_
