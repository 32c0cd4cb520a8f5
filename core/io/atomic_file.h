// Writing files so that a failure never leaves a half-written file nor destroys the previous
// one: the content goes to a temporary file beside the target, which is then renamed over it.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace sonarcarve {

/// Writes `bytes` to `path` atomically (temporary file + rename). Throws Error on failure,
/// leaving any previous file at `path` untouched.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

/// Calls write(temporary_path), which must create the file or throw, then renames it over
/// `path`. The temporary path has the same extension as `path`. On any failure the temporary file
/// is removed and the previous file kept.
void replaceFileAtomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path&)>& write);

}  // namespace sonarcarve
