// EncodeQuantizedMesh against the quantized-mesh-1.0 specification, read
// here byte by byte: a five-vertex tile whose zig-zag deltas, high-water
// mark codes and edge lists are worked out by hand from the spec; 32-bit
// indices with the padding the spec asks for; and the horizon occlusion
// point checked as Cesium uses it (EllipsoidalOccluder's visibility test,
// written here): a camera that cannot see it sees none of the vertices.

#include "server/tiles/quantized_mesh/quantized_mesh_encoder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "server/tiles/quantized_mesh/wgs84.h"

namespace locator {
namespace {

using ::testing::ElementsAre;

// Little-endian fields of the file, from `offset` on.
class Reader {
 public:
  explicit Reader(const std::string& bytes, size_t offset = 0)
      : bytes_(bytes), at_(offset) {}
  template <typename T>
  T Get() {
    T value;
    EXPECT_LE(at_ + sizeof(T), bytes_.size());
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  template <typename T>
  std::vector<T> List(size_t n) {
    std::vector<T> out;
    for (size_t i = 0; i < n; ++i) out.push_back(Get<T>());
    return out;
  }
  size_t at() const { return at_; }

 private:
  const std::string& bytes_;
  size_t at_;
};

// A 1° square at the origin: its corners and a peak in the middle.
ClippedMesh Pyramid() {
  ClippedMesh m;
  m.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}};
  m.heights = {10, 20, 30, 10, 40};
  m.sides = {kWestSide | kSouthSide, kSouthSide | kEastSide,
             kEastSide | kNorthSide, kWestSide | kNorthSide, 0};
  m.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  return m;
}

TEST(QuantizedMeshEncoderTest, FieldsAreTheSpecsWorkedByHand) {
  const std::string bytes = EncodeQuantizedMesh(Pyramid(), {0, 0, 1, 1});
  ASSERT_EQ(bytes.size(), 88u + 4 + 5 * 6 + 4 + 12 * 2 + 4 * (4 + 2 * 2));
  Reader heights(bytes, 24);
  EXPECT_EQ(heights.Get<float>(), 10.0f);
  EXPECT_EQ(heights.Get<float>(), 40.0f);
  Reader r(bytes, 88);
  ASSERT_EQ(r.Get<uint32_t>(), 5u);
  // Vertices in the order the triangles first use them: 0, 1, 4, 2, 3.
  // u: 0, 32767, 16384, 32767, 0 as zig-zag deltas.
  EXPECT_THAT(r.List<uint16_t>(5), ElementsAre(0, 65534, 32765, 32766, 65533));
  // v: 0, 0, 16384, 32767, 32767.
  EXPECT_THAT(r.List<uint16_t>(5), ElementsAre(0, 0, 32768, 32766, 0));
  // height over 10..40: 0, 10922, 32767, 21845, 0.
  EXPECT_THAT(r.List<uint16_t>(5), ElementsAre(0, 21844, 43690, 21843, 43689));
  ASSERT_EQ(r.Get<uint32_t>(), 4u);
  // Triangles (0 1 2) (1 3 2) (3 4 2) (4 0 2) in the new numbers, each
  // index as the highest so far minus it.
  EXPECT_THAT(r.List<uint16_t>(12),
              ElementsAre(0, 0, 0, 2, 0, 2, 1, 0, 3, 1, 5, 3));
  // West (south to north), south, east, north (west to east).
  for (const std::vector<uint16_t>& edge :
       {std::vector<uint16_t>{0, 4}, {0, 1}, {1, 3}, {4, 3}}) {
    ASSERT_EQ(r.Get<uint32_t>(), 2u);
    EXPECT_EQ(r.List<uint16_t>(2), edge);
  }
  EXPECT_EQ(r.at(), bytes.size());
}

TEST(QuantizedMeshEncoderTest, ManyVerticesTakeAlignedThirtyTwoBitIndices) {
  // 65537 vertices: a fan. The vertex data ends 2 bytes past a multiple
  // of 4, so two bytes of padding come before the triangle count.
  ClippedMesh m;
  const uint32_t n = 65537;
  for (uint32_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / n;
    m.points.push_back({t, t * t});
    m.heights.push_back(i);
    m.sides.push_back(0);
  }
  for (uint32_t i = 1; i + 1 < n; ++i) m.triangles.push_back({0, i, i + 1});
  const std::string bytes = EncodeQuantizedMesh(m, {0, 0, 1, 1});
  const size_t vertices_end = 88 + 4 + 6 * size_t{n};
  ASSERT_EQ(vertices_end % 4, 2u);
  Reader r(bytes, vertices_end);
  EXPECT_EQ(r.Get<uint16_t>(), 0u);  // padding
  ASSERT_EQ(r.Get<uint32_t>(), n - 2);
  EXPECT_THAT(r.List<uint32_t>(6), ElementsAre(0, 0, 0, 3, 1, 0));
}

TEST(QuantizedMeshEncoderTest, NoTrianglesIsATileWithoutVertices) {
  const std::string bytes =
      EncodeQuantizedMesh(ClippedMesh(), {10, 40, 11, 41});
  ASSERT_EQ(bytes.size(), 88u + 4 + 4 + 4 * 4);
  Reader r(bytes);
  const Vec3 centre = {r.Get<double>(), r.Get<double>(), r.Get<double>()};
  const Vec3 expected = GeodeticToEcef(10.5, 40.5, 0);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(centre[i], expected[i], 1e-6);
}

// Cesium's EllipsoidalOccluder.isScaledSpacePointVisible for a camera at
// `camera` (scaled space).
bool Visible(const Vec3& camera, const Vec3& point) {
  const double vh =
      camera[0] * camera[0] + camera[1] * camera[1] + camera[2] * camera[2] - 1;
  const Vec3 vt = {point[0] - camera[0], point[1] - camera[1],
                   point[2] - camera[2]};
  const double vt_dot_vc =
      -(vt[0] * camera[0] + vt[1] * camera[1] + vt[2] * camera[2]);
  const double vt2 = vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2];
  const bool occluded =
      vh < 0 ? vt_dot_vc > 0
             : vt_dot_vc > vh && vt_dot_vc * vt_dot_vc / vt2 > vh;
  return !occluded;
}

