#include "common/progress_trace.h"

namespace sonarcarve {

MemoryTrace::MemoryTrace(Progress& inner, std::size_t every, std::string frame_stage)
    : inner_(inner),
      every_(every > 0 ? every : 1),
      frame_stage_(std::move(frame_stage)),
      start_(std::chrono::steady_clock::now()) {}

double MemoryTrace::elapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void MemoryTrace::sampleLocked(const std::string& stage, std::size_t done, std::size_t total) {
  MemorySample s{elapsedSeconds(), stage, done, total, frames_carved_, {}};
  s.memory = processMemory().value_or(ProcessMemory{});
  samples_.push_back(std::move(s));
}

void MemoryTrace::sample(const std::string& stage) {
  std::lock_guard lock(mutex_);
  sampleLocked(stage, 0, 0);
}

void MemoryTrace::report(const std::string& stage, std::size_t done, std::size_t total) {
  {
    std::lock_guard lock(mutex_);
    const double now = elapsedSeconds();
    const bool new_stage = stages_.empty() || stages_.back().stage != stage;
    if (new_stage) {
      stages_.push_back({stage, now, now, total});
      next_sample_ = 0;
    }
    stages_.back().last_report_s = now;
    stages_.back().units = total;
    if (stage == frame_stage_) {
      frames_carved_ = std::max(frames_carved_, done);
    }
    if (new_stage || done >= next_sample_ || done >= total) {
      sampleLocked(stage, done, total);
      next_sample_ = (done / every_ + 1) * every_;
    }
  }
  inner_.report(stage, done, total);
}

std::vector<MemorySample> MemoryTrace::samples() const {
  std::lock_guard lock(mutex_);
  return samples_;
}

std::vector<StageSpan> MemoryTrace::stages() const {
  std::lock_guard lock(mutex_);
  return stages_;
}

}  // namespace sonarcarve
