// A command's run into its --out folder: the folder made ready first, and, when the run fails,
// the folders made for it removed again and named on stderr, so that no empty or half-written
// folder is left that looks like a result. A folder that existed before is left to the
// command (reconstruct writes its files apart and moves them in only once all are complete).
#pragma once

#include <filesystem>
#include <functional>

namespace sonarcarve::cli {

enum class PartialOutput {
  Kept,     ///< remove the created folders only when empty (reconstruct: nothing is left)
  Removed,  ///< what the failed run wrote is no result: removed with the folder (simulate)
};

/// prepareOutputFolder(folder), then `run`; if `run` throws, removeCreatedFolders and rethrow.
int runIntoOutputFolder(const std::filesystem::path& folder, PartialOutput partial,
                        const std::function<int()>& run);

}  // namespace sonarcarve::cli
