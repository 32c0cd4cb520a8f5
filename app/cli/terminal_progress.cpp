#include "cli/terminal_progress.h"

#include <unistd.h>
#include <atomic>
#include <csignal>
#include <cstdio>

namespace sonarcarve::cli {
namespace {

std::atomic<int> g_interrupts{0};

void onInterrupt(int) {
  if (g_interrupts.fetch_add(1) >= 1) {
    _exit(130);
  }
  const char message[] = "\nstopping after the current step (Ctrl-C again to quit now)\n";
  [[maybe_unused]] auto ignored = write(STDERR_FILENO, message, sizeof(message) - 1);
}

}  // namespace

TerminalProgress::TerminalProgress() : start_(std::chrono::steady_clock::now()) {
  g_interrupts = 0;
  std::signal(SIGINT, onInterrupt);
}

TerminalProgress::~TerminalProgress() {
  finish();
  std::signal(SIGINT, SIG_DFL);
}

bool TerminalProgress::cancelled() const {
  return g_interrupts.load() > 0;
}

void TerminalProgress::report(const std::string& stage, std::size_t done, std::size_t total) {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  // A terminal gets one line redrawn ten times a second; a log file a line every 5 s.
  const bool tty = isatty(STDERR_FILENO) != 0;
  if (done < total && now - last_draw_ < std::chrono::milliseconds(tty ? 100 : 5000)) {
    return;
  }
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double left = done > 0 ? elapsed * static_cast<double>(total - done) / done : 0.0;
  std::fprintf(stderr, "%s%s: %zu/%zu (%3.0f%%)  %.1f s elapsed, %.1f s left   %s", tty ? "\r" : "",
               stage.c_str(), done, total, total > 0 ? 100.0 * done / total : 100.0, elapsed, left,
               tty ? "" : "\n");
  std::fflush(stderr);
  drawn_ = tty;
}

void TerminalProgress::finish() {
  std::lock_guard lock(mutex_);
  if (drawn_) {
    std::fprintf(stderr, "\n");
    drawn_ = false;
  }
}

}  // namespace sonarcarve::cli
