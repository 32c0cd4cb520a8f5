// An anonymous temporary file for data a run sets aside while it runs (map pages, map.bt's
// blocks): std::tmpfile, in the system's temporary directory, removed when closed, even after
// a crash.
#pragma once

#include <cstdio>
#include <string>

namespace sonarcarve {

/// Opens one for reading and writing. Throws Error naming `source` if it cannot be made.
std::FILE* openTemporaryFile(const std::string& source);

}  // namespace sonarcarve
