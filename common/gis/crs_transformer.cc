#include "common/gis/crs_transformer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "common/gis/crs_verdicts.h"
#include "common/gis/request_crs_policy.h"
#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator::gis {
namespace {

// The name of CRS `crs`, quoted: a request CRS's name is the client's text.
std::string QuotedName(const PJ* crs) {
  const char* name = proj_get_name(crs);
  return QuotedInput(name != nullptr ? name : "");
}

// A transformation from `from` to `to`, normalized to x = lon/easting, in
// the calling thread's request context.
Status CreateTransformation(const PJ* from, const PJ* to, PjPtr* out) {
  PJ_CONTEXT* ctx = ThreadRequestProjContext().get();
  PjPtr raw(proj_create_crs_to_crs_from_pj(ctx, from, to, nullptr, nullptr));
  if (raw != nullptr) {
    out->reset(proj_normalize_for_visualization(ctx, raw.get()));
  }
  if (*out == nullptr) {
    return Status::InvalidArgument("no transformation from " +
                                   QuotedName(from) + " to " + QuotedName(to) +
                                   ": " + LastProjError(ctx));
  }
  return Status::OK();
}

std::string PointText(size_t index, const Point2& p) {
  return "point " + std::to_string(index) + " " + locator::PointText(p);
}

bool Transform(PJ* pj, PJ_DIRECTION direction, Point2* p) {
  PJ_COORD c = proj_coord(p->x, p->y, 0, 0);
  c = proj_trans(pj, direction, c);
  if (!std::isfinite(c.xy.x) || !std::isfinite(c.xy.y)) return false;
  *p = Point2{c.xy.x, c.xy.y};
  return true;
}

// Lets the request context open the grids the dataset's CRS names: the
// operator chose them.
void AdmitGridsOf(const std::string& dataset_crs) {
  GuardedProjContext& ctx = ThreadProjContext();
  if (const StatusOr<PjPtr> crs = CreateCrs(ctx, dataset_crs); crs.ok()) {
    for (const GridUse& grid : GridsOf(ctx, crs->get())) {
      if (!grid.file.empty()) AdmitProjFile(grid.file);
    }
  }
  ctx.TakeRefusal();  // a grid it may not open is reported by the transform
}

// The key of a (request CRS, dataset CRS) pair in the verdicts.
std::string PairKey(const std::string& request_crs,
                    const std::string& dataset_crs) {
  return std::to_string(request_crs.size()) + ":" + request_crs + dataset_crs;
}

}  // namespace

bool CrsTransformer::AreaOfUse::Contains(double lon, double lat) const {
  if (lat < south || lat > north) return false;
  if (west <= east) return lon >= west && lon <= east;
  return lon >= west || lon <= east;
}

CrsTransformer::~CrsTransformer() = default;

StatusOr<std::unique_ptr<CrsTransformer>> CrsTransformer::Create(
    const std::string& request_crs, const std::string& dataset_crs) {
  AdmitGridsOf(dataset_crs);
  GuardedProjContext& guarded = ThreadRequestProjContext();
  ASSIGN_OR_RETURN(PjPtr request, CreateRequestCrs(request_crs));
  ASSIGN_OR_RETURN(PjPtr dataset, CreateCrs(guarded, dataset_crs));
  std::unique_ptr<CrsTransformer> created(new CrsTransformer);
  created->context_ = guarded.get();
  created->request_crs_ = request_crs;
  created->dataset_crs_ = dataset_crs;
  RETURN_IF_ERROR(CreateTransformation(request.get(), dataset.get(),
                                       &created->request_to_dataset_));
  PJ_CONTEXT* ctx = guarded.get();
  PjPtr geodetic(proj_crs_get_geodetic_crs(ctx, request.get()));
  const PJ_TYPE geodetic_type =
      geodetic == nullptr ? PJ_TYPE_UNKNOWN : proj_get_type(geodetic.get());
  if (geodetic_type != PJ_TYPE_GEOGRAPHIC_2D_CRS &&
      geodetic_type != PJ_TYPE_GEOGRAPHIC_3D_CRS) {
    return Status::InvalidArgument("CRS " + QuotedCrs(request_crs) +
                                   " has no geographic base CRS");
  }
  RETURN_IF_ERROR(CreateTransformation(request.get(), geodetic.get(),
                                       &created->request_to_lon_lat_));
  // A grid either CRS names that the transformations needed and could not
  // open: PROJ would have picked another transformation without it.
  RETURN_IF_ERROR(RefusedFileError(guarded, request_crs));
  for (const PJ* crs : {request.get(), dataset.get()}) {
    AreaOfUse area;
    if (proj_get_area_of_use(ctx, crs, &area.west, &area.south, &area.east,
                             &area.north, nullptr) &&
        area.west > -1000) {  // PROJ says -1000 for "unknown"
      created->areas_.push_back(area);
    }
  }
  return created;
}

