// Event-loop latency of the workbench while it carves: the GUI thread must never block for
// more than 50 ms. A 5 ms timer runs on the GUI thread from the start of the run to its end;
// every gap between two ticks beyond the 5 ms is time the event loop could not answer.
//   sonarcarve_gui_latency_bench MISSION [--noise-model N.yaml] [--params P.yaml] [--runs N]
//                                [--json] [--trace] [--view-points N]
// --trace names every event that took 20 ms or more (nested events are listed too). With
// --runs N the mission runs N times (a re-run as a parameter change starts it); the resident
// memory is printed after each run, and at the end the time to close and destroy the window
// (what quitting costs after the last run). It also counts the 3D map's redraws and the 3D
// view's repaints (its frame rate while carving), the most map points the view held at once,
// and the process's peak resident memory (VmHWM).
// Run it under Xvfb (xvfb-run -a -s '-screen 0 1280x800x24'); it prints the worst gap, the
// 99th percentile and the run's duration. It asserts nothing: figures go to docs/benchmarks.md.
#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "allocator.h"
#include "common/process_memory.h"
#include "main_window.h"
#include "map_view.h"
#include "params_panel.h"
#include "vtk_gl_widget.h"

namespace {

// Times every event the GUI thread handles, to name what blocks it (with --trace).
class TimedApplication : public QApplication {
 public:
  using QApplication::QApplication;
  bool trace = false;
  bool notify(QObject* receiver, QEvent* event) override {
    if (!trace) {
      return QApplication::notify(receiver, event);
    }
    // Named before the event: a DeferredDelete event deletes its receiver.
    const int type = event->type();
    const QByteArray name = QByteArray(receiver->metaObject()->className()) + " " +
                            receiver->objectName().toLocal8Bit();
    QElapsedTimer t;
    t.start();
    const bool result = QApplication::notify(receiver, event);
    const qint64 ms = t.elapsed();
    if (ms >= 20) {
      std::fprintf(stderr, "slow event: %lld ms, type %d, %s\n", static_cast<long long>(ms), type,
                   name.constData());
    }
    return result;
  }
};

// The process's resident memory now and at its peak (VmHWM), MB of 2^20 bytes (Linux).
double residentMb() {
  const auto memory = sonarcarve::processMemory();
  return memory ? static_cast<double>(memory->resident_bytes) / (1024.0 * 1024.0) : 0.0;
}
double peakResidentMb() {
  const auto memory = sonarcarve::processMemory();
  return memory ? static_cast<double>(memory->peak_resident_bytes) / (1024.0 * 1024.0) : 0.0;
}

// Counts the paint events of a widget: the 3D view's frames.
class PaintCounter : public QObject {
 public:
  std::size_t paints = 0;
  bool eventFilter(QObject* watched, QEvent* event) override {
    paints += event->type() == QEvent::Paint ? 1 : 0;
    return QObject::eventFilter(watched, event);
  }
};

}  // namespace

