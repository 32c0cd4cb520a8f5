// Reading Linux's /proc and /sys text files: their whole text, and the "Key:  1234 kB" fields of
// /proc/meminfo and /proc/self/status.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace sonarcarve {

/// The whole text of a file; empty if it cannot be read.
std::string procFileText(const char* path);
/// The number after `key` (e.g. "MemAvailable:") at the start of a line of `text`, read as
/// kibibytes and returned in bytes; nothing if the key is missing or no number follows it.
std::optional<std::uint64_t> procKibField(const std::string& text, const std::string& key);
/// A whole number at the start of `text` (after blanks); nothing otherwise.
std::optional<std::uint64_t> wholeNumberOf(const std::string& text);

}  // namespace sonarcarve
