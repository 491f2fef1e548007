// CrsTransformer: maps points between a request's CRS and a dataset's CRS
// with PROJ, in traditional GIS axis order (x = longitude/easting, y =
// latitude/northing) on both sides, whatever the CRS definitions say.
//
// It owns the PROJ transformation from the request CRS to the dataset CRS,
// the conversion of request points to longitude/latitude for the
// area-of-use check, and the areas of use of both CRSs.
//
// The request CRS is a request's (request_crs_policy.h: bounded in length,
// made in the thread's request context, so PROJ opens only its own data
// files); the dataset CRS is the operator's, and the grids it names are
// admitted to the request context (AdmitProjFile) before the transformation
// is made.
//
// Invariant: both CRSs were known to PROJ at creation and every PJ belongs
// to the creating thread's request context.
//
// Thread-safety: none. PROJ objects are not thread-safe and creating one is
// slow (milliseconds, a database lookup), so callers use ForThread(): a
// bounded per-thread cache keyed by the (request CRS, dataset CRS) pair,
// behind the process-wide verdicts (CrsVerdicts) that make a failing pair
// fail without being made again.

#ifndef LOCATOR_COMMON_GIS_CRS_TRANSFORMER_H_
#define LOCATOR_COMMON_GIS_CRS_TRANSFORMER_H_

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/gis/proj_objects.h"
#include "locator/geometry.h"
#include "locator/status.h"
#include "locator/status_or.h"

namespace locator::gis {

class CrsTransformer {
 public:
  // Pairs a thread's cache holds; the least recently used one goes first.
  static constexpr size_t kCacheCapacity = 16;

  // Creates a transformer on the calling thread; InvalidArgument naming the
  // CRS PROJ does not know, the pair it cannot transform between, or the
  // file the request context did not let PROJ open.
  static StatusOr<std::unique_ptr<CrsTransformer>> Create(
      const std::string& request_crs, const std::string& dataset_crs);

  // The calling thread's transformer for the pair, created on first use
  // unless the pair is known to fail. *out stays valid until this thread's
  // next ForThread call.
  static Status ForThread(const std::string& request_crs,
                          const std::string& dataset_crs, CrsTransformer** out);

  CrsTransformer(const CrsTransformer&) = delete;
  CrsTransformer& operator=(const CrsTransformer&) = delete;
  ~CrsTransformer();

  // Maps `points` (request CRS) to the dataset CRS in place.
  // InvalidArgument naming the first point (by its index in the request:
  // points[0] is point `first_index`) outside the area of use of either CRS
  // or that PROJ cannot transform; then `points` is partly transformed.
  // Non-finite points are left as they are, for the caller's own check to
  // name.
  Status ToDataset(std::span<Point2> points, size_t first_index = 0) const;

  // Maps `points` (request CRS) to the dataset CRS in place, as ToDataset,
  // but a point outside the area of use of either CRS, or that PROJ cannot
  // transform, becomes NaN instead of failing the call: for a map tile,
  // whose pixels may lie anywhere on Earth, such pixels are simply empty.
  // With `known_inside`, the caller vouches that every point lies in the
  // area of use (SeparableBoxInAreaOfUse of a box holding them), and the
  // per-point check is skipped.
  void ToDatasetWhereDefined(std::span<Point2> points,
                             bool known_inside = false) const;
  // Whether all of `box` (request CRS) lies in the area of use of both
  // CRSs, for a request CRS whose longitude depends on x alone and latitude
  // on y alone, each monotonically (Web Mercator): then the box's corners
  // bound its longitudes and latitudes. False when unsure (an area across
  // 180°, a corner PROJ cannot map).
  bool SeparableBoxInAreaOfUse(const BoundingBox& box) const;
  // Maps `points` (dataset CRS) back to the request CRS in place;
  // InvalidArgument naming the first point PROJ cannot transform.
  Status ToRequest(std::span<Point2> points) const;

 private:
  // A longitude/latitude box in degrees; west > east crosses 180°.
  struct AreaOfUse {
    double west, south, east, north;
    bool Contains(double lon, double lat) const;
  };

  CrsTransformer() = default;
  std::string Describe() const;

  std::string request_crs_;
  std::string dataset_crs_;
  PJ_CONTEXT* context_ = nullptr;  // the creating thread's request context
  PjPtr request_to_dataset_;
  PjPtr request_to_lon_lat_;
  std::vector<AreaOfUse> areas_;
};

// The calling thread's transformer (ForThread) from a request's CRS to a
// dataset's, failing as a server fails the request: InvalidArgument
// starting "crs: ", and saying so when the dataset has no CRS. For the
// servers and for those who route their requests.
Status RequestTransformer(const std::string& request_crs,
                          const std::string& dataset_crs, CrsTransformer** out);

// Maps `points` from a request's CRS to a dataset's in place, as a server
// maps a request's points (RequestTransformer, then ToDataset), with its
// errors: for those who route requests by where their points are.
Status RequestPointsToDataset(const std::string& request_crs,
                              const std::string& dataset_crs,
                              std::span<Point2> points);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_CRS_TRANSFORMER_H_
