#include "cli/output_folder_run.h"

#include <iostream>
#include <vector>

#include "io/files/output_folder.h"

namespace sonarcarve::cli {

int runIntoOutputFolder(const std::filesystem::path& folder, PartialOutput partial,
                        const std::function<int()>& run) {
  const std::vector<std::filesystem::path> created = prepareOutputFolder(folder);
  try {
    return run();
  } catch (...) {
    for (const std::filesystem::path& removed :
         removeCreatedFolders(created, partial == PartialOutput::Removed)) {
      std::cerr << "removed " << removed.string()
                << ", which this run had created: the run failed and left no result\n";
    }
    throw;
  }
}

}  // namespace sonarcarve::cli
