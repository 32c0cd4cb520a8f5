// RAII for PROJ's C handles: a PJ_CONTEXT and the PJ objects made in it, each destroyed exactly
// once by its owner. A context is not shared between threads: whoever owns PJ objects owns
// their context too, declared first so that it is destroyed last.
#pragma once

#include <proj.h>

#include <memory>
#include <string>

namespace sonarcarve::proj {

struct ContextDeleter {
  void operator()(PJ_CONTEXT* context) const noexcept { proj_context_destroy(context); }
};
struct ObjectDeleter {
  void operator()(PJ* object) const noexcept { proj_destroy(object); }
};
using Context = std::unique_ptr<PJ_CONTEXT, ContextDeleter>;
using Object = std::unique_ptr<PJ, ObjectDeleter>;

/// A new context that prints nothing to stderr: its errors are read back (lastError) and
/// thrown as sonarcarve::Error with the file and the field they came from.
Context quietContext();

/// PROJ's words for the context's last error ("crs not found", ...), or "unknown reason".
std::string lastError(PJ_CONTEXT* context);

}  // namespace sonarcarve::proj
