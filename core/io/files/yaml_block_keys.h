// Duplicate keys in block-style YAML read by a parser that accepts them silently (OpenCV's, for
// noise models: the last of two `smoothing:` lines won). Keys are found by their indentation,
// as the block style writes them ("key:" at the start of a line, after spaces); flow
// collections and values are left alone.
#pragma once

#include <string>
#include <string_view>

namespace sonarcarve {

/// Throws Error naming `file`, the line and the key when one mapping of `text` holds a key
/// twice.
void requireUniqueBlockKeys(std::string_view text, const std::string& file);

}  // namespace sonarcarve
