#include "common/gis/request_crs_policy.h"

#include "common/gis/crs_verdicts.h"

namespace locator::gis {

Status CheckRequestCrsLength(std::string_view crs) {
  if (crs.size() <= kMaxRequestCrsBytes) return Status::OK();
  return Status::InvalidArgument("a CRS of " + std::to_string(crs.size()) +
                                 " bytes (" + QuotedCrs(crs) + "); at most " +
                                 std::to_string(kMaxRequestCrsBytes) +
                                 " bytes are accepted");
}

Status CreateRequestCrs(std::string_view crs, PjPtr* out) {
  if (Status status = CheckRequestCrsLength(crs); !status.ok()) return status;
  GuardedProjContext& ctx = ThreadRequestProjContext();
  PjPtr created;
  if (Status status = CreateCrs(ctx, crs, &created); !status.ok()) {
    return status;
  }
  // Checked by name: PROJ remembers a grid it could not open and does not
  // ask for it again.
  for (const GridUse& grid : GridsOf(ctx, created.get())) {
    ctx.Permits(grid.name);
  }
  if (Status refused = RefusedFileError(ctx, crs); !refused.ok()) {
    return refused;
  }
  *out = std::move(created);
  return Status::OK();
}

Status CheckRequestCrs(const std::string& crs) {
  if (Status status = CheckRequestCrsLength(crs); !status.ok()) return status;
  static CrsVerdicts* const verdicts = new CrsVerdicts();
  return verdicts->Decide(crs, [&crs] {
    PjPtr created;
    return CreateRequestCrs(crs, &created);
  });
}

}  // namespace locator::gis
