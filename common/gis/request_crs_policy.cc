#include "common/gis/request_crs_policy.h"

#include "common/gis/crs_verdicts.h"
#include "common/status_macros.h"

namespace locator::gis {

Status CheckRequestCrsLength(std::string_view crs) {
  if (crs.size() <= kMaxRequestCrsBytes) return Status::OK();
  return Status::InvalidArgument("a CRS of " + std::to_string(crs.size()) +
                                 " bytes (" + QuotedCrs(crs) + "); at most " +
                                 std::to_string(kMaxRequestCrsBytes) +
                                 " bytes are accepted");
}

Status CreateRequestCrs(std::string_view crs, PjPtr* out) {
  RETURN_IF_ERROR(CheckRequestCrsLength(crs));
  GuardedProjContext& ctx = ThreadRequestProjContext();
  PjPtr created;
  RETURN_IF_ERROR(CreateCrs(ctx, crs, &created));
  // Checked by name: PROJ remembers a grid it could not open and does not
  // ask for it again.
  for (const GridUse& grid : GridsOf(ctx, created.get())) {
    ctx.Permits(grid.name);
  }
  RETURN_IF_ERROR(RefusedFileError(ctx, crs));
  *out = std::move(created);
  return Status::OK();
}

Status CheckRequestCrs(const std::string& crs) {
  RETURN_IF_ERROR(CheckRequestCrsLength(crs));
  static CrsVerdicts* const verdicts = new CrsVerdicts();
  return verdicts->Decide(crs, [&crs] {
    PjPtr created;
    return CreateRequestCrs(crs, &created);
  });
}

}  // namespace locator::gis
