#include "cli/param_flags.h"

#include <cctype>
#include <stdexcept>

#include "common/error.h"
#include "pipeline/param_schema.h"

namespace sonarcarve::cli {
namespace {

std::string typeName(const ParamSpec& spec) {
  switch (spec.type()) {
    case ParamType::Number:
      return "NUMBER";
    case ParamType::Integer:
      return "INT";
    case ParamType::Bool:
      return "true|false";
    case ParamType::Enum: {
      std::string names;
      for (const std::string_view choice : spec.access.choices) {
        names += (names.empty() ? "" : "|") + std::string(choice);
      }
      return names;
    }
    case ParamType::Path:
      return "FILE";
    case ParamType::Box:
      return "NUMBER";
  }
  return "";
}

std::string helpText(const ParamSpec& spec) {
  std::string help(spec.help);
  help[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(help[0])));
  const std::string value = formatParam(spec, spec.defaultValue());
  help += " (";
  if (!spec.unit.empty()) {
    help += std::string(spec.unit) + "; ";
  }
  if (spec.type() == ParamType::Box) {
    help += "N0 E0 D0 N1 E1 D1; ";
  }
  return help + "default " + (value.empty() ? "none" : value) + ")";
}

}  // namespace

std::shared_ptr<ParamFlags> addParamFlags(CLI::App& cmd) {
  const auto& schema = paramSchema();
  auto flags = std::make_shared<ParamFlags>();
  // Sized once: the options keep references into these vectors.
  flags->text.resize(schema.size());
  flags->words.resize(schema.size());
  for (std::size_t i = 0; i < schema.size(); ++i) {
    const ParamSpec& spec = schema[i];
    const std::string flag(spec.flag);
    CLI::Option* option = spec.type() == ParamType::Box
                              ? cmd.add_option(flag, flags->words[i], helpText(spec))->expected(6)
                              : cmd.add_option(flag, flags->text[i], helpText(spec));
    option->type_name(typeName(spec))->group("Parameters (override --params)");
    flags->options.push_back(option);
  }
  return flags;
}

void applyParamFlags(const ParamFlags& flags, ReconstructionParams& params) {
  const auto& schema = paramSchema();
  for (std::size_t i = 0; i < schema.size(); ++i) {
    if (flags.options[i]->count() == 0) {
      continue;
    }
    const ParamSpec& spec = schema[i];
    std::string text = flags.text[i];
    for (const std::string& word : flags.words[i]) {
      text += (text.empty() ? "" : " ") + word;
    }
    const ParsedValue parsed = parseParam(spec, text);
    if (!parsed.problem.empty()) {
      throw Error("command line", std::string(spec.flag), parsed.problem);
    }
    spec.set(params, parsed.value);
  }
}

CLI::Validator schemaCheck(std::string_view key) {
  const ParamSpec* spec = findParam(key);
  if (spec == nullptr) {
    throw std::logic_error("no parameter " + std::string(key) + " in the schema");
  }
  return CLI::Validator([spec](const std::string& text) { return parseParam(*spec, text).problem; },
                        "");
}

}  // namespace sonarcarve::cli
