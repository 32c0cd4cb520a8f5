#include "pipeline/param_diff.h"

#include "pipeline/param_schema.h"

namespace sonarcarve {

std::vector<ParamDifference> differingParams(const ReconstructionParams& a,
                                             const ReconstructionParams& b) {
  std::vector<ParamDifference> differences;
  for (const ParamSpec& spec : paramSchema()) {
    std::string in_a = formatParam(spec, spec.get(a));
    std::string in_b = formatParam(spec, spec.get(b));
    if (in_a != in_b) {
      differences.push_back(
          {std::string(spec.key), std::string(spec.unit), std::move(in_a), std::move(in_b)});
    }
  }
  return differences;
}

}  // namespace sonarcarve
