#include "io/files/decompress.h"

#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>

#include "common/error.h"

namespace sonarcarve {

std::vector<std::uint8_t> decompressLz4Frame(std::span<const std::uint8_t> in,
                                             std::uint64_t max_size, const std::string& source,
                                             const std::string& place) {
  LZ4F_dctx* ctx = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION))) {
    throw Error(source, place, "cannot create an lz4 decompression context");
  }
  std::vector<std::uint8_t> out;
  std::size_t in_pos = 0;
  std::string problem;
  while (problem.empty()) {
    const std::size_t step = std::min<std::uint64_t>(max_size - out.size() + 1, 1 << 20);
    const std::size_t old = out.size();
    out.resize(old + step);
    std::size_t out_size = step;
    std::size_t in_size = in.size() - in_pos;
    const std::size_t hint =
        LZ4F_decompress(ctx, out.data() + old, &out_size, in.data() + in_pos, &in_size, nullptr);
    out.resize(old + out_size);
    in_pos += in_size;
    if (LZ4F_isError(hint)) {
      problem = std::string("lz4 data is corrupt (") + LZ4F_getErrorName(hint) + ")";
    } else if (out.size() > max_size) {
      problem = "lz4 data expands beyond " + std::to_string(max_size) + " bytes";
    } else if (hint == 0) {
      break;  // the frame is complete
    } else if (in_size == 0 && out_size == 0) {
      problem = "lz4 frame is cut short";
    }
  }
  LZ4F_freeDecompressionContext(ctx);
  if (!problem.empty()) {
    throw Error(source, place, problem);
  }
  return out;
}

std::vector<std::uint8_t> decompressZstdFrame(std::span<const std::uint8_t> in,
                                              std::uint64_t max_size, const std::string& source,
                                              const std::string& place) {
  ZSTD_DStream* stream = ZSTD_createDStream();
  if (stream == nullptr) {
    throw Error(source, place, "cannot create a zstd decompression context");
  }
  std::vector<std::uint8_t> out;
  ZSTD_inBuffer input{in.data(), in.size(), 0};
  std::string problem;
  std::size_t hint = 1;
  while (problem.empty() && hint != 0) {
    const std::size_t step = std::min<std::uint64_t>(max_size - out.size() + 1, 1 << 20);
    const std::size_t old = out.size();
    out.resize(old + step);
    ZSTD_outBuffer output{out.data() + old, step, 0};
    hint = ZSTD_decompressStream(stream, &output, &input);
    out.resize(old + output.pos);
    if (ZSTD_isError(hint)) {
      problem = std::string("zstd data is corrupt (") + ZSTD_getErrorName(hint) + ")";
    } else if (out.size() > max_size) {
      problem = "zstd data expands beyond " + std::to_string(max_size) + " bytes";
    } else if (hint != 0 && input.pos == input.size && output.pos == 0) {
      problem = "zstd frame is cut short";
    }
  }
  ZSTD_freeDStream(stream);
  if (!problem.empty()) {
    throw Error(source, place, problem);
  }
  return out;
}

bool isZstdFrame(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= 4 && bytes[0] == 0x28 && bytes[1] == 0xB5 && bytes[2] == 0x2F &&
         bytes[3] == 0xFD;
}

}  // namespace sonarcarve
