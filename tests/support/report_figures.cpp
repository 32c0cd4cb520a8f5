#include "support/report_figures.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>

namespace sonarcarve::test {
namespace {

// Half a unit of the last digit of a number written with `text`'s decimals.
double halfLastDigit(const std::string& text) {
  const auto point = text.find('.');
  const int decimals = point == std::string::npos ? 0 : static_cast<int>(text.size() - point - 1);
  return 0.5 * std::pow(10.0, -decimals);
}

}  // namespace

std::string unescapeHtml(const std::string& text) {
  static const std::pair<const char*, const char*> kReferences[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
  std::string plain = text;
  for (const auto& [reference, character] : kReferences) {
    for (auto at = plain.find(reference); at != std::string::npos;
         at = plain.find(reference, at + 1)) {
      plain.replace(at, std::string(reference).size(), character);
    }
  }
  return plain;
}

std::vector<ShownFigure> shownFigures(const std::string& html) {
  static const std::regex kFigure("<span data-json=\"([^\"]*)\">([^<]*)</span>");
  std::vector<ShownFigure> figures;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), kFigure);
       it != std::sregex_iterator(); ++it) {
    figures.push_back({unescapeHtml((*it)[1]), unescapeHtml((*it)[2])});
  }
  return figures;
}

std::string figureMismatches(const std::string& html, const std::string& report_json) {
  const nlohmann::json report = nlohmann::json::parse(report_json);
  std::string problems;
  for (const ShownFigure& figure : shownFigures(html)) {
    const nlohmann::json::json_pointer pointer(figure.pointer);
    if (!report.contains(pointer)) {
      problems += figure.pointer + ": not in report.json\n";
      continue;
    }
    const nlohmann::json& value = report.at(pointer);
    if (value.is_number()) {
      const double shown = std::stod(figure.text);
      if (!(std::abs(shown - value.get<double>()) <= halfLastDigit(figure.text) * (1 + 1e-9))) {
        problems +=
            figure.pointer + ": shown " + figure.text + ", report.json " + value.dump() + "\n";
      }
    } else if (value.is_string() ? value.get<std::string>() != figure.text
                                 : value.dump() != figure.text) {
      problems +=
          figure.pointer + ": shown '" + figure.text + "', report.json " + value.dump() + "\n";
    }
  }
  return problems;
}

std::map<std::string, std::string> shownChecksums(const std::string& html) {
  static const std::regex kChecksum("data-sha256=\"([^\"]*)\">([0-9a-f]*)<");
  std::map<std::string, std::string> sums;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), kChecksum);
       it != std::sregex_iterator(); ++it) {
    sums[unescapeHtml((*it)[1])] = (*it)[2];
  }
  return sums;
}

}  // namespace sonarcarve::test
