// Shared checks for the terrain tests: a DEM's TIN served by the engine and
// measured there, sample by sample, by brute force.

#ifndef LOCATOR_TESTS_CORE_TERRAIN_TEST_SUPPORT_H_
#define LOCATOR_TESTS_CORE_TERRAIN_TEST_SUPPORT_H_

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include "common/elevation_grid.h"
#include "locator/dataset.h"
#include "locator/engine.h"
#include "server/core/terrain/tin_options.h"

namespace locator::test {

// Whether sample (col, row) is in the served domain: the corner of a cell
// whose four corners are valid (see triangulate_grid.h), computed here on
// its own from the samples.
inline bool InGridDomain(const ElevationGrid& grid, int64_t col, int64_t row) {
  const auto cell = [&](int64_t c, int64_t r) {
    if (c < 0 || r < 0 || c + 1 >= grid.width || r + 1 >= grid.height) {
      return false;
    }
    const auto uc = static_cast<uint32_t>(c), ur = static_cast<uint32_t>(r);
    return grid.IsValid(uc, ur) && grid.IsValid(uc + 1, ur) &&
           grid.IsValid(uc, ur + 1) && grid.IsValid(uc + 1, ur + 1);
  };
  return cell(col - 1, row - 1) || cell(col, row - 1) || cell(col - 1, row) ||
         cell(col, row);
}

// What serving a TIN of `grid` answers at the grid's own samples.
struct ServedErrors {
  double max_error = 0;  // over the samples in the domain
  uint64_t in_domain = 0;
  uint64_t outside = 0;  // samples answered OUTSIDE_DOMAIN or outside the hull
};

// Serves `tin` with the engine and locates every sample of `grid`: a sample
// in the domain must be answered with a value, and any other sample outside
// the domain or the hull; each failure is recorded (the first few).
inline ServedErrors MeasureServed(const ElevationGrid& grid,
                                  const Dataset& tin) {
  ServedErrors result;
  const StatusOr<std::unique_ptr<Engine>> created =
      Engine::Create(tin, EngineOptions());
  EXPECT_TRUE(created.ok()) << created.status().ToString();
  if (!created.ok()) return result;
  const Engine* engine = created->get();
  int failures = 0;
  for (uint32_t row = 0; row < grid.height; ++row) {
    for (uint32_t col = 0; col < grid.width; ++col) {
      LocateResult r;
      const Status located = engine->Locate(grid.SampleAt(col, row), &r);
      EXPECT_TRUE(located.ok()) << located.ToString();
      const bool inside = r.type == LocationType::kFace ||
                          r.type == LocationType::kEdge ||
                          r.type == LocationType::kVertex;
      if (!InGridDomain(grid, col, row)) {
        if (inside && failures++ < 5) {
          ADD_FAILURE() << "sample (" << col << ", " << row
                        << ") is outside the domain but answered "
                        << LocationTypeName(r.type);
        }
        ++result.outside;
        continue;
      }
      ++result.in_domain;
      if ((!inside || !r.has_value) && failures++ < 5) {
        ADD_FAILURE() << "sample (" << col << ", " << row
                      << ") is in the domain but answered "
                      << LocationTypeName(r.type);
        continue;
      }
      result.max_error = std::max(
          result.max_error, std::abs(double{grid.ValueAt(col, row)} - r.value));
    }
  }
  return result;
}

// What the engine serving `tin` answers at every point of `in`: the largest
// error over those it serves, and how many it does not.
struct ServedAtPoints {
  double max_error = 0;
  uint64_t unserved = 0;
};

inline ServedAtPoints MeasureServedAtPoints(const Dataset& in,
                                            const Dataset& tin) {
  ServedAtPoints served;
  const StatusOr<std::unique_ptr<Engine>> created =
      Engine::Create(tin, EngineOptions());
  EXPECT_TRUE(created.ok()) << created.status().ToString();
  if (!created.ok()) return served;
  const Engine* engine = created->get();
  for (size_t i = 0; i < in.points.size(); ++i) {
    LocateResult r;
    EXPECT_TRUE(engine->Locate(in.points[i], &r).ok());
    if (!r.has_value) {
      ++served.unserved;
      continue;
    }
    served.max_error =
        std::max(served.max_error, std::abs(in.values[i] - r.value));
  }
  return served;
}

// Options asking for `max_error` on `threads` threads.
inline TinOptions WithError(double max_error, unsigned threads = 1) {
  TinOptions options;
  options.max_error = max_error;
  options.threads = threads;
  return options;
}

// The rounding the certificate and the engine may differ by: a few ulps of
// the largest |value|.
inline double RoundingTolerance(const ElevationGrid& grid) {
  double largest = 0;
  for (const float v : grid.values) {
    if (!std::isnan(v)) largest = std::max(largest, double{std::abs(v)});
  }
  return 64 * std::numeric_limits<double>::epsilon() * (1 + largest);
}

}  // namespace locator::test

#endif  // LOCATOR_TESTS_CORE_TERRAIN_TEST_SUPPORT_H_
