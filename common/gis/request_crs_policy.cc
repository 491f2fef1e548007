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

StatusOr<PjPtr> CreateRequestCrs(std::string_view crs) {
  RETURN_IF_ERROR(CheckRequestCrsLength(crs));
  GuardedProjContext& ctx = ThreadRequestProjContext();
  ASSIGN_OR_RETURN(PjPtr created, CreateCrs(ctx, crs));
  // Checked by name: PROJ remembers a grid it could not open and does not
  // ask for it again.
  for (const GridUse& grid : GridsOf(ctx, created.get())) {
    ctx.Permits(grid.name);
  }
  RETURN_IF_ERROR(RefusedFileError(ctx, crs));
  return created;
}

Status CheckRequestCrs(const std::string& crs) {
  RETURN_IF_ERROR(CheckRequestCrsLength(crs));
  static CrsVerdicts* const verdicts = new CrsVerdicts();
  return verdicts->Decide(crs,
                          [&crs] { return CreateRequestCrs(crs).status(); });
}

}  // namespace locator::gis
