// An automatic decision of a run, as data: made once by the stage that decides it and shown the
// same way by the CLI, report.json, the workbench's log and its Choices panel. The reason is for
// a survey analyst (one line, what was done and why, no internal quantity); the detail is for
// an expert (the derivation, with its figures); the action, when there is one, is what the
// analyst could do about it.
#pragma once

#include <string>
#include <vector>

namespace sonarcarve {

struct RunChoice {
  std::string name;      ///< "denoising", "shadow-aware carving", ...
  std::string value;     ///< what was chosen: "on", "off", "learned noise model", ...
  std::string reason;    ///< for an analyst: one line
  std::string detail;    ///< for an expert: how it was derived
  std::string action;    ///< what the analyst could do; empty when nothing
  bool warning = false;  ///< the choice may harm the map: the analyst should look
};

/// "denoising: learned noise model: <reason>", with "warning: " first for a warning: the one
/// line of the CLI and the workbench's log.
std::string choiceLine(const RunChoice& choice);

/// The detail and the suggested action, indented under choiceLine (CLI --verbose).
std::string choiceDetail(const RunChoice& choice);

/// The choice named `name` among `choices`, or null.
const RunChoice* findChoice(const std::vector<RunChoice>& choices, const std::string& name);

}  // namespace sonarcarve
