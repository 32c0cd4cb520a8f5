// `sonarcarve-cli bench reconstruct MISSION`: a whole reconstruction of a mission through the
// Pipeline (every stage, frames read from disk), timed per stage, with the process's memory
// sampled against the frames carved (common/progress_trace.h). Nothing is written but the
// figures: a table (or JSON) on stdout and, with --csv, the memory samples for plotting.
#pragma once

#include <string>

#include "common/thread_pool.h"

namespace sonarcarve::cli {

struct BenchReconstructOptions {
  std::string mission;
  int frames = 0;  ///< the first this many frames; 0: all
  std::string params_file;
  std::string csv;
  bool json = false;
  int sample_every = 100;  ///< frames (or other units) between memory samples within a stage
};

int benchReconstruct(const BenchReconstructOptions& o, ThreadPool& pool);

}  // namespace sonarcarve::cli
