#include "server/tiles/png_image.h"

#include <libdeflate.h>

#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace locator {
namespace {

// libdeflate's level 1: twice zlib's level-1 speed on terrain tiles, and
// smaller output.
constexpr int kCompressionLevel = 1;
// PNG's filter type for a row: each byte minus the same byte of the pixel
// to its left.
constexpr uint8_t kFilterSub = 1;

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const {
    libdeflate_free_compressor(c);
  }
};

// The thread's compressor: made once (it holds ~0.5 MB of tables), and
// used by one call at a time.
libdeflate_compressor* ThreadCompressor() {
  thread_local std::unique_ptr<libdeflate_compressor, CompressorDeleter>
      compressor(libdeflate_alloc_compressor(kCompressionLevel));
  return compressor.get();
}

void AppendBigEndian(uint32_t value, std::string* out) {
  const std::array<char, 4> bytes = {
      static_cast<char>(value >> 24), static_cast<char>(value >> 16),
      static_cast<char>(value >> 8), static_cast<char>(value)};
  out->append(bytes.data(), bytes.size());
}

// Appends the chunk `type` (4 letters) with `data`: length, type, data,
// and the CRC-32 of type and data.
void AppendChunk(std::string_view type, std::string_view data,
                 std::string* out) {
  AppendBigEndian(static_cast<uint32_t>(data.size()), out);
  const size_t type_at = out->size();
  out->append(type);
  out->append(data);
  AppendBigEndian(static_cast<uint32_t>(libdeflate_crc32(
                      0, out->data() + type_at, out->size() - type_at)),
                  out);
}

// The image's rows as PNG's filtered scanlines: each row a filter byte
// (Sub) and the row's bytes, each minus its left neighbour's.
std::vector<uint8_t> SubFilteredRows(std::span<const uint8_t> pixels,
                                     size_t row_bytes, size_t pixel_bytes) {
  const size_t rows = pixels.size() / row_bytes;
  std::vector<uint8_t> filtered(rows * (row_bytes + 1));
  uint8_t* out = filtered.data();
  for (size_t r = 0; r < rows; ++r) {
    const uint8_t* row = pixels.data() + r * row_bytes;
    *out++ = kFilterSub;
    for (size_t i = 0; i < pixel_bytes; ++i) *out++ = row[i];
    for (size_t i = pixel_bytes; i < row_bytes; ++i) {
      *out++ = static_cast<uint8_t>(row[i] - row[i - pixel_bytes]);
    }
  }
  return filtered;
}

}  // namespace

StatusOr<std::string> EncodePng(std::span<const uint8_t> pixels, uint32_t width,
                                uint32_t height, PngColor color) {
  const size_t pixel_bytes = BytesPerPixel(color);
  if (width == 0 || height == 0 ||
      pixels.size() != size_t{width} * height * pixel_bytes) {
    return Status::InvalidArgument(
        "an image of " + std::to_string(width) + " x " +
        std::to_string(height) + " pixels needs " +
        std::to_string(pixel_bytes) + " bytes a pixel, and at least one pixel");
  }
  libdeflate_compressor* compressor = ThreadCompressor();
  if (compressor == nullptr)
    return Status::Internal("libdeflate: out of memory");
  const std::vector<uint8_t> filtered =
      SubFilteredRows(pixels, size_t{width} * pixel_bytes, pixel_bytes);
  std::string compressed(
      libdeflate_zlib_compress_bound(compressor, filtered.size()), '\0');
  const size_t compressed_size =
      libdeflate_zlib_compress(compressor, filtered.data(), filtered.size(),
                               compressed.data(), compressed.size());
  if (compressed_size == 0) {
    return Status::Internal("libdeflate could not compress the image");
  }
  compressed.resize(compressed_size);

  // PNG's colour types: 6 is RGB with alpha, 2 RGB, 4 grey with alpha.
  const uint8_t color_type = color == PngColor::kRgba  ? 6
                             : color == PngColor::kRgb ? 2
                                                       : 4;
  std::string header;
  AppendBigEndian(width, &header);
  AppendBigEndian(height, &header);
  // Bit depth 8, the colour type, deflate, adaptive filtering, no interlace.
  header += {8, static_cast<char>(color_type), 0, 0, 0};

  std::string png = "\x89PNG\r\n\x1a\n";
  png.reserve(png.size() + compressed.size() + 64);
  AppendChunk("IHDR", header, &png);
  AppendChunk("IDAT", compressed, &png);
  AppendChunk("IEND", {}, &png);
  return png;
}

}  // namespace locator
