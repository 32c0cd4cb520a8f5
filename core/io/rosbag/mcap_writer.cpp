#include "io/rosbag/mcap_writer.h"

#include <lz4frame.h>
#include <zlib.h>
#include <zstd.h>

#include <algorithm>
#include <cstring>

#include "common/error.h"
#include "io/rosbag/mcap_format.h"

namespace sonarcarve {
namespace {

template <typename T>
void put(std::vector<std::uint8_t>& out, T value) {
  const std::size_t at = out.size();
  out.resize(at + sizeof(T));
  std::memcpy(out.data() + at, &value, sizeof(T));
}

void putString(std::vector<std::uint8_t>& out, const std::string& text) {
  put(out, static_cast<std::uint32_t>(text.size()));
  out.insert(out.end(), text.begin(), text.end());
}

void putRecord(std::vector<std::uint8_t>& out, std::uint8_t op,
               const std::vector<std::uint8_t>& content) {
  out.push_back(op);
  put(out, static_cast<std::uint64_t>(content.size()));
  out.insert(out.end(), content.begin(), content.end());
}

std::vector<std::uint8_t> compress(McapChunks chunks, const std::vector<std::uint8_t>& in) {
  std::vector<std::uint8_t> out;
  if (chunks == McapChunks::Lz4) {
    out.resize(LZ4F_compressFrameBound(in.size(), nullptr));
    const std::size_t n = LZ4F_compressFrame(out.data(), out.size(), in.data(), in.size(), nullptr);
    if (LZ4F_isError(n)) {
      throw Error("MCAP writer", "", std::string("lz4: ") + LZ4F_getErrorName(n));
    }
    out.resize(n);
  } else if (chunks == McapChunks::Zstd) {
    out.resize(ZSTD_compressBound(in.size()));
    const std::size_t n = ZSTD_compress(out.data(), out.size(), in.data(), in.size(), 3);
    if (ZSTD_isError(n)) {
      throw Error("MCAP writer", "", std::string("zstd: ") + ZSTD_getErrorName(n));
    }
    out.resize(n);
  } else {
    out = in;
  }
  return out;
}

const char* compressionName(McapChunks chunks) {
  return chunks == McapChunks::Lz4 ? "lz4" : chunks == McapChunks::Zstd ? "zstd" : "";
}

}  // namespace

McapWriter::McapWriter(McapChunks chunks, std::size_t chunk_bytes)
    : chunks_(chunks), chunk_bytes_(chunk_bytes) {
  file_.assign(mcap::kMagic.begin(), mcap::kMagic.end());
  std::vector<std::uint8_t> header;
  putString(header, "ros2");
  putString(header, "sonarcarve");
  putRecord(file_, mcap::kHeader, header);
}

void McapWriter::addSchema(std::uint16_t id, const std::string& name,
                           const std::string& definition) {
  std::vector<std::uint8_t> r;
  put(r, id);
  putString(r, name);
  putString(r, "ros2msg");
  putString(r, definition);
  putRecord(file_, mcap::kSchema, r);
}

void McapWriter::addChannel(std::uint16_t id, std::uint16_t schema, const std::string& topic) {
  std::vector<std::uint8_t> r;
  put(r, id);
  put(r, schema);
  putString(r, topic);
  putString(r, "cdr");
  put(r, std::uint32_t{0});  // metadata: an empty map
  putRecord(file_, mcap::kChannel, r);
}

void McapWriter::addMessage(std::uint16_t channel, std::uint64_t log_time_ns,
                            std::uint64_t publish_time_ns, std::span<const std::uint8_t> data) {
  std::vector<std::uint8_t> r;
  put(r, channel);
  put(r, sequence_++);
  put(r, log_time_ns);
  put(r, publish_time_ns);
  r.insert(r.end(), data.begin(), data.end());
  if (chunks_ == McapChunks::None) {
    putRecord(file_, mcap::kMessage, r);
    return;
  }
  chunk_start_ns_ = chunk_.empty() ? log_time_ns : std::min(chunk_start_ns_, log_time_ns);
  chunk_end_ns_ = chunk_.empty() ? log_time_ns : std::max(chunk_end_ns_, log_time_ns);
  putRecord(chunk_, mcap::kMessage, r);
  if (chunk_.size() >= chunk_bytes_) {
    flushChunk();
  }
}

void McapWriter::flushChunk() {
  if (chunk_.empty()) {
    return;
  }
  const std::vector<std::uint8_t> stored = compress(chunks_, chunk_);
  std::vector<std::uint8_t> r;
  put(r, chunk_start_ns_);
  put(r, chunk_end_ns_);
  put(r, static_cast<std::uint64_t>(chunk_.size()));
  put(r, static_cast<std::uint32_t>(::crc32(0L, chunk_.data(), static_cast<uInt>(chunk_.size()))));
  putString(r, compressionName(chunks_));
  put(r, static_cast<std::uint64_t>(stored.size()));
  r.insert(r.end(), stored.begin(), stored.end());
  putRecord(file_, mcap::kChunk, r);
  chunk_.clear();
}

std::vector<std::uint8_t> McapWriter::finish() {
  flushChunk();
  std::vector<std::uint8_t> data_end;
  put(data_end, std::uint32_t{0});  // data section CRC not computed
  putRecord(file_, mcap::kDataEnd, data_end);
  std::vector<std::uint8_t> footer;
  put(footer, std::uint64_t{0});  // no summary section
  put(footer, std::uint64_t{0});
  put(footer, std::uint32_t{0});
  putRecord(file_, mcap::kFooter, footer);
  file_.insert(file_.end(), mcap::kMagic.begin(), mcap::kMagic.end());
  return std::move(file_);
}

}  // namespace sonarcarve
