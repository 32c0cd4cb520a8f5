// report: report.json's text (pipeline/report.h), before any output is written: it reads the
// ground truth, and a broken one must fail the run before a file changes. It runs after a
// cancellation too: a cancelled run reports what it finished.
#include "pipeline/report.h"
#include "pipeline/run_context.h"
#include "pipeline/stages/standard_stages.h"

namespace sonarcarve {
namespace {

class ReportStage : public Stage {
 public:
  explicit ReportStage(std::function<void(const ReconstructionResult&)> announce)
      : Stage("report", 0.02), announce_(std::move(announce)) {}
  bool runsAfterCancel() const override { return true; }

  void run(RunContext& run, Progress&) const override {
    if (announce_) {
      announce_(run.result);
    }
    run.survey = surveyPlan(run.posed, run.sonar);
    run.result.report =
        reconstructionReport(run.mission, run.sonar, run.params, run.result, run.survey, run.pool);
  }

 private:
  std::function<void(const ReconstructionResult&)> announce_;
};

}  // namespace

std::unique_ptr<Stage> makeReportStage(std::function<void(const ReconstructionResult&)> announce) {
  return std::make_unique<ReportStage>(std::move(announce));
}

}  // namespace sonarcarve
