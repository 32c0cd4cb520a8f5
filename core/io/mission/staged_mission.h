// A mission written apart first (io/run/staged_outputs.h) and moved into its folder only once
// complete: a run that fails part-way (a full disk) leaves an earlier mission there as it was,
// and one that succeeds leaves its own mission only, never frames, navigation and ground truth
// of two runs mixed (simulate --force into a folder that holds a mission).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/run/staged_outputs.h"

namespace sonarcarve {

/// Moves every file and folder of the staged mission into the output folder: the earlier
/// mission.yaml is removed first (so that a move that fails midway leaves no mission that
/// reads as complete), the files and folders are moved in, mission.yaml last. Then each of
/// `earlier_files` (names an earlier run may have written) that this mission does not hold is
/// removed from the output folder. Returns the paths removed that way. What is in the way of a
/// move (StagedOutputs::requireTarget) is refused before anything moves. Throws Error naming
/// the file that could not be moved.
std::vector<std::filesystem::path> publishStagedMission(
    const StagedOutputs& staged, const std::vector<std::string>& earlier_files);

}  // namespace sonarcarve
