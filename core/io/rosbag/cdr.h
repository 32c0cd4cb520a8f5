// CDR (OMG Common Data Representation, XCDR1 as ROS 2 writes it): the byte layout of ROS 2
// messages in bags. A message starts with a 4-byte encapsulation header (00 01 = little-endian,
// 00 00 = big-endian, then two option bytes); each primitive is aligned to its own size,
// counted from the byte after that header; a string is a u32 length that counts its NUL, then
// the bytes and the NUL; a sequence is a u32 count then its elements; a fixed array has no
// count. docs/formats.md, "ROS 2 bags".
#pragma once

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace sonarcarve {

/// Reads one CDR message. Every read is bounds-checked: a message that ends early or claims
/// more elements than it holds throws Error(source, "<place>, CDR byte N", what was expected).
class CdrReader {
 public:
  /// Checks the encapsulation header. `place` names the message in errors ("message 12").
  CdrReader(std::span<const std::uint8_t> message, std::string source, std::string place);

  template <typename T>
  T read(const char* what) {
    static_assert(std::is_arithmetic_v<T>);
    align(sizeof(T));
    require(sizeof(T), what);
    T value{};
    std::memcpy(&value, body_.data() + offset_, sizeof(T));
    offset_ += sizeof(T);
    return big_endian_ ? swapped(value) : value;
  }
  bool readBool(const char* what) { return read<std::uint8_t>(what) != 0; }
  std::string readString(const char* what);
  /// A sequence's element count, checked against the bytes left (`element_size` each).
  std::uint32_t readCount(std::size_t element_size, const char* what);
  template <typename T>
  std::vector<T> readSequence(const char* what) {
    const std::uint32_t n = readCount(sizeof(T), what);
    std::vector<T> out(n);
    for (T& value : out) {
      value = read<T>(what);
    }
    return out;
  }
  /// `size` raw bytes (a uint8[] sequence's content), without copying.
  std::span<const std::uint8_t> readBytes(std::size_t size, const char* what);

  /// Throws unless at most `padding` bytes are left (a writer may pad the end): a message
  /// longer than its fields is of another type or layout.
  void requireEnd(std::size_t padding, const char* type) const;

  bool bigEndian() const { return big_endian_; }
  std::size_t offset() const { return offset_; }
  /// Throws the reader's Error at the current place.
  [[noreturn]] void fail(const std::string& what) const;

 private:
  void align(std::size_t size);
  void require(std::size_t size, const char* what) const;
  template <typename T>
  static T swapped(T value) {
    unsigned char b[sizeof(T)];
    std::memcpy(b, &value, sizeof(T));
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) {
      std::swap(b[i], b[sizeof(T) - 1 - i]);
    }
    std::memcpy(&value, b, sizeof(T));
    return value;
  }

  std::span<const std::uint8_t> body_;  ///< after the encapsulation header
  std::string source_;
  std::string place_;
  std::size_t offset_ = 0;
  bool big_endian_ = false;
};

/// Writes one little-endian CDR message (for the bag writer).
class CdrWriter {
 public:
  CdrWriter();
  template <typename T>
  void write(T value) {
    static_assert(std::is_arithmetic_v<T>);
    align(sizeof(T));
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &value, sizeof(T));
  }
  void writeBool(bool value) { write<std::uint8_t>(value ? 1 : 0); }
  void writeString(const std::string& text);
  void writeCount(std::size_t count) { write(static_cast<std::uint32_t>(count)); }
  template <typename T>
  void writeSequence(const std::vector<T>& values) {
    writeCount(values.size());
    for (const T& v : values) {
      write(v);
    }
  }
  void writeBytes(std::span<const std::uint8_t> bytes);
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  void align(std::size_t size);
  std::vector<std::uint8_t> bytes_;
};

}  // namespace sonarcarve
