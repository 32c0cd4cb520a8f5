// The parameter flags of `sonarcarve-cli reconstruct`, one per entry of the parameter schema
// (pipeline/param_schema.h): names, help and checks all come from the schema, so a parameter
// added there gets its flag here.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "pipeline/reconstruction_params.h"

namespace sonarcarve::cli {

/// What the user typed for each schema entry, in schema order.
struct ParamFlags {
  std::vector<CLI::Option*> options;
  std::vector<std::string> text;                ///< scalar values
  std::vector<std::vector<std::string>> words;  ///< values of several words (the region)
};

/// Adds a flag for every schema entry to `cmd`, in the group "Parameters".
std::shared_ptr<ParamFlags> addParamFlags(CLI::App& cmd);
/// Sets the parameters whose flags were given; throws Error naming the flag on a bad value
/// (a value outside the entry's range included, as the panel and the params YAML refuse it).
void applyParamFlags(const ParamFlags& flags, ReconstructionParams& params);

/// A CLI11 check for a flag of another command that sets the schema entry `key` (`frame
/// --smoothing`, `noise-model --smoothing`): its value must be one the entry accepts, in its
/// range, or the command line is refused naming the flag and the range.
CLI::Validator schemaCheck(std::string_view key);

}  // namespace sonarcarve::cli
