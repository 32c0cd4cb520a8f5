// What a path is, in the words of error messages: readers (io/files/input_file.h) and writers
// (io/files/atomic_file.h, io/files/output_folder.h) refuse what they did not expect by name.
#pragma once

#include <sys/types.h>

#include <string>

namespace sonarcarve {

/// "a directory", "a FIFO (named pipe)", "a device", "a socket", "a symbolic link", "a regular
/// file" for a `st_mode` of stat(2).
std::string fileKindName(mode_t mode);

}  // namespace sonarcarve
