// Uses the installed engine: builds an Engine on a generated dataset and
// locates a dataset point and a point outside the unit square. Prints
// "locator consumer: ok" and exits 0 when every answer is right.

#include <cstdio>
#include <memory>
#include <string>
#include <utility>

#include "locator/dataset_sources.h"
#include "locator/engine.h"
#include "locator/locate_result.h"

namespace {

int Fail(const std::string& what) {
  std::fprintf(stderr, "locator consumer: %s\n", what.c_str());
  return 1;
}

}  // namespace

int main() {
  constexpr int64_t kProbe = 123;
  locator::Dataset dataset = locator::GenerateUniform(1000, 7);
  const locator::Point2 vertex = dataset.points[kProbe];

  locator::StatusOr<std::unique_ptr<locator::Engine>> created =
      locator::Engine::Create(std::move(dataset), locator::EngineOptions());
  if (!created.ok()) return Fail("Create: " + created.status().ToString());
  const std::unique_ptr<locator::Engine> engine = *std::move(created);

  locator::LocateResult result;
  locator::Status status = engine->Locate(vertex, &result);
  if (!status.ok()) return Fail("Locate: " + status.ToString());
  if (result.type != locator::LocationType::kVertex ||
      result.vertex_ids[result.feature_index] != kProbe) {
    return Fail("dataset point " + std::to_string(kProbe) + " located as " +
                std::string(locator::LocationTypeName(result.type)));
  }

  status = engine->Locate({2.0, 2.0}, &result);
  if (!status.ok()) return Fail("Locate: " + status.ToString());
  if (result.type != locator::LocationType::kOutsideConvexHull) {
    return Fail("(2, 2) is not outside the hull of the unit square");
  }

  std::printf(
      "locator consumer: ok (%llu triangles)\n",
      static_cast<unsigned long long>(engine->dataset_info().triangles));
  return 0;
}
