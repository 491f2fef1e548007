#include "server/core/terrain/fractal_terrain.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

namespace locator {

namespace {

uint64_t Mix(uint64_t x) {  // SplitMix64's finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// The unit gradient of lattice point (ix, iy) of octave `octave`.
void Gradient(uint64_t seed, int octave, int64_t ix, int64_t iy, double* gx,
              double* gy) {
  const uint64_t h =
      Mix(seed ^
          Mix(static_cast<uint64_t>(octave) * 0x9e3779b97f4a7c15ull ^
              Mix(static_cast<uint64_t>(ix) ^ Mix(static_cast<uint64_t>(iy)))));
  const double angle =
      static_cast<double>(h >> 11) * 0x1p-53 * 2 * std::numbers::pi;
  *gx = std::cos(angle);
  *gy = std::sin(angle);
}

// Quintic fade: C2 continuous noise.
double Fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

// Adds octave `octave` of the noise, times `amplitude`, to row `row`.
void AddOctave(const FractalTerrainOptions& options, int octave,
               double amplitude, double cycles_per_sample, uint32_t row,
               std::vector<double>* z) {
  const double ty = row * cycles_per_sample;
  const auto iy = static_cast<int64_t>(std::floor(ty));
  const double fy = ty - static_cast<double>(iy);
  const double wy = Fade(fy);
  int64_t cached = std::numeric_limits<int64_t>::min();
  double g[4][2] = {};
  for (size_t col = 0; col < z->size(); ++col) {
    const double tx = static_cast<double>(col) * cycles_per_sample;
    const auto ix = static_cast<int64_t>(std::floor(tx));
    if (ix != cached) {
      cached = ix;
      Gradient(options.seed, octave, ix, iy, &g[0][0], &g[0][1]);
      Gradient(options.seed, octave, ix + 1, iy, &g[1][0], &g[1][1]);
      Gradient(options.seed, octave, ix, iy + 1, &g[2][0], &g[2][1]);
      Gradient(options.seed, octave, ix + 1, iy + 1, &g[3][0], &g[3][1]);
    }
    const double fx = tx - static_cast<double>(ix);
    const double n00 = g[0][0] * fx + g[0][1] * fy;
    const double n10 = g[1][0] * (fx - 1) + g[1][1] * fy;
    const double n01 = g[2][0] * fx + g[2][1] * (fy - 1);
    const double n11 = g[3][0] * (fx - 1) + g[3][1] * (fy - 1);
    const double wx = Fade(fx);
    const double top = n00 + wx * (n10 - n00);
    const double bottom = n01 + wx * (n11 - n01);
    (*z)[col] += amplitude * (top + wy * (bottom - top));
  }
}

}  // namespace

ElevationGrid FractalTerrain(uint32_t width, uint32_t height,
                             const FractalTerrainOptions& options,
                             unsigned threads) {
  ElevationGrid grid;
  grid.width = width;
  grid.height = height;
  grid.origin_x = 0;
  grid.origin_y = 0;
  grid.step_x = 1;
  grid.step_y = -1;
  grid.source = "fractal:" + std::to_string(width) + "x" +
                std::to_string(height) + ":" + std::to_string(options.seed);
  grid.values.resize(grid.samples());
  const double extent = std::max<double>(std::max(width, height) - 1.0, 1.0);
  std::atomic<uint32_t> next{0};
  const auto work = [&] {
    std::vector<double> z(width);
    for (uint32_t row = next++; row < height; row = next++) {
      std::fill(z.begin(), z.end(), 0.0);
      double amplitude = options.height;
      for (int octave = 0; octave < options.octaves; ++octave) {
        const double cycles =
            options.base_frequency * std::ldexp(1.0, octave) / extent;
        AddOctave(options, octave, amplitude, cycles, row, &z);
        amplitude *= options.persistence;
      }
      float* out = grid.values.data() + grid.Index(0, row);
      for (uint32_t col = 0; col < width; ++col) {
        out[col] = static_cast<float>(z[col]);
      }
    }
  };
  std::vector<std::thread> helpers;
  for (unsigned i = 1; i < std::max(threads, 1u); ++i) {
    helpers.emplace_back(work);
  }
  work();
  for (std::thread& helper : helpers) helper.join();
  return grid;
}

}  // namespace locator
