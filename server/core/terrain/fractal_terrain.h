// FractalTerrain: deterministic synthetic DEMs for tests and benchmarks: a
// sum of octaves of gradient noise (fractional Brownian motion) over the
// unit square, sampled on a grid. The terrain is defined in continuous
// coordinates, so grids of different sizes sample the same terrain at
// different resolutions (as a DEM resampled finer); detail stops at the
// last octave's wavelength.
//
// Thread-safety: pure functions.

#ifndef LOCATOR_CORE_TERRAIN_FRACTAL_TERRAIN_H_
#define LOCATOR_CORE_TERRAIN_FRACTAL_TERRAIN_H_

#include <cstdint>

#include "common/elevation_grid.h"

namespace locator {

struct FractalTerrainOptions {
  uint64_t seed = 1;
  // Octaves of noise; octave k has 2^k times the first one's frequency.
  int octaves = 9;
  // Noise cycles across the grid's longer side in the first octave.
  double base_frequency = 2;
  // Each octave's amplitude over the previous one's (0.5: a Hurst exponent
  // of 1; larger is rougher).
  double persistence = 0.5;
  // Metres per unit of noise amplitude.
  double height = 2000;
};

// A width x height grid of the terrain: sample (col, row) at (col, -row)
// (north-up, one unit per sample), no nodata, built with up to `threads`
// threads. The same samples for the same arguments, whatever `threads`.
ElevationGrid FractalTerrain(uint32_t width, uint32_t height,
                             const FractalTerrainOptions& options,
                             unsigned threads = 1);

}  // namespace locator

#endif  // LOCATOR_CORE_TERRAIN_FRACTAL_TERRAIN_H_
