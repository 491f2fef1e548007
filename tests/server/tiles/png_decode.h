// DecodeRgbaPng: a PNG read back to 8-bit RGBA with libpng, for the tests
// of terrain tiles (any PNG libpng reads is expanded to RGBA).

#ifndef LOCATOR_TESTS_SERVER_TILES_PNG_DECODE_H_
#define LOCATOR_TESTS_SERVER_TILES_PNG_DECODE_H_

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "locator/status.h"

namespace locator::test {

struct RgbaImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba;  // 4 bytes a pixel, row by row

  std::array<uint8_t, 3> Rgb(size_t pixel) const {
    return {rgba[4 * pixel], rgba[4 * pixel + 1], rgba[4 * pixel + 2]};
  }
  uint8_t Alpha(size_t pixel) const { return rgba[4 * pixel + 3]; }
};

// Decodes `png`; InvalidArgument with libpng's complaint if it is no PNG.
Status DecodeRgbaPng(std::string_view png, RgbaImage* image);

}  // namespace locator::test

#endif  // LOCATOR_TESTS_SERVER_TILES_PNG_DECODE_H_
