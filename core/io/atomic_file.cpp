#include "io/atomic_file.h"

#include <unistd.h>
#include <fstream>
#include <system_error>

#include "common/error.h"

namespace sonarcarve {

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
  std::filesystem::path tmp = path;
  tmp += ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) {
      throw Error(path.string(), "", "cannot create temporary file " + tmp.string());
    }
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) {
      out.close();
      std::filesystem::remove(tmp);
      throw Error(path.string(), "", "write failed (disk full?); previous file kept");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp);
    throw Error(path.string(), "", "cannot replace file: " + ec.message());
  }
}

}  // namespace sonarcarve
