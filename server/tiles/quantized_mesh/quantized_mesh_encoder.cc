#include "server/tiles/quantized_mesh/quantized_mesh_encoder.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "server/tiles/quantized_mesh/wgs84.h"

namespace locator {
namespace {

constexpr uint32_t kUnused = 0xffffffffu;

// Appends little-endian bytes of plain values.
class ByteWriter {
 public:
  template <typename T>
  void Put(T value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) {
      std::reverse(bytes, bytes + sizeof(T));
    }
    out_.append(reinterpret_cast<const char*>(bytes), sizeof(T));
  }
  // An index in the file's index width.
  void PutIndex(uint32_t index, bool wide) {
    if (wide) {
      Put<uint32_t>(index);
    } else {
      Put<uint16_t>(static_cast<uint16_t>(index));
    }
  }
  void PadTo(size_t alignment) {
    while (out_.size() % alignment != 0) out_.push_back('\0');
  }
  std::string Take() { return std::move(out_); }

 private:
  std::string out_;
};

uint16_t ZigZag(int value) {
  return static_cast<uint16_t>((value << 1) ^ (value >> 31));
}

uint16_t Quantize(double value, double low, double high) {
  if (!(high > low)) return 0;
  const double q = std::round((value - low) / (high - low) * kQuantizedMax);
  return static_cast<uint16_t>(std::clamp(q, 0.0, double{kQuantizedMax}));
}

double Dequantize(uint16_t q, double low, double high) {
  return low + q * (high - low) / kQuantizedMax;
}

}  // namespace

std::string EncodeQuantizedMesh(const ClippedMesh& mesh,
                                const BoundingBox& box) {
  // Vertices in the order the triangles first use them, as the
  // high-water-mark encoding needs.
  std::vector<uint32_t> order, number(mesh.size(), kUnused);
  for (const auto& t : mesh.triangles) {
    for (uint32_t v : t) {
      if (number[v] != kUnused) continue;
      number[v] = static_cast<uint32_t>(order.size());
      order.push_back(v);
    }
  }
  double low = 0, high = 0;
  if (!order.empty()) {
    low = high = mesh.heights[order[0]];
    for (uint32_t v : order) {
      low = std::min(low, mesh.heights[v]);
      high = std::max(high, mesh.heights[v]);
    }
  }
  // The header holds floats: round them outwards.
  float low_f = static_cast<float>(low), high_f = static_cast<float>(high);
  if (low_f > low) low_f = std::nextafter(low_f, -INFINITY);
  if (high_f < high) high_f = std::nextafter(high_f, INFINITY);

  const size_t n = order.size();
  std::vector<std::array<uint16_t, 3>> q(n);
  std::vector<Vec3> ecef(n);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t v = order[i];
    const Point2& p = mesh.points[v];
    const uint8_t sides = mesh.sides[v];
    uint16_t u = Quantize(p.x, box.min_x, box.max_x);
    uint16_t w = Quantize(p.y, box.min_y, box.max_y);
    if (sides & kWestSide) u = 0;
    if (sides & kEastSide) u = kQuantizedMax;
    if (sides & kSouthSide) w = 0;
    if (sides & kNorthSide) w = kQuantizedMax;
    q[i] = {u, w, Quantize(mesh.heights[v], low_f, high_f)};
    ecef[i] = GeodeticToEcef(Dequantize(u, box.min_x, box.max_x),
                             Dequantize(w, box.min_y, box.max_y),
                             Dequantize(q[i][2], low_f, high_f));
  }
  Sphere sphere = BoundingSphere(ecef);
  if (n == 0) {
    sphere.centre = GeodeticToEcef((box.min_x + box.max_x) / 2,
                                   (box.min_y + box.max_y) / 2, 0);
  }
  const Vec3 occlusion = HorizonOcclusionPoint(ecef, sphere.centre);

  ByteWriter out;
  for (double c : sphere.centre) out.Put<double>(c);
  out.Put<float>(low_f);
  out.Put<float>(high_f);
  for (double c : sphere.centre) out.Put<double>(c);
  out.Put<double>(sphere.radius);
  for (double c : occlusion) out.Put<double>(c);

  out.Put<uint32_t>(static_cast<uint32_t>(n));
  for (int k = 0; k < 3; ++k) {
    int previous = 0;
    for (size_t i = 0; i < n; ++i) {
      out.Put<uint16_t>(ZigZag(q[i][k] - previous));
      previous = q[i][k];
    }
  }
  const bool wide = n > 65536;
  if (wide) out.PadTo(4);
  out.Put<uint32_t>(static_cast<uint32_t>(mesh.triangles.size()));
  uint32_t highest = 0;
  for (const auto& t : mesh.triangles) {
    for (uint32_t v : t) {
      const uint32_t index = number[v];
      out.PutIndex(highest - index, wide);
      if (index == highest) ++highest;
    }
  }
  for (BoxSide side : {kWestSide, kSouthSide, kEastSide, kNorthSide}) {
    const bool vertical = side == kWestSide || side == kEastSide;
    std::vector<uint32_t> edge;
    for (size_t i = 0; i < n; ++i) {
      if (mesh.sides[order[i]] & side) edge.push_back(static_cast<uint32_t>(i));
    }
    std::sort(edge.begin(), edge.end(), [&](uint32_t a, uint32_t b) {
      return vertical ? q[a][1] < q[b][1] : q[a][0] < q[b][0];
    });
    out.Put<uint32_t>(static_cast<uint32_t>(edge.size()));
    for (uint32_t i : edge) out.PutIndex(i, wide);
  }
  return out.Take();
}

}  // namespace locator
