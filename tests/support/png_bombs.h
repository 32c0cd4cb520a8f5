// PNG files whose header and content disagree, for the tests of bounded decoding: an inflation
// bomb (a valid PNG whose image data inflates to far more than its header declares) and a
// valid frame of a given size.
#pragma once

#include <cstdint>
#include <string>

namespace sonarcarve::test {

/// A 16-bit grey PNG declaring rows x cols whose one zlib stream (valid, checksum included)
/// inflates to `inflated_mib` MiB of zeros: the declared image (all zero) and far more after
/// it. About 1 KiB of file a MiB inflated, built in no more time than that takes to copy.
std::string inflationBombPng(std::uint32_t rows, std::uint32_t cols, std::uint32_t inflated_mib);

/// A valid 16-bit grey PNG of rows x cols zeros.
std::string zeroPng(std::uint32_t rows, std::uint32_t cols);

/// A PNG chunk: length, type, data and CRC.
std::string pngChunk(const std::string& type, const std::string& data);

}  // namespace sonarcarve::test
