#include "pipeline/run_choice.h"

namespace sonarcarve {

std::string choiceLine(const RunChoice& choice) {
  return (choice.warning ? "warning: " : "") + choice.name + ": " + choice.value + ": " +
         choice.reason;
}

std::string choiceDetail(const RunChoice& choice) {
  std::string text = "  detail: " + choice.detail;
  if (!choice.action.empty()) {
    text += "\n  what to do: " + choice.action;
  }
  return text;
}

const RunChoice* findChoice(const std::vector<RunChoice>& choices, const std::string& name) {
  for (const RunChoice& choice : choices) {
    if (choice.name == name) {
      return &choice;
    }
  }
  return nullptr;
}

}  // namespace sonarcarve
