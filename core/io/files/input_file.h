// Opening an input file. Every reader opens its files through here, so that only a regular file
// is read where a file is expected: a directory, a FIFO (which blocks until someone writes) or
// a device such as /dev/zero (which never ends) is refused with an Error naming the file and
// what was expected, before anything is read or allocated.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace sonarcarve {

/// Throws Error naming `path` unless it is an existing regular file (symbolic links followed).
/// `what` names the expected content in the message: "navigation CSV", "frame image".
void requireRegularFile(const std::filesystem::path& path, std::string_view what);

/// Throws Error naming `path` unless it is a regular file of at most `max_bytes` (and of no more
/// than the memory available): for readers that read a file whole by other means (OpenCV's
/// FileStorage, yaml-cpp), before they open it.
void requireInputSize(const std::filesystem::path& path, std::string_view what,
                      std::uint64_t max_bytes);

/// The whole content of a regular file (checked as by requireRegularFile, and again on the
/// opened descriptor). Throws Error naming the file on any failure, and, before anything is
/// read, when the file is larger than `max_bytes` (the bound of its format,
/// common/input_limits.h) or than the memory available.
std::string readInputFile(const std::filesystem::path& path, std::string_view what,
                          std::uint64_t max_bytes);

/// `text` without the UTF-8 byte-order mark some editors put at the start of a text file.
std::string_view withoutByteOrderMark(std::string_view text);

}  // namespace sonarcarve
