// The navigation-error flags shared by `simulate` and `nav-error` (NavErrorSpec).
#pragma once

#include <CLI/CLI.hpp>

#include "sim/trajectory.h"

namespace sonarcarve::cli {

/// --nav-error-*, --nav-bias-* and --nav-noise-*, each writing into `spec` (the seed is the
/// command's own --seed).
void addNavErrorFlags(CLI::App& cmd, NavErrorSpec& spec);

}  // namespace sonarcarve::cli
