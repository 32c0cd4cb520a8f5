// `sonarcarve-cli params --yaml | --markdown`: the defaults file, or the table of every
// parameter that docs/user-guide/parameters.md embeds (a lint test compares the two). Both
// come from the parameter schema.
#include <iostream>

#include "cli/commands.h"
#include "pipeline/param_schema.h"

namespace sonarcarve::cli {
namespace {

// Markdown table cells must not hold a bare '|'.
std::string cell(std::string_view text) {
  std::string out;
  for (const char c : text) {
    out += c == '|' ? std::string("\\|") : std::string(1, c);
  }
  return out;
}

std::string code(std::string_view text) {
  return text.empty() ? "" : "`" + std::string(text) + "`";
}

std::string panelPlace(const ParamSpec& spec) {
  std::string place = std::string(spec.gui.group) + " › " + std::string(spec.gui.label);
  return spec.gui.advanced ? place + " (more)" : place;
}

std::string defaultText(const ParamSpec& spec) {
  const std::string value = formatParam(spec, spec.defaultValue());
  return value.empty() ? "none" : code(value);
}

void printMarkdown(std::ostream& out) {
  out << "| key | CLI flag | panel | meaning | unit | default | valid values |\n"
      << "| --- | --- | --- | --- | --- | --- | --- |\n";
  for (const ParamSpec& spec : paramSchema()) {
    out << "| " << code(spec.key) << " | " << code(spec.flag) << " | " << cell(panelPlace(spec))
        << " | " << cell(spec.help) << " | " << cell(spec.unit) << " | " << cell(defaultText(spec))
        << " | " << cell(describeAccepted(spec)) << " |\n";
  }
}

}  // namespace

void addParamsCommand(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand(
      "params", "Print the default parameters YAML or the table of every parameter");
  auto yaml = std::make_shared<bool>(false);
  auto markdown = std::make_shared<bool>(false);
  cmd->add_flag("--yaml", *yaml, "The defaults as a parameters file (reconstruct --params)");
  cmd->add_flag("--markdown", *markdown,
                "Every parameter as a Markdown table: key, flag, panel, unit, default, range");
  cmd->require_option(1);
  cmd->callback([yaml, markdown, &exit_code] {
    if (*markdown) {
      printMarkdown(std::cout);
    } else {
      std::cout << ReconstructionParams{}.toYaml();
    }
    exit_code = 0;
  });
}

}  // namespace sonarcarve::cli
