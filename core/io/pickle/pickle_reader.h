// A Python pickle decoder that executes nothing (docs/formats.md, "HoloOcean / NeuSIS
// datasets"): it reads the opcodes of protocols 2 to 5 that hold dicts, lists, tuples, numbers,
// strings, bytes and numpy arrays, and builds those values itself. A global is accepted only
// from an allow-list (numpy's array and dtype reconstructors, _codecs.encode for protocol 2's
// bytes, numpy's scalar) and only called as that function is known to behave; any other
// opcode or global is refused with an Error naming the file, the byte and the opcode.
//
// Bounded: every length is checked against the bytes left before anything is allocated, an
// array's declared shape must match its data, and the stack, the memo, the objects made and the
// containers' nesting have limits, so a "pickle bomb" (lists nested a million deep, a list put
// inside itself through the memo) is refused at once.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "io/pickle/pickle_value.h"

namespace sonarcarve::pickle {

/// Containers nested deeper than this are refused.
inline constexpr int kMaxNesting = 64;
/// Items on the stack at once (Python's pickler pushes at most 1000 between marks).
inline constexpr std::size_t kMaxStack = 100000;
/// Objects made, and references held by containers, in one pickle (a frame's: a few dozen).
inline constexpr std::size_t kMaxObjects = 100000;
/// Largest pickle file read: a frame of 2^24 float64 pixels and room to spare.
inline constexpr std::uint64_t kMaxPickleFileBytes = std::uint64_t{256} << 20;

/// Decodes `bytes`; `source` names them in errors. Throws Error(source, "byte N", ...).
ValuePtr decodePickle(std::string_view bytes, const std::string& source);

/// Reads and decodes a pickle file (a regular file of at most kMaxPickleFileBytes).
ValuePtr readPickleFile(const std::filesystem::path& path);

}  // namespace sonarcarve::pickle
