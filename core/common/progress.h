// Progress and cancellation for long work in the Qt-free core. The GUI implements it with
// queued signals, the CLI with a terminal line; the engine calls it between frames and inside
// long loops. Implementations must be thread safe: workers may call from any thread.
#pragma once

#include <atomic>
#include <cstddef>
#include <string>
#include <utility>

namespace sonarcarve {

class Progress {
 public:
  virtual ~Progress() = default;
  /// `done` of `total` units of the step named `stage` are finished.
  virtual void report(const std::string& stage, std::size_t done, std::size_t total) = 0;
  /// True once the user asked to stop; the engine then stops at the next check.
  virtual bool cancelled() const = 0;
  /// The whole run's progress, 0 to 1: the stages done and the share of the one running
  /// (pipeline/stage.h). Nothing by default.
  virtual void overall(double /*fraction*/) {}
};

/// Progress that reports nothing and is cancelled only through cancel().
class SilentProgress : public Progress {
 public:
  void report(const std::string&, std::size_t, std::size_t) override {}
  bool cancelled() const override { return cancelled_.load(std::memory_order_relaxed); }
  void cancel() { cancelled_.store(true, std::memory_order_relaxed); }

 private:
  std::atomic<bool> cancelled_{false};
};

/// Another step's progress under this step's name (a step that reuses one written for
/// another purpose); cancellation passes through.
class RenamedProgress : public Progress {
 public:
  RenamedProgress(Progress& inner, std::string stage) : inner_(inner), stage_(std::move(stage)) {}
  void report(const std::string&, std::size_t done, std::size_t total) override {
    inner_.report(stage_, done, total);
  }
  bool cancelled() const override { return inner_.cancelled(); }
  void overall(double fraction) override { inner_.overall(fraction); }

 private:
  Progress& inner_;
  std::string stage_;
};

/// Thrown by engine steps that stop because Progress::cancelled() became true.
class Cancelled : public std::exception {
 public:
  const char* what() const noexcept override { return "cancelled"; }
};

}  // namespace sonarcarve
