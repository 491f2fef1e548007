#include "common/gis/proj_objects.h"

#include "common/input_text.h"

namespace locator::gis {
namespace {

struct ContextDeleter {
  void operator()(PJ_CONTEXT* ctx) const { proj_context_destroy(ctx); }
};

}  // namespace

std::string QuotedCrs(std::string_view crs) { return QuotedInput(crs); }

PJ_CONTEXT* ThreadProjContext() {
  thread_local std::unique_ptr<PJ_CONTEXT, ContextDeleter> context(
      proj_context_create());
  return context.get();
}

std::string LastProjError() {
  PJ_CONTEXT* ctx = ThreadProjContext();
  const char* message = proj_context_errno_string(ctx, proj_context_errno(ctx));
  return message == nullptr ? "unknown PROJ error" : message;
}

Status CreateCrs(std::string_view crs, PjPtr* out) {
  PJ_CONTEXT* ctx = ThreadProjContext();
  std::string text(crs);
  if (text.starts_with("+proj=") &&
      text.find("type=crs") == std::string::npos) {
    text += " +type=crs";
  }
  PjPtr created(text.empty() ? nullptr : proj_create(ctx, text.c_str()));
  if (created == nullptr) {
    return Status::InvalidArgument("unknown CRS " + QuotedCrs(crs) + ": " +
                                   (text.empty() ? "empty" : LastProjError()));
  }
  if (!proj_is_crs(created.get())) {
    return Status::InvalidArgument(
        "unknown CRS " + QuotedCrs(crs) +
        ": it names an operation, not a coordinate reference system");
  }
  *out = std::move(created);
  return Status::OK();
}

}  // namespace locator::gis
