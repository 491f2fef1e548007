#include "common/gis/proj_objects.h"

#include "common/input_text.h"
#include "common/status_macros.h"

namespace locator::gis {
namespace {

// Compound, bound and derived CRSs nest; PROJ's own objects go a few levels
// deep at most.
constexpr int kMaxCrsNesting = 8;

void CollectGrids(GuardedProjContext& ctx, const PJ* crs, int depth,
                  std::vector<GridUse>* grids) {
  if (crs == nullptr || depth > kMaxCrsNesting) return;
  PJ_CONTEXT* const pj_ctx = ctx.get();
  if (proj_get_type(crs) == PJ_TYPE_COMPOUND_CRS) {
    for (int i = 0;; ++i) {
      PjPtr part(proj_crs_get_sub_crs(pj_ctx, crs, i));
      if (part == nullptr) break;
      CollectGrids(ctx, part.get(), depth + 1, grids);
    }
    return;
  }
  // A bound CRS's transformation, or a derived CRS's deriving conversion.
  if (PjPtr operation(proj_crs_get_coordoperation(pj_ctx, crs));
      operation != nullptr) {
    const int count =
        proj_coordoperation_get_grid_used_count(pj_ctx, operation.get());
    for (int i = 0; i < count; ++i) {
      const char* name = nullptr;
      const char* file = nullptr;
      if (proj_coordoperation_get_grid_used(pj_ctx, operation.get(), i, &name,
                                            &file, nullptr, nullptr, nullptr,
                                            nullptr, nullptr)) {
        grids->push_back(
            GridUse{name == nullptr ? "" : name, file == nullptr ? "" : file});
      }
    }
  }
  PjPtr base(proj_get_source_crs(pj_ctx, crs));
  CollectGrids(ctx, base.get(), depth + 1, grids);
}

}  // namespace

std::string QuotedCrs(std::string_view crs) { return QuotedInput(crs); }

GuardedProjContext& ThreadProjContext() {
  thread_local GuardedProjContext context(ProjFileScope::kAnyRegularFile);
  return context;
}

GuardedProjContext& ThreadRequestProjContext() {
  thread_local GuardedProjContext context(ProjFileScope::kDataDirectories);
  return context;
}

std::string LastProjError(PJ_CONTEXT* ctx) {
  const char* message = proj_context_errno_string(ctx, proj_context_errno(ctx));
  return message == nullptr ? "unknown PROJ error" : message;
}

Status RefusedFileError(GuardedProjContext& ctx, std::string_view crs) {
  const std::string refusal = ctx.TakeRefusal();
  if (refusal.empty()) return Status::OK();
  return Status::InvalidArgument(
      "CRS " + QuotedCrs(crs) +
      " names a file PROJ may not open here: " + refusal);
}

StatusOr<PjPtr> CreateCrs(GuardedProjContext& ctx, std::string_view crs) {
  std::string text(crs);
  if (text.starts_with("+proj=") &&
      text.find("type=crs") == std::string::npos) {
    text += " +type=crs";
  }
  // Only this creation's refusals and errors count.
  ctx.TakeRefusal();
  ctx.TakeLoggedError();
  PjPtr created(text.empty() ? nullptr : proj_create(ctx.get(), text.c_str()));
  RETURN_IF_ERROR(RefusedFileError(ctx, crs));
  if (created == nullptr) {
    std::string why = text.empty() ? "empty" : ctx.TakeLoggedError();
    if (why.empty()) why = LastProjError(ctx.get());
    return Status::InvalidArgument("unknown CRS " + QuotedCrs(crs) + ": " +
                                   why);
  }
  if (!proj_is_crs(created.get())) {
    return Status::InvalidArgument(
        "unknown CRS " + QuotedCrs(crs) +
        ": it names an operation, not a coordinate reference system");
  }
  return created;
}

std::vector<GridUse> GridsOf(GuardedProjContext& ctx, const PJ* crs) {
  std::vector<GridUse> grids;
  CollectGrids(ctx, crs, 0, &grids);
  return grids;
}

}  // namespace locator::gis
