// libFuzzer target: arbitrary bytes as a LAS file named "fuzz.las", read by
// the LAS reader (common/gis/las/) with every point kept, with ground and
// water last returns only, and with a class that point formats 0-5 cannot
// hold, under a 5,000-point limit.
//
// Aborts unless each read either
//   - succeeds with at least one point, no more than the limit, finite
//     coordinates and one finite value per point; or
//   - fails with InvalidArgument, FailedPrecondition (a compressed file) or
//     ResourceExhausted (the limit), its message starting "fuzz.las: ".
//
// Seeds: tests/fuzz/corpus/las_fuzzer/ (files the test writer makes; see
// tests/common/gis/las_dataset_test.cc to regenerate them).

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "common/gis/las/las_dataset.h"

namespace {

constexpr char kName[] = "fuzz.las";
constexpr size_t kMaxPoints = 5000;

void Fail(const char* what, const locator::Status& status) {
  std::fprintf(stderr, "las_fuzzer: %s (%s)\n", what,
               status.ToString().c_str());
  std::abort();
}

void Check(std::string_view bytes, const locator::gis::las::LasFilter& filter) {
  locator::DatasetLimits limits;
  limits.max_points = kMaxPoints;
  locator::Dataset ds;
  locator::gis::las::LasPointCounts counts;
  const locator::Status status = locator::gis::las::LoadLasBytes(
      bytes, kName, filter, limits, &ds, &counts);
  if (!status.ok()) {
    using Code = locator::Status::Code;
    if (status.code() != Code::kInvalidArgument &&
        status.code() != Code::kFailedPrecondition &&
        status.code() != Code::kResourceExhausted) {
      Fail("unexpected error code", status);
    }
    if (!status.message().starts_with(std::string(kName) + ": ")) {
      Fail("error does not start with the file name", status);
    }
    return;
  }
  if (ds.points.empty() || ds.points.size() > kMaxPoints) {
    Fail("point count out of range", status);
  }
  if (ds.values.size() != ds.points.size()) Fail("values not parallel", status);
  if (counts.kept != ds.points.size() || counts.records < counts.kept) {
    Fail("counts disagree with the dataset", status);
  }
  for (size_t i = 0; i < ds.points.size(); ++i) {
    if (!std::isfinite(ds.points[i].x) || !std::isfinite(ds.points[i].y) ||
        !std::isfinite(ds.values[i])) {
      Fail("a non-finite coordinate", status);
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  using locator::gis::las::LasFilter;
  Check(bytes, LasFilter());
  LasFilter ground;
  ground.classes.reset();
  ground.classes.set(2);
  ground.classes.set(9);
  ground.highest_class = 9;
  ground.returns = locator::gis::las::LasReturns::kLast;
  Check(bytes, ground);
  LasFilter high;
  high.classes.reset();
  high.classes.set(64);
  high.highest_class = 64;
  Check(bytes, high);
  return 0;
}
