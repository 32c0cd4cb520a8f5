// Reading report.html back (pipeline/report_html.h) for tests: the figures it shows, each
// with its JSON pointer into report.json, compared with report.json's values.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace sonarcarve::test {

struct ShownFigure {
  std::string pointer;  ///< data-json: "/evaluation/fscore"
  std::string text;     ///< as shown, unescaped
};

/// Every <span data-json="..."> of `html`, in order.
std::vector<ShownFigure> shownFigures(const std::string& html);

/// The figures of `html` that differ from `report_json`'s, one line each ("" when every one
/// agrees): a number agrees within half a unit of its last digit shown, a string exactly.
std::string figureMismatches(const std::string& html, const std::string& report_json);

/// The checksums the page shows, by file name (data-sha256 cells).
std::map<std::string, std::string> shownChecksums(const std::string& html);

/// `text` with the page's character references (&amp; &lt; &gt; &quot; &#39;) decoded.
std::string unescapeHtml(const std::string& text);

}  // namespace sonarcarve::test
