// Writing files so that a failure never leaves a half-written file nor destroys the previous
// one. Every output of SonarCarve (meshes, clouds, maps, noise models, reports, simulated
// missions, sessions, parameters) is encoded in memory, then written here: to a temporary file
// beside the target, flushed to the disk (fsync), its size checked, then renamed over the
// target, and the folder synced so the rename survives a power cut. Only a regular file is
// replaced: a FIFO, a device or a socket in the way is refused, and a symbolic link is written
// through (the link stays and the file it leads to gets the new content).
#pragma once

#include <filesystem>
#include <string_view>

namespace sonarcarve {

/// The file writeFileAtomically(path) replaces: `path` itself when it does not exist or is a
/// regular file; the regular file a symbolic link at `path` leads to (through any chain of
/// links), so that the link is kept and leads to the new content. Throws Error naming `path`
/// and what it is for anything else: a FIFO, a device (`/dev/null`), a socket, a directory, a
/// link to one of them, a link that leads nowhere (dangling, or a loop). Commands call it on
/// their --out before any work, so that a bad target fails at once.
std::filesystem::path outputFileTarget(const std::filesystem::path& path);

/// Writes `bytes` to `path` atomically, onto outputFileTarget(path). Throws Error naming `path` and
/// the cause (a full disk, a read-only folder, a path that is a folder) on any failure, leaving a
/// previous file at `path` untouched and no temporary file behind. The temporary file is named
/// `.NAME.tmp-PID` in the same folder; one left over was cut off by a kill and can be deleted.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace sonarcarve
