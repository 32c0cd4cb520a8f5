#include "pipeline/report_html.h"

#include <nlohmann/json.hpp>

#include "common/base64.h"
#include "common/error.h"
#include "pipeline/html_text.h"

namespace sonarcarve {
namespace {

using nlohmann::json;

const char* const kStyle = R"(
body{font-family:"DejaVu Sans",Helvetica,Arial,sans-serif;color:#222;margin:0;background:#f4f5f7}
main{max-width:1180px;margin:0 auto;padding:24px 32px;background:#fff}
h1{font-size:26px;margin:0 0 4px}h2{font-size:19px;margin:32px 0 10px;border-bottom:2px solid #2f7fd1;padding-bottom:4px}
.sub{color:#555;margin:0 0 16px}
.cards{display:flex;flex-wrap:wrap;gap:12px;margin:16px 0}
.card{border:1px solid #d8dce3;border-radius:6px;padding:10px 16px;min-width:130px}
.card b{display:block;font-size:22px}.card>span{color:#555;font-size:13px}
table{border-collapse:collapse;margin:8px 0;font-size:14px}
td,th{border-bottom:1px solid #e3e6ea;padding:5px 10px;text-align:left;vertical-align:top}
th{background:#f0f3f7}td.n{text-align:right;font-variant-numeric:tabular-nums}
tr.warn td{background:#fff1ec}tr.warn td:first-child{border-left:4px solid #d9534f}
.warnings{border:1px solid #e4a09a;background:#fff6f4;border-radius:6px;padding:8px 16px}
.warnings li{margin:4px 0}
figure{margin:8px 16px 16px 0;display:inline-block;vertical-align:top}
figcaption{font-size:13px;color:#444;max-width:560px;margin-top:4px}
figure img{display:block;border:1px solid #ddd}
code,.hash{font-family:"DejaVu Sans Mono",monospace;font-size:12px}
.muted{color:#666;font-size:13px}
details summary{cursor:pointer;margin:8px 0}
footer{color:#777;font-size:12px;margin-top:32px}
@media print{body{background:#fff}main{padding:0}}
)";

// Figures of report.json, each written in an element that names its place in the file.
class Figures {
 public:
  explicit Figures(const json& report) : report_(report) {}

  bool has(const std::string& pointer) const {
    return report_.contains(json::json_pointer(pointer));
  }
  const json& at(const std::string& pointer) const {
    return report_.at(json::json_pointer(pointer));
  }
  /// The value at `pointer` ("-" when missing): numbers with `decimals` digits after the point
  /// (whole numbers as they are), strings escaped.
  std::string operator()(const std::string& pointer, int decimals = 3) const {
    if (!has(pointer)) {
      return "-";
    }
    const json& value = at(pointer);
    std::string shown;
    if (value.is_number_integer() || value.is_number_unsigned()) {
      shown = value.dump();
    } else if (value.is_number()) {
      shown = fixedText(value.get<double>(), decimals);
    } else if (value.is_string()) {
      shown = escapeHtml(value.get<std::string>());
    } else {
      shown = escapeHtml(value.dump());
    }
    return "<span data-json=\"" + escapeHtml(pointer) + "\">" + shown + "</span>";
  }

 private:
  const json& report_;
};

std::string text(const json& report, const char* key) {
  const auto it = report.find(key);
  return it != report.end() && it->is_string() ? it->get<std::string>() : std::string();
}

std::string row(const std::string& label, const std::string& value, const std::string& unit = "") {
  return "<tr><th>" + escapeHtml(label) + "</th><td class=\"n\">" + value + "</td><td>" +
         escapeHtml(unit) + "</td></tr>";
}

std::string card(const std::string& value, const std::string& label) {
  return "<div class=\"card\"><b>" + value + "</b><span>" + escapeHtml(label) + "</span></div>";
}

std::string image(const ReportPicture& picture) {
  return "<figure><img alt=\"" + escapeHtml(picture.title) + "\" src=\"data:image/png;base64," +
         base64(picture.png) + "\"><figcaption><b>" + escapeHtml(picture.title) + ".</b> " +
         escapeHtml(picture.caption) + "</figcaption></figure>";
}

std::string header(const Figures& f) {
  std::string html = "<h1>Survey report: " + f("/mission_name") + "</h1><p class=\"sub\">" +
                     "Mission " + f("/mission") + " &middot; reconstructed by SonarCarve " +
                     escapeHtml(SONARCARVE_VERSION) + " (" + f("/engine") + " engine)</p>";
  html += "<div class=\"cards\">";
  html += card(f("/frames_used") + " of " + f("/frames_in_mission"), "frames used");
  html += card(f("/surface_points"), "surface points");
  html += card(f("/mesh_triangles"), "mesh triangles");
  html += card(f("/survey/coverage_area_m2", 1) + " m&sup2;", "area covered by the fans");
  if (f.has("/evaluation/fscore")) {
    html += card(f("/evaluation/fscore"), "F-score against the ground truth");
  }
  html += card(f("/total_s", 1) + " s", "run time");
  return html + "</div>";
}

// The choices that warn, the mission's warnings, frames left out and a cancelled run.
std::string warnings(const json& report, const Figures& f) {
  std::string items;
  const json& choices = report.value("choices", json::array());
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (choices[i].value("warning", false)) {
      const std::string at = "/choices/" + std::to_string(i);
      items += "<li><b>" + f(at + "/name") + "</b>: " + f(at + "/reason") + "</li>";
    }
  }
  const json& mission = report.value("warnings", json::array());
  for (std::size_t i = 0; i < mission.size(); ++i) {
    items += "<li>" + f("/warnings/" + std::to_string(i)) + "</li>";
  }
  if (report.value("frames_skipped", 0) > 0) {
    items +=
        "<li>" + f("/frames_skipped") + " frames could not be used (the run's log says why)</li>";
  }
  if (report.value("cancelled", false)) {
    items += "<li>The run was cancelled: the map holds what it finished.</li>";
  }
  if (items.empty()) {
    return "<h2>Warnings</h2><p>None: no automatic choice warned, and every frame was used.</p>";
  }
  return "<h2>Warnings</h2><ul class=\"warnings\">" + items + "</ul>";
}

std::string mission(const Figures& f, const ReportPage& page) {
  std::string html = "<h2>The mission</h2><table>";
  html += row("Sonar", f("/sonar/id"));
  html += row("Range", f("/sonar/range_min_m", 2) + " to " + f("/sonar/range_max_m", 2), "m");
  html += row("Beams x range bins", f("/sonar/beams") + " x " + f("/sonar/range_bins"));
  html += row("Horizontal aperture", f("/sonar/horizontal_aperture_deg", 1), "degrees");
  html += row("Vertical aperture", f("/sonar/vertical_aperture_deg", 1), "degrees");
  if (f.has("/source")) {
    html += row("Recording", f("/source"));
  }
  html += row("Frames in the mission", f("/frames_in_mission"));
  html += row("Frames used", f("/frames_used"));
  html += row("Track length", f("/survey/track_length_m", 2), "m");
  html += row("Sonar depth", f("/survey/depth_min_m", 2) + " to " + f("/survey/depth_max_m", 2),
              "m (local)");
  html += row("Area covered by the fans", f("/survey/coverage_area_m2", 1), "m\u00b2");
  if (f.has("/crs")) {
    html += row("Coordinate reference system", f("/crs"));
  }
  html +=
      row("Origin (north, east, down)",
          f("/origin_ned_m/0", 2) + ", " + f("/origin_ned_m/1", 2) + ", " + f("/origin_ned_m/2", 2),
          "m: every output is local to it");
  html += "</table>";
  if (!page.plan_svg.empty()) {
    html += "<figure>" + page.plan_svg +
            "<figcaption><b>The track in plan</b>, north up: the sonar's path (red, from the green "
            "start), the area its fans swept (blue) and the map's surface "
            "points (black).</figcaption>"
            "</figure>";
  }
  return html;
}

std::string mapSection(const Figures& f, const ReportPage& page) {
  std::string html = "<h2>The map</h2><p>" + f("/surface_points") + " surface points, " +
                     f("/occupied_voxels") + " occupied voxels; the mesh has " +
                     f("/mesh_vertices") + " vertices and " + f("/mesh_triangles") +
                     " triangles. The points are coloured by their height.</p>";
  if (page.map_views.empty()) {
    return html + "<p class=\"muted\">The run found no surface to draw.</p>";
  }
  for (const ReportPicture& picture : page.map_views) {
    html += image(picture);
  }
  return html;
}

std::string fanSection(const ReportPage& page) {
  std::string html = "<h2>A sample frame, before and after denoising</h2>";
  if (page.fans.empty()) {
    return html + "<p class=\"muted\">" + escapeHtml(page.fans_missing) + "</p>";
  }
  for (const ReportPicture& picture : page.fans) {
    html += image(picture);
  }
  return html;
}

std::string accuracy(const Figures& f) {
  std::string html = "<h2>Accuracy against the ground truth</h2>";
  if (!f.has("/evaluation")) {
    return html +
           "<p>The mission has no ground truth (a simulated mission carries one): the "
           "accuracy is not measured.</p>";
  }
  const bool mesh = f.has("/mesh_evaluation");
  const auto line = [&](const std::string& label, const std::string& key, int decimals,
                        const std::string& unit) {
    return "<tr><th>" + escapeHtml(label) + "</th><td class=\"n\">" +
           f("/evaluation/" + key, decimals) + "</td>" +
           (mesh ? "<td class=\"n\">" + f("/mesh_evaluation/" + key, decimals) + "</td>" : "") +
           "<td>" + escapeHtml(unit) + "</td></tr>";
  };
  html +=
      "<p>Distances from the map to the true surface, and the share of the visible true "
      "surface the map found, within " +
      f("/evaluation/tau_m") + " m.</p>";
  html += "<table><tr><th></th><th>surface points</th>" +
          std::string(mesh ? "<th>mesh vertices</th>" : "") + "<th></th></tr>";
  html += line("F-score", "fscore", 3, "");
  html += line("Precision (share of the map near the truth)", "precision", 3, "");
  html += line("Completeness (share of the truth found)", "completeness", 3, "");
  html += line("Median error", "accuracy_median_m", 3, "m");
  html += line("90th percentile of the error", "accuracy_p90_m", 3, "m");
  html += line("Mean error", "accuracy_mean_m", 3, "m");
  html += line("Chamfer distance", "chamfer_m", 3, "m");
  html += line("Points floating over 10 cm off", "floating_points_over_10cm", 0, "");
  return html + "</table>";
}

// The model fit's figures (issue 41), which its choices carry.
std::string fit(const json& report, const Figures& f) {
  std::string html;
  const json& choices = report.value("choices", json::array());
  for (std::size_t i = 0; i < choices.size(); ++i) {
    const std::string name = choices[i].value("name", "");
    if (name == "map fit" || name == "fitted elevation beam") {
      const std::string at = "/choices/" + std::to_string(i);
      html += "<tr><th>" + f(at + "/name") + "</th><td>" + f(at + "/reason") +
              "<br><span class=\"muted\">" + f(at + "/detail") + "</span></td></tr>";
    }
  }
  return html.empty() ? html
                      : "<h2>The model fit</h2><p>How well the fitted map explains the frames "
                        "(residuals), and what the fit found.</p><table>" +
                            html + "</table>";
}

std::string choices(const json& report, const Figures& f) {
  std::string html =
      "<h2>Parameters and automatic choices</h2><p>What the run decided by itself, and "
      "why:</p><table><tr><th>choice</th><th>value</th><th>why</th></tr>";
  const json& list = report.value("choices", json::array());
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = "/choices/" + std::to_string(i);
    const bool warns = list[i].value("warning", false);
    const bool action = !list[i].value("action", "").empty();
    html += std::string(warns ? "<tr class=\"warn\">" : "<tr>") + "<td>" + f(at + "/name") +
            "</td><td>" + f(at + "/value") + "</td><td>" + f(at + "/reason") +
            (action ? "<br><i>What you can do:</i> " + f(at + "/action") : "") + "</td></tr>";
  }
  html += "</table>";
  const json& parameters = report.value("parameters", json::array());
  std::string changed;
  std::string all;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const std::string at = "/parameters/" + std::to_string(i);
    const std::string line = "<tr><td><code>" + f(at + "/key") + "</code></td><td>" +
                             f(at + "/value") + " " + f(at + "/unit") + "</td><td>" +
                             f(at + "/help") + "</td></tr>";
    all += line;
    if (parameters[i].value("changed", false)) {
      changed += line;
    }
  }
  const std::string head = "<table><tr><th>parameter</th><th>value</th><th>meaning</th></tr>";
  html += changed.empty() ? "<p>Every parameter at its default.</p>"
                          : "<p>Parameters set for this run (the others at their defaults):</p>" +
                                head + changed + "</table>";
  return html + "<details><summary>All " + std::to_string(parameters.size()) +
         " parameters (params.yaml holds them too)</summary>" + head + all + "</table></details>";
}

std::string deliverables(const ReportPage& page) {
  std::string html =
      "<h2>Deliverables</h2><p>The files of this run, beside this report, with their size and "
      "SHA-256 checksum (<code>sha256sum FILE</code> prints it; manifest.json lists them "
      "too).</p><table><tr><th>file</th><th>bytes</th><th>SHA-256</th></tr>";
  for (const RunManifestFile& file : page.deliverables) {
    html += "<tr><td>" + escapeHtml(file.name) + "</td><td class=\"n\">" +
            std::to_string(file.bytes) + "</td><td class=\"hash\" data-sha256=\"" +
            escapeHtml(file.name) + "\">" + escapeHtml(file.sha256) + "</td></tr>";
  }
  return html + "</table>";
}

std::string timing(const Figures& f) {
  return "<h2>The run</h2><table>" +
         row("Carving time per frame (median)", f("/carve_ms_per_frame_median", 1), "ms") +
         row("Surface extraction per frame", f("/occlusion_ms_per_frame", 1), "ms") +
         row("Map memory", f("/map_megabytes", 1), "MB") + row("Total", f("/total_s", 1), "s") +
         row("Detector", f("/detector")) + "</table>";
}

}  // namespace

std::string reportHtml(const ReportPage& page) {
  const json report = json::parse(page.report_json, nullptr, false);
  if (!report.is_object()) {
    throw Error("report.json", "", "not a JSON object: the report page cannot be written");
  }
  const Figures f(report);
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
      "<title>Survey report: " +
      escapeHtml(text(report, "mission_name")) + "</title><style>" + kStyle +
      "</style></head><body><main>\n";
  html += header(f) + "\n";
  html += warnings(report, f) + "\n";
  html += mission(f, page) + "\n";
  html += mapSection(f, page) + "\n";
  html += fanSection(page) + "\n";
  html += accuracy(f) + "\n";
  html += fit(report, f) + "\n";
  html += choices(report, f) + "\n";
  html += deliverables(page) + "\n";
  html += timing(f) + "\n";
  html += "<footer>Written by SonarCarve " + escapeHtml(SONARCARVE_VERSION) +
          " from report.json, beside this page; every figure here is report.json's. The page is "
          "self-contained: it loads nothing.</footer></main></body></html>\n";
  return html;
}

}  // namespace sonarcarve
