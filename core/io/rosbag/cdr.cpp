#include "io/rosbag/cdr.h"

#include "common/error.h"

namespace sonarcarve {
namespace {
constexpr std::size_t kEncapsulationSize = 4;
}  // namespace

CdrReader::CdrReader(std::span<const std::uint8_t> message, std::string source, std::string place)
    : source_(std::move(source)), place_(std::move(place)) {
  if (message.size() < kEncapsulationSize) {
    throw Error(source_, place_,
                "CDR message of " + std::to_string(message.size()) +
                    " bytes: expected at least the 4-byte encapsulation header");
  }
  if (message[0] != 0 || message[1] > 1) {
    throw Error(source_, place_,
                "CDR encapsulation " + std::to_string(message[0]) + " " +
                    std::to_string(message[1]) +
                    ": expected 00 01 (little-endian CDR) or 00 00 (big-endian CDR)");
  }
  big_endian_ = message[1] == 0;
  body_ = message.subspan(kEncapsulationSize);
}

void CdrReader::fail(const std::string& what) const {
  throw Error(source_, place_ + ", CDR byte " + std::to_string(offset_ + kEncapsulationSize), what);
}

void CdrReader::align(std::size_t size) {
  const std::size_t padded = (offset_ + size - 1) / size * size;
  offset_ = std::min(padded, body_.size());
}

void CdrReader::require(std::size_t size, const char* what) const {
  if (body_.size() - offset_ < size) {
    fail(std::string("message ends early: expected ") + what + " (" + std::to_string(size) +
         " bytes, " + std::to_string(body_.size() - offset_) + " left)");
  }
}

void CdrReader::requireEnd(std::size_t padding, const char* type) const {
  const std::size_t left = body_.size() - offset_;
  if (left > padding) {
    fail(std::to_string(left) + " bytes after the last field of " + type +
         ": expected the end of the message (is it another type, or another version?)");
  }
}

std::string CdrReader::readString(const char* what) {
  const std::uint32_t length = readCount(1, what);
  if (length == 0) {
    return {};  // some writers put 0 for an empty string
  }
  const std::span<const std::uint8_t> bytes = readBytes(length, what);
  if (bytes.back() != 0) {
    fail(std::string(what) + " is not terminated by a NUL byte (expected a CDR string)");
  }
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size() - 1};
}

std::uint32_t CdrReader::readCount(std::size_t element_size, const char* what) {
  const auto count = read<std::uint32_t>(what);
  // Elements are aligned to their size: at most element_size - 1 bytes of padding first.
  const std::size_t left = body_.size() - offset_;
  if (static_cast<std::uint64_t>(count) * element_size > left) {
    fail(std::string(what) + " claims " + std::to_string(count) + " elements of " +
         std::to_string(element_size) + " bytes: only " + std::to_string(left) + " bytes left");
  }
  return count;
}

std::span<const std::uint8_t> CdrReader::readBytes(std::size_t size, const char* what) {
  require(size, what);
  const auto out = body_.subspan(offset_, size);
  offset_ += size;
  return out;
}

CdrWriter::CdrWriter() : bytes_{0x00, 0x01, 0x00, 0x00} {}

void CdrWriter::align(std::size_t size) {
  const std::size_t body = bytes_.size() - kEncapsulationSize;
  const std::size_t padded = (body + size - 1) / size * size;
  bytes_.resize(kEncapsulationSize + padded, 0);
}

void CdrWriter::writeString(const std::string& text) {
  writeCount(text.size() + 1);
  bytes_.insert(bytes_.end(), text.begin(), text.end());
  bytes_.push_back(0);
}

void CdrWriter::writeBytes(std::span<const std::uint8_t> bytes) {
  bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
}

}  // namespace sonarcarve
