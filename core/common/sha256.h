// SHA-256 (FIPS 180-4) of bytes, as the lowercase hex sha256sum prints: the checksums of a run's
// deliverables in its manifest and its report (docs/formats.md). Written here from the standard:
// Debian's OpenSSL would be a library linked for this alone.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace sonarcarve {

/// Hashes bytes fed in pieces of any size.
class Sha256 {
 public:
  Sha256();
  void update(std::string_view bytes);
  /// The digest as 64 lowercase hex digits; the object is spent after it.
  std::string hexDigest();

 private:
  void compress(const std::uint8_t* block);
  std::array<std::uint32_t, 8> state_;
  std::array<std::uint8_t, 64> block_{};
  std::size_t block_used_ = 0;
  std::uint64_t total_bytes_ = 0;
};

/// The SHA-256 of `bytes` as 64 lowercase hex digits.
std::string sha256Hex(std::string_view bytes);

}  // namespace sonarcarve