TEST(QuantizedMeshEncoderTest, AnyCameraThatSeesAVertexSeesTheOcclusionPoint) {
  ClippedMesh m = Pyramid();
  for (double& h : m.heights) h *= 100;  // up to 4 km
  const BoundingBox box{14, 49, 15, 50};
  for (Point2& p : m.points) p = {14 + p.x, 49 + p.y};
  const std::string bytes = EncodeQuantizedMesh(m, box);
  Reader r(bytes, 64);
  const Vec3 occlusion = {r.Get<double>(), r.Get<double>(), r.Get<double>()};
  std::vector<Vec3> scaled;
  for (size_t i = 0; i < m.size(); ++i) {
    const Vec3 e = GeodeticToEcef(m.points[i].x, m.points[i].y, m.heights[i]);
    scaled.push_back(
        {e[0] / kWgs84Radii[0], e[1] / kWgs84Radii[1], e[2] / kWgs84Radii[2]});
  }
  std::mt19937 random(7);
  std::uniform_real_distribution<double> lon(0, 40), lat(30, 70),
      height(1000, 3e6);
  size_t seen = 0, hidden = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 e = GeodeticToEcef(lon(random), lat(random), height(random));
    const Vec3 camera = {e[0] / kWgs84Radii[0], e[1] / kWgs84Radii[1],
                         e[2] / kWgs84Radii[2]};
    bool any = false;
    for (const Vec3& p : scaled) any |= Visible(camera, p);
    if (any) {
      ++seen;
      EXPECT_TRUE(Visible(camera, occlusion)) << "camera " << k;
    }
    if (!Visible(camera, occlusion)) ++hidden;
  }
  // Both cases happen: the point hides the tile from far away.
  EXPECT_GT(seen, 1000u);
  EXPECT_GT(hidden, 500u);
}

}  // namespace
}  // namespace locator
