#include "common/gis/crs_info.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <utility>

#include "common/gis/proj_objects.h"
#include "common/status_macros.h"

namespace locator::gis {
namespace {

constexpr int kFullConfidence = 100;
// DescribeCrsMemoized forgets everything when it holds this many.
constexpr size_t kMemoCapacity = 8;

// The horizontal part of `crs`: the first component of a compound CRS, the
// source of a bound CRS, else `crs` itself.
PjPtr HorizontalCrs(const PJ* crs) {
  PJ_CONTEXT* ctx = ThreadProjContext().get();
  switch (proj_get_type(crs)) {
    case PJ_TYPE_COMPOUND_CRS:
      return PjPtr(proj_crs_get_sub_crs(ctx, crs, 0));
    case PJ_TYPE_BOUND_CRS:
      return PjPtr(proj_get_source_crs(ctx, crs));
    default:
      return PjPtr(proj_clone(ctx, crs));
  }
}

int EpsgCode(const PJ* crs) {
  const char* authority = proj_get_id_auth_name(crs, 0);
  if (authority != nullptr && std::strcmp(authority, "EPSG") == 0) {
    return std::atoi(proj_get_id_code(crs, 0));
  }
  PJ_CONTEXT* ctx = ThreadProjContext().get();
  int* confidence = nullptr;
  PJ_OBJ_LIST* matches = proj_identify(ctx, crs, "EPSG", nullptr, &confidence);
  int code = 0;
  if (matches != nullptr && proj_list_get_count(matches) > 0 &&
      confidence[0] == kFullConfidence) {
    PjPtr match(proj_list_get(ctx, matches, 0));
    code = std::atoi(proj_get_id_code(match.get(), 0));
  }
  proj_int_list_destroy(confidence);
  proj_list_destroy(matches);
  return code;
}

}  // namespace

StatusOr<CrsInfo> DescribeCrs(std::string_view crs) {
  GuardedProjContext& guarded = ThreadProjContext();
  ASSIGN_OR_RETURN(const PjPtr created, CreateCrs(guarded, crs));
  PJ_CONTEXT* ctx = guarded.get();
  CrsInfo info;
  const char* name = proj_get_name(created.get());
  info.name = name == nullptr ? "" : name;
  info.epsg_code = EpsgCode(created.get());

  PjPtr horizontal = HorizontalCrs(created.get());
  PjPtr normalized(horizontal == nullptr ? nullptr
                                         : proj_normalize_for_visualization(
                                               ctx, horizontal.get()));
  PjPtr cs(normalized == nullptr
               ? nullptr
               : proj_crs_get_coordinate_system(ctx, normalized.get()));
  if (cs == nullptr) {
    return Status::InvalidArgument("CRS '" + info.name +
                                   "' has no horizontal coordinate system");
  }
  const int axes = std::min(proj_cs_get_axis_count(ctx, cs.get()), 2);
  for (int i = 0; i < axes; ++i) {
    const char* unit = nullptr;
    proj_cs_get_axis_info(ctx, cs.get(), i, nullptr, nullptr, nullptr, nullptr,
                          &unit, nullptr, nullptr);
    info.axis_units.emplace_back(unit == nullptr ? "" : unit);
  }
  return info;
}

StatusOr<CrsInfo> DescribeCrsMemoized(const std::string& crs) {
  static std::mutex mu;
  static std::map<std::string, StatusOr<CrsInfo>> memo;
  {
    std::lock_guard<std::mutex> lock(mu);
    if (const auto it = memo.find(crs); it != memo.end()) return it->second;
  }
  StatusOr<CrsInfo> described = DescribeCrs(crs);
  std::lock_guard<std::mutex> lock(mu);
  if (memo.size() >= kMemoCapacity) memo.clear();
  memo.emplace(crs, described);
  return described;
}

}  // namespace locator::gis
