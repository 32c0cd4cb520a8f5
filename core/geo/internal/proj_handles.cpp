#include "geo/internal/proj_handles.h"

#include <new>

namespace sonarcarve::proj {

Context quietContext() {
  Context context(proj_context_create());
  if (!context) {
    throw std::bad_alloc();
  }
  proj_log_level(context.get(), PJ_LOG_NONE);
  return context;
}

std::string lastError(PJ_CONTEXT* context) {
  const int code = proj_context_errno(context);
  const char* text = code != 0 ? proj_context_errno_string(context, code) : nullptr;
  return text != nullptr && *text != '\0' ? std::string(text) : std::string("unknown reason");
}

}  // namespace sonarcarve::proj
