#include "io/atomic_file.h"

#include <unistd.h>
#include <fstream>
#include <system_error>

#include "common/error.h"

namespace sonarcarve {

void replaceFileAtomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path&)>& write) {
  // Keep the extension last: some writers (VTK's PLY, OpenCV's) choose the format by it.
  std::filesystem::path tmp = path;
  tmp.replace_filename(path.stem().string() + ".tmp-" + std::to_string(::getpid()) +
                       path.extension().string());
  std::error_code ec;
  try {
    write(tmp);
  } catch (...) {
    std::filesystem::remove(tmp, ec);
    throw;
  }
  if (!std::filesystem::is_regular_file(tmp)) {
    throw Error(path.string(), "", "writing failed; previous file kept");
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw Error(path.string(), "", "cannot replace file: " + ec.message());
  }
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  replaceFileAtomically(path, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw Error(path.string(), "", "cannot create temporary file " + tmp.string());
    }
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      throw Error(path.string(), "", "write failed (disk full?); previous file kept");
    }
  });
}

}  // namespace sonarcarve
