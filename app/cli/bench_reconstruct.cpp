#include "cli/bench_reconstruct.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/terminal_progress.h"
#include "common/error.h"
#include "common/progress_trace.h"
#include "io/files/atomic_file.h"
#include "io/frame_source.h"
#include "pipeline/reconstruction.h"

namespace sonarcarve::cli {
namespace {

struct StageFigure {
  std::string stage;
  double seconds = 0.0;
};

// Each stage from the end of the one before (or from `opened_s`) to its own last report.
std::vector<StageFigure> stageFigures(const std::vector<StageSpan>& spans, double opened_s) {
  std::vector<StageFigure> figures;
  double from = opened_s;
  for (const StageSpan& span : spans) {
    figures.push_back({span.stage, std::max(0.0, span.last_report_s - from)});
    from = std::max(from, span.last_report_s);
  }
  return figures;
}

// Frames per second of the mission: the median time between frames (a lawnmower's turns,
// where no frame is taken, do not count).
double frameRate(const Mission& mission, std::size_t frames) {
  std::vector<double> gaps;
  for (std::size_t i = 1; i < std::min(frames, mission.frames.size()); ++i) {
    gaps.push_back(mission.frames[i].time_s - mission.frames[i - 1].time_s);
  }
  if (gaps.empty()) {
    return 0.0;
  }
  std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
  const double gap = gaps[gaps.size() / 2];
  return gap > 0.0 ? 1.0 / gap : 0.0;
}

std::string samplesCsv(const std::vector<MemorySample>& samples) {
  std::ostringstream out;
  out << "time_s,stage,done,total,frames_carved,rss_mb,peak_rss_mb,rss_anon_mb\n";
  for (const MemorySample& s : samples) {
    char line[256];
    std::snprintf(line, sizeof line, "%.3f,%s,%zu,%zu,%zu,%.1f,%.1f,%.1f\n", s.time_s,
                  s.stage.c_str(), s.done, s.total, s.frames_carved,
                  megabytes(s.memory.resident_bytes), megabytes(s.memory.peak_resident_bytes),
                  megabytes(s.memory.anonymous_bytes));
    out << line;
  }
  return out.str();
}

}  // namespace

int benchReconstruct(const BenchReconstructOptions& o, ThreadPool& pool) {
  TerminalProgress terminal;
  MemoryTrace trace(terminal, static_cast<std::size_t>(std::max(1, o.sample_every)));
  trace.sample("start");
  const Mission mission = openMission(o.mission);
  ReconstructionParams params = o.params_file.empty()
                                    ? ReconstructionParams{}
                                    : ReconstructionParams::fromYamlFile(o.params_file);
  if (o.frames > 0) {
    if (static_cast<std::size_t>(o.frames) > mission.frames.size()) {
      std::ostringstream text;
      text << "asks for " << o.frames << " frames: the mission holds " << mission.frames.size();
      throw Error("--frames", "", text.str());
    }
    params.first_frame = 0;
    params.last_frame = o.frames;
  }
  const Pipeline pipeline(mission, params, pool);
  const double opened_s = trace.elapsedSeconds();
  trace.sample("opened");
  const ReconstructionResult result = pipeline.run(trace);
  trace.sample("end");
  terminal.finish();
  const double total_s = trace.elapsedSeconds();

  const std::size_t frames = result.frames_used;
  const double rate = frameRate(mission, selectedFrames(mission, params).size());
  const double mission_s = rate > 0.0 ? static_cast<double>(frames) / rate : 0.0;
  const double real_time_factor = total_s > 0.0 ? mission_s / total_s : 0.0;
  const std::vector<MemorySample> samples = trace.samples();
  const ProcessMemory end = samples.back().memory;
  std::vector<StageFigure> figures = stageFigures(trace.stages(), opened_s);
  figures.insert(figures.begin(), {"open", opened_s});
  const auto per_frame = [&](double s) {
    return frames > 0 ? 1000.0 * s / static_cast<double>(frames) : 0.0;
  };
  if (!o.csv.empty()) {
    writeFileAtomically(o.csv, samplesCsv(samples));
  }
  if (o.json) {
    nlohmann::json stages = nlohmann::json::array();
    for (const StageFigure& f : figures) {
      stages.push_back(
          {{"stage", f.stage}, {"seconds", f.seconds}, {"ms_per_frame", per_frame(f.seconds)}});
    }
    nlohmann::json memory = nlohmann::json::array();
    for (const MemorySample& s : samples) {
      memory.push_back({{"time_s", s.time_s},
                        {"stage", s.stage},
                        {"frames_carved", s.frames_carved},
                        {"rss_mb", megabytes(s.memory.resident_bytes)},
                        {"peak_rss_mb", megabytes(s.memory.peak_resident_bytes)},
                        {"rss_anon_mb", megabytes(s.memory.anonymous_bytes)}});
    }
    const nlohmann::json j = {{"bench", "reconstruct"},
                              {"mission", o.mission},
                              {"frames", frames},
                              {"cancelled", result.cancelled},
                              {"threads", pool.size()},
                              {"frame_rate_hz", rate},
                              {"mission_seconds", mission_s},
                              {"total_seconds", total_s},
                              {"ms_per_frame", per_frame(total_s)},
                              {"real_time_factor", real_time_factor},
                              {"peak_rss_mb", megabytes(end.peak_resident_bytes)},
                              {"end_rss_mb", megabytes(end.resident_bytes)},
                              {"end_rss_anon_mb", megabytes(end.anonymous_bytes)},
                              {"occupied_voxels", result.occupied_voxels},
                              {"map_mb", megabytes(result.map_bytes)},
                              {"surface_points", result.surface.size()},
                              {"mesh_triangles", result.mesh.triangles.size()},
                              {"stages", stages},
                              {"memory", memory}};
    std::printf("%s\n", j.dump(2).c_str());
    return result.cancelled ? 130 : 0;
  }
  std::printf("reconstruct %s: %zu frames at %.1f Hz (%.0f s of mission), %u threads%s\n",
              o.mission.c_str(), frames, rate, mission_s, pool.size(),
              result.cancelled ? ", CANCELLED" : "");
  std::printf("  %-12s %10s %12s\n", "stage", "seconds", "ms/frame");
  for (const StageFigure& f : figures) {
    std::printf("  %-12s %10.1f %12.1f\n", f.stage.c_str(), f.seconds, per_frame(f.seconds));
  }
  std::printf("  %-12s %10.1f %12.1f\n", "total", total_s, per_frame(total_s));
  std::printf(
      "  real-time factor %.2f (mission time / processing time; above 1 is faster than "
      "real time)\n",
      real_time_factor);
  std::printf("  peak RSS %.0f MB (VmHWM); at the end RSS %.0f MB, anonymous %.0f MB\n",
              megabytes(end.peak_resident_bytes), megabytes(end.resident_bytes),
              megabytes(end.anonymous_bytes));
  std::printf("  map %.0f MB, %zu occupied voxels, %zu surface points, %zu mesh triangles\n",
              megabytes(result.map_bytes), result.occupied_voxels, result.surface.size(),
              result.mesh.triangles.size());
  std::printf("  %-10s %-12s %12s %12s %12s\n", "frames", "stage", "RSS MB", "peak MB", "anon MB");
  for (const MemorySample& s : samples) {  // the ends of stages (every sample: --csv, --json)
    if (s.done < s.total) {
      continue;
    }
    std::printf("  %-10zu %-12s %12.0f %12.0f %12.0f\n", s.frames_carved, s.stage.c_str(),
                megabytes(s.memory.resident_bytes), megabytes(s.memory.peak_resident_bytes),
                megabytes(s.memory.anonymous_bytes));
  }
  return result.cancelled ? 130 : 0;
}

}  // namespace sonarcarve::cli
