// The parameters in which two parameter sets differ, each as a file writes it, in the schema's
// order (for comparing two runs).
#pragma once

#include <string>
#include <vector>

#include "pipeline/reconstruction_params.h"

namespace sonarcarve {

struct ParamDifference {
  std::string key;   ///< "voxel_size_m", "detector.z"
  std::string unit;  ///< "m", "" for none
  std::string a;     ///< the value in the first set ("" for none)
  std::string b;
};

std::vector<ParamDifference> differingParams(const ReconstructionParams& a,
                                             const ReconstructionParams& b);

}  // namespace sonarcarve
