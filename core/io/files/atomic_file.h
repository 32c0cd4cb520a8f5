// Writing files so that a failure never leaves a half-written file nor destroys the previous
// one. Every output of SonarCarve (meshes, clouds, maps, noise models, reports, simulated
// missions, sessions, parameters) is encoded in memory, then written here: to a temporary file
// beside the target, flushed to the disk (fsync), its size checked, then renamed over the
// target, and the folder synced so the rename survives a power cut.
#pragma once

#include <filesystem>
#include <string_view>

namespace sonarcarve {

/// Writes `bytes` to `path` atomically. Throws Error naming `path` and the cause (a full disk,
/// a read-only folder, a path that is a folder) on any failure, leaving a previous file at
/// `path` untouched and no temporary file behind. The temporary file is named
/// `.NAME.tmp-PID` in the same folder; one left over was cut off by a kill and can be deleted.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace sonarcarve
