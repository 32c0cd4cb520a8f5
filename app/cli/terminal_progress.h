// TerminalProgress: Progress for the command line. Draws one updating line on stderr (at
// most ten times a second) and turns Ctrl-C into a cancellation: the first Ctrl-C asks the
// engine to stop cleanly, a second one ends the program at once.
#pragma once

#include <chrono>
#include <mutex>

#include "common/progress.h"

namespace sonarcarve::cli {

class TerminalProgress : public Progress {
 public:
  TerminalProgress();
  ~TerminalProgress() override;
  void report(const std::string& stage, std::size_t done, std::size_t total) override;
  bool cancelled() const override;
  /// Ends the progress line.
  void finish();

 private:
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  bool drawn_ = false;
};

}  // namespace sonarcarve::cli