Status CrsTransformer::ForThread(const std::string& request_crs,
                                 const std::string& dataset_crs,
                                 CrsTransformer** out) {
  struct Entry {
    std::string request_crs;
    std::string dataset_crs;
    std::unique_ptr<CrsTransformer> transformer;
  };
  // The context is made before the cache, so that it outlives the
  // transformers' PROJ objects when the thread exits.
  ThreadRequestProjContext();
  // Most recently used first.
  thread_local std::vector<Entry> cache;
  const auto hit =
      std::find_if(cache.begin(), cache.end(), [&](const Entry& e) {
        return e.request_crs == request_crs && e.dataset_crs == dataset_crs;
      });
  if (hit != cache.end()) {
    std::rotate(cache.begin(), hit, hit + 1);
    *out = cache.front().transformer.get();
    return Status::OK();
  }
  // Refused before it is used as a key.
  RETURN_IF_ERROR(CheckRequestCrsLength(request_crs));
  static CrsVerdicts* const verdicts = new CrsVerdicts();
  std::unique_ptr<CrsTransformer> created;
  RETURN_IF_ERROR(verdicts->Decide(PairKey(request_crs, dataset_crs), [&] {
    ASSIGN_OR_RETURN(created, Create(request_crs, dataset_crs));
    return Status::OK();
  }));
  if (cache.size() == kCacheCapacity) cache.pop_back();
  cache.insert(cache.begin(),
               Entry{request_crs, dataset_crs, std::move(created)});
  *out = cache.front().transformer.get();
  return Status::OK();
}

std::string CrsTransformer::Describe() const {
  return "from " + QuotedCrs(request_crs_) + " to " + QuotedCrs(dataset_crs_);
}

Status CrsTransformer::ToDataset(std::span<Point2> points,
                                 size_t first_index) const {
  for (size_t i = 0; i < points.size(); ++i) {
    if (!IsFinite(points[i])) continue;  // the caller's check names it
    Point2 lon_lat = points[i];
    const bool inside =
        Transform(request_to_lon_lat_.get(), PJ_FWD, &lon_lat) &&
        std::all_of(areas_.begin(), areas_.end(), [&](const AreaOfUse& a) {
          return a.Contains(lon_lat.x, lon_lat.y);
        });
    if (!inside) {
      return Status::InvalidArgument(PointText(first_index + i, points[i]) +
                                     " is outside the area of use of the "
                                     "transformation " +
                                     Describe());
    }
    const Point2 original = points[i];
    if (!Transform(request_to_dataset_.get(), PJ_FWD, &points[i])) {
      return Status::InvalidArgument(PointText(first_index + i, original) +
                                     " cannot be transformed " + Describe() +
                                     ": " + LastProjError(context_));
    }
  }
  return Status::OK();
}

void CrsTransformer::ToDatasetWhereDefined(std::span<Point2> points,
                                           bool known_inside) const {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (Point2& p : points) {
    if (!IsFinite(p)) continue;
    Point2 lon_lat = p;
    const bool inside =
        known_inside ||
        (Transform(request_to_lon_lat_.get(), PJ_FWD, &lon_lat) &&
         std::all_of(areas_.begin(), areas_.end(), [&](const AreaOfUse& a) {
           return a.Contains(lon_lat.x, lon_lat.y);
         }));
    if (!inside || !Transform(request_to_dataset_.get(), PJ_FWD, &p)) {
      p = Point2{kNaN, kNaN};
    }
  }
}

bool CrsTransformer::SeparableBoxInAreaOfUse(const BoundingBox& box) const {
  Point2 low{box.min_x, box.min_y}, high{box.max_x, box.max_y};
  if (!Transform(request_to_lon_lat_.get(), PJ_FWD, &low) ||
      !Transform(request_to_lon_lat_.get(), PJ_FWD, &high)) {
    return false;
  }
  // Both corners inside an area that does not cross 180° put the whole
  // box of longitudes and latitudes between them inside it.
  return std::all_of(areas_.begin(), areas_.end(), [&](const AreaOfUse& a) {
    return a.west <= a.east && a.Contains(low.x, low.y) &&
           a.Contains(high.x, high.y);
  });
}

Status CrsTransformer::ToRequest(std::span<Point2> points) const {
  for (size_t i = 0; i < points.size(); ++i) {
    const Point2 original = points[i];
    if (!Transform(request_to_dataset_.get(), PJ_INV, &points[i])) {
      return Status::InvalidArgument(
          PointText(i, original) + " cannot be transformed back " + Describe() +
          ": " + LastProjError(context_));
    }
  }
  return Status::OK();
}

Status RequestTransformer(const std::string& request_crs,
                          const std::string& dataset_crs,
                          CrsTransformer** out) {
  if (dataset_crs.empty()) {
    return Status::InvalidArgument(
        "crs: the request names CRS " + QuotedCrs(request_crs) +
        " but the dataset has none; send points in the dataset's own "
        "coordinates (no crs)");
  }
  const Status status =
      CrsTransformer::ForThread(request_crs, dataset_crs, out);
  if (status.ok()) return status;
  return Status::InvalidArgument("crs: " + status.message());
}

Status RequestPointsToDataset(const std::string& request_crs,
                              const std::string& dataset_crs,
                              std::span<Point2> points) {
  CrsTransformer* transformer = nullptr;
  RETURN_IF_ERROR(RequestTransformer(request_crs, dataset_crs, &transformer));
  return transformer->ToDataset(points);
}

}  // namespace locator::gis
