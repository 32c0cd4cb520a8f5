#include "io/files/temporary_file.h"

#include <cerrno>
#include <cstring>

#include "common/error.h"

namespace sonarcarve {

std::FILE* openTemporaryFile(const std::string& source) {
  std::FILE* file = std::tmpfile();
  if (file == nullptr) {
    throw Error(source, "", std::string("could not be made: ") + std::strerror(errno));
  }
  return file;
}

}  // namespace sonarcarve
