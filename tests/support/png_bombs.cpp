#include "support/png_bombs.h"

#include <zlib.h>

#include <stdexcept>
#include <vector>

namespace sonarcarve::test {
namespace {

std::string bigEndian32(std::uint32_t v) {
  std::string bytes;
  for (int shift = 24; shift >= 0; shift -= 8) {
    bytes += static_cast<char>((v >> shift) & 0xff);
  }
  return bytes;
}

// `input` deflated with a sync flush: a whole number of bytes that ends no stream.
std::string deflateSync(z_stream& z, const std::vector<unsigned char>& input) {
  std::string out;
  z.next_in = const_cast<unsigned char*>(input.data());
  z.avail_in = static_cast<uInt>(input.size());
  unsigned char buffer[1 << 14];
  do {
    z.next_out = buffer;
    z.avail_out = sizeof buffer;
    deflate(&z, Z_SYNC_FLUSH);
    out.append(reinterpret_cast<char*>(buffer), sizeof buffer - z.avail_out);
  } while (z.avail_out == 0);
  return out;
}

}  // namespace

std::string pngChunk(const std::string& type, const std::string& data) {
  const std::string body = type + data;
  const auto crc =
      crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()));
  return bigEndian32(static_cast<std::uint32_t>(data.size())) + body +
         bigEndian32(static_cast<std::uint32_t>(crc));
}

std::string zeroPng(std::uint32_t rows, std::uint32_t cols) {
  const std::vector<unsigned char> raw(std::size_t{rows} * (1 + 2 * std::size_t{cols}), 0);
  std::vector<unsigned char> idat(compressBound(static_cast<uLong>(raw.size())));
  uLongf size = static_cast<uLongf>(idat.size());
  compress(idat.data(), &size, raw.data(), static_cast<uLong>(raw.size()));
  return "\x89PNG\r\n\x1a\n" +
         pngChunk("IHDR", bigEndian32(cols) + bigEndian32(rows) + std::string("\x10\0\0\0\0", 5)) +
         pngChunk("IDAT", std::string(reinterpret_cast<char*>(idat.data()), size)) +
         pngChunk("IEND", "");
}

std::string inflationBombPng(std::uint32_t rows, std::uint32_t cols, std::uint32_t inflated_mib) {
  // A raw deflate stream of MiB after MiB of zeros: once the window is all zeros, deflating
  // another MiB of them gives the same bytes every time, so they are deflated once and repeated.
  z_stream z{};
  deflateInit2(&z, 9, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY);
  const std::vector<unsigned char> mib(std::size_t{1} << 20, 0);
  const std::string first = deflateSync(z, mib);
  const std::string again = deflateSync(z, mib);
  if (deflateSync(z, mib) != again) {
    throw std::logic_error("deflating zeros again gave other bytes");
  }
  unsigned char end[16];
  z.next_in = nullptr;
  z.avail_in = 0;
  z.next_out = end;
  z.avail_out = sizeof end;
  deflate(&z, Z_FINISH);  // an empty final block
  const std::string last(reinterpret_cast<char*>(end), sizeof end - z.avail_out);
  deflateEnd(&z);

  std::string idat = "\x78\xda";  // zlib header: deflate, 32 KiB window, best compression
  idat += first;
  for (std::uint32_t k = 1; k < inflated_mib; ++k) {
    idat += again;
  }
  idat += last;
  const uLong one_mib = adler32(1, mib.data(), static_cast<uInt>(mib.size()));
  uLong adler = one_mib;
  for (std::uint32_t k = 1; k < inflated_mib; ++k) {
    adler = adler32_combine(adler, one_mib, static_cast<z_off_t>(mib.size()));
  }
  idat += bigEndian32(static_cast<std::uint32_t>(adler));

  std::string png = "\x89PNG\r\n\x1a\n";
  png += pngChunk("IHDR", bigEndian32(cols) + bigEndian32(rows) + std::string("\x10\0\0\0\0", 5));
  // IDAT chunks of at most 1 MiB, as encoders split them.
  for (std::size_t at = 0; at < idat.size(); at += std::size_t{1} << 20) {
    png += pngChunk("IDAT", idat.substr(at, std::size_t{1} << 20));
  }
  return png + pngChunk("IEND", "");
}

}  // namespace sonarcarve::test
