// Finding Oculus messages again after corrupt bytes (docs/formats.md, "Oculus logs"). A
// message stream has no markers between messages: each header's payloadSize says where the
// next one starts, so one corrupt size field loses the thread. The reader then scans forward
// for the next byte where a message starts that is confirmed by what follows it, instead of
// trusting the size (which used to drop the intact messages it jumped over).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include "io/files/mapped_file.h"

namespace sonarcarve {

inline constexpr std::size_t kNoOculusMessage = std::numeric_limits<std::size_t>::max();

/// True if an Oculus message header (oculusId 0x4f53) starts at `offset` and its payload ends
/// within `bytes`.
bool oculusHeaderFitsAt(std::span<const std::uint8_t> bytes, std::size_t offset);

/// True if a simple ping result at `offset` decodes (its image checked, not converted).
bool oculusPingDecodesAt(std::span<const std::uint8_t> bytes, std::size_t offset);

/// True if the message at `offset` has a header that fits and its size leads to the end of
/// `bytes` or to another header that fits: the size field can be trusted.
bool oculusSizeLeadsToAMessage(std::span<const std::uint8_t> bytes, std::size_t offset);

/// The first offset at or after `from` where a confirmed message starts: its header fits, its
/// msgVersion is 0 to 2, and either its size leads to a message or the end (as above) or it is
/// a simple ping result that decodes. kNoOculusMessage if there is none. With `file` (whose
/// bytes `bytes` begins), the holes of a sparse file are jumped over: a 20 GB hole after a
/// ping is passed at once instead of read as 20 GB of zeros.
std::size_t findNextOculusMessage(std::span<const std::uint8_t> bytes, std::size_t from,
                                  const MappedFile* file = nullptr);

}  // namespace sonarcarve