int main(int argc, char** argv) {
  sonarcarve::gui::tuneAllocatorForLatency();  // as the workbench does
  sonarcarve::widgets::VtkGlWidget::setDefaultSurfaceFormat();
  TimedApplication app(argc, argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s MISSION [--noise-model FILE] [--json]\n", argv[0]);
    return 2;
  }
  bool json = false;
  int runs = 1;
  QString noise_model;
  QString params_file;
  std::size_t view_points = 0;  // the view's default budget
  for (int i = 2; i < argc; ++i) {
    const QString arg = argv[i];
    if (arg == "--json") {
      json = true;
    } else if (arg == "--trace") {
      app.trace = true;
    } else if (arg == "--noise-model" && i + 1 < argc) {
      noise_model = argv[++i];
    } else if (arg == "--params" && i + 1 < argc) {
      params_file = argv[++i];
    } else if (arg == "--view-points" && i + 1 < argc) {
      view_points = QString(argv[++i]).toULongLong();
    } else if (arg == "--runs" && i + 1 < argc) {
      runs = std::max(1, QString(argv[++i]).toInt());
    }
  }
  auto owned = std::make_unique<sonarcarve::gui::MainWindow>();
  sonarcarve::gui::MainWindow& window = *owned;
  if (!params_file.isEmpty()) {
    window.setParams(sonarcarve::ReconstructionParams::fromYamlFile(params_file.toStdString()));
  }
  if (!noise_model.isEmpty()) {
    auto p = window.paramsPanel().params();
    p.noise_model = noise_model.toStdString();
    window.setParams(p);
  }
  if (view_points > 0) {
    window.mapView().setMapPointBudget(view_points);
  }
  window.show();
  // The 3D view's map redraws and repaints while carving, the most map points it held and the
  // most voxels they stood for.
  std::size_t map_redraws = 0;
  std::size_t most_map_points = 0;
  std::size_t most_map_voxels = 0;
  QObject::connect(&window.mapView(), &sonarcarve::widgets::MapView::redrawn,
                   [&](std::size_t points) {
                     ++map_redraws;
                     most_map_points = std::max(most_map_points, points);
                     most_map_voxels = std::max(most_map_voxels, window.mapView().mapPointCount());
                   });
  PaintCounter view_paints;
  if (auto* gl = window.mapView().findChild<sonarcarve::widgets::VtkGlWidget*>()) {
    gl->installEventFilter(&view_paints);
  }

  constexpr int kTick_ms = 5;
  std::vector<double> gaps_ms;
  QElapsedTimer clock;
  QElapsedTimer run_clock;
  qint64 last_ns = 0;
  QTimer ticker;
  ticker.setTimerType(Qt::PreciseTimer);
  ticker.setInterval(kTick_ms);
  QObject::connect(&ticker, &QTimer::timeout, [&] {
    const qint64 now = clock.nsecsElapsed();
    gaps_ms.push_back(std::max(0.0, static_cast<double>(now - last_ns) / 1e6 - kTick_ms));
    last_ns = now;
  });
  int status = 0;
  const auto stop = [&](bool ok) {
    ticker.stop();
    status = ok ? 0 : 1;
    QApplication::quit();
  };
  int finished_runs = 0;
  QObject::connect(&window, &sonarcarve::gui::MainWindow::runFinished, [&] {
    ++finished_runs;
    std::fprintf(stderr, "run %d finished: resident memory %.0f MB\n", finished_runs, residentMb());
    if (finished_runs < runs) {
      QTimer::singleShot(0, &window, [&window] { window.startRun(); });
    } else {
      stop(true);
    }
  });
  QObject::connect(&window, &sonarcarve::gui::MainWindow::runFailed, [&] { stop(false); });
  // Once the window is up, open the mission (which starts the run).
  QTimer::singleShot(500, [&] {
    if (!window.openMission(QString::fromLocal8Bit(argv[1]))) {
      stop(false);
      return;
    }
    // Opening (reading the mission, the ground truth) is not carving: measure from here.
    clock.start();
    run_clock.start();
    last_ns = 0;
    ticker.start();
  });
  app.exec();
  QElapsedTimer quit_clock;
  quit_clock.start();
  owned->close();
  owned.reset();
  std::fprintf(stderr,
               "closing and destroying the window: %lld ms (resident memory then %.0f MB)\n",
               static_cast<long long>(quit_clock.elapsed()), residentMb());
  if (gaps_ms.empty()) {
    std::fprintf(stderr, "no measurement\n");
    return 1;
  }
  std::vector<double> sorted = gaps_ms;
  std::sort(sorted.begin(), sorted.end());
  const double worst = sorted.back();
  const double p99 =
      sorted[static_cast<std::size_t>(0.99 * static_cast<double>(sorted.size() - 1))];
  const double median = sorted[sorted.size() / 2];
  const double run_s = static_cast<double>(run_clock.elapsed()) / 1000.0;
  const double redraws_per_s = static_cast<double>(map_redraws) / std::max(run_s, 1e-3);
  const double paints_per_s = static_cast<double>(view_paints.paints) / std::max(run_s, 1e-3);
  if (json) {
    std::printf(
        "{\"ticks\": %zu, \"worst_block_ms\": %.1f, \"p99_block_ms\": %.1f, "
        "\"median_block_ms\": %.2f, \"run_s\": %.2f, \"map_redraws_per_s\": %.2f, "
        "\"view_paints_per_s\": %.2f, \"most_map_points_held\": %zu, \"most_map_voxels\": "
        "%zu, \"peak_resident_mb\": %.0f}\n",
        sorted.size(), worst, p99, median, run_s, redraws_per_s, paints_per_s, most_map_points,
        most_map_voxels, peakResidentMb());
  } else {
    std::printf(
        "event loop while carving: %zu ticks, worst block %.1f ms, p99 %.1f ms, median "
        "%.2f ms; run %.2f s\n"
        "3D view: map redrawn %.2f times/s, repainted %.2f times/s, at most %zu map points "
        "held (for at most %zu voxels); peak resident memory (VmHWM) %.0f MB\n",
        sorted.size(), worst, p99, median, run_s, redraws_per_s, paints_per_s, most_map_points,
        most_map_voxels, peakResidentMb());
  }
  return status;
}
