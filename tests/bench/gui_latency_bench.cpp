// Event-loop latency of the workbench while it carves: the GUI thread must never block for
// more than 50 ms. A 5 ms timer runs on the GUI thread from the start of the run to its end;
// every gap between two ticks beyond the 5 ms is time the event loop could not answer.
//   sonarcarve_gui_latency_bench MISSION [--noise-model N.yaml] [--params P.yaml] [--runs N]
//                                [--json] [--trace]
// --trace names every event that took 20 ms or more (nested events are listed too). With
// --runs N the mission runs N times (a re-run as a parameter change starts it); the resident
// memory is printed after each run, and at the end the time to close and destroy the window
// (what quitting costs after the last run).
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

// The process's resident memory, MB of 2^20 bytes (Linux).
double residentMb() {
  const auto memory = sonarcarve::processMemory();
  return memory ? static_cast<double>(memory->resident_bytes) / (1024.0 * 1024.0) : 0.0;
}

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
  window.show();

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
  if (json) {
    std::printf(
        "{\"ticks\": %zu, \"worst_block_ms\": %.1f, \"p99_block_ms\": %.1f, "
        "\"median_block_ms\": %.2f, \"run_s\": %.2f}\n",
        sorted.size(), worst, p99, median, run_s);
  } else {
    std::printf(
        "event loop while carving: %zu ticks, worst block %.1f ms, p99 %.1f ms, median "
        "%.2f ms; run %.2f s\n",
        sorted.size(), worst, p99, median, run_s);
  }
  return status;
}
