// Text for the HTML the report writes (pipeline/report_html.h): whatever comes from a mission
// or a run (names, paths, reasons) is escaped before it goes into the page.
#pragma once

#include <string>
#include <string_view>

namespace sonarcarve {

/// `text` with &, <, >, " and ' as character references: safe inside an element and inside
/// a quoted attribute.
std::string escapeHtml(std::string_view text);

/// `value` with `decimals` digits after the point ("12.35"); "-" for NaN and infinities.
std::string fixedText(double value, int decimals);

}  // namespace sonarcarve
