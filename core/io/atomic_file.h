// Writing files so that a failure never leaves a half-written file nor destroys the previous
// one: the content goes to a temporary file beside the target, which is then renamed over it.
#pragma once

#include <filesystem>
#include <string_view>

namespace sonarcarve {

/// Writes `bytes` to `path` atomically (temporary file + rename). Throws Error on failure,
/// leaving any previous file at `path` untouched.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace sonarcarve
