// The survey report page (pipeline/report_html.h) and its pieces: escaping, SHA-256 and base64,
// the pictures, and that every figure the page shows is report.json's.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>

#include "common/angles.h"
#include "common/base64.h"
#include "common/error.h"
#include "common/sha256.h"
#include "pipeline/html_text.h"
#include "pipeline/map_pictures.h"
#include "pipeline/report_html.h"
#include "pipeline/survey_plan.h"
#include "pipeline/track_plan_svg.h"
#include "support/report_figures.h"

namespace sonarcarve {
namespace {

// A report.json as a run with a ground truth writes it, with a choice that warns.
nlohmann::json sampleReport() {
  return nlohmann::json::parse(R"({
    "mission": "/data/<b>missions</b>/riser", "mission_name": "riser <script>alert('x')</script>",
    "origin_ned_m": [4760000.5, 560000.25, 0.0], "crs": "EPSG:32631", "engine": "fast",
    "detector": "ztest", "frames_used": 98, "frames_in_mission": 100, "frames_skipped": 2,
    "cancelled": false, "occupied_voxels": 123456, "surface_points": 23456,
    "mesh_vertices": 20000, "mesh_triangles": 39000, "map_megabytes": 90.123456,
    "carve_ms_per_frame_median": 151.23, "occlusion_ms_per_frame": 12.345, "total_s": 20.5678,
    "source": "mission folder",
    "sonar": {"id": "oculus-m750d", "range_min_m": 0.5, "range_max_m": 10.0, "range_bins": 380,
              "beams": 256, "horizontal_aperture_deg": 130.0, "vertical_aperture_deg": 20.0},
    "survey": {"track_length_m": 9.87654, "depth_min_m": 10.0, "depth_max_m": 19.9,
               "coverage_area_m2": 113.456},
    "choices": [
      {"name": "denoising", "value": "learned", "reason": "noise & speckle < 3 dB", "detail": "",
       "action": "", "warning": false},
      {"name": "map.bt", "value": "skipped", "reason": "the box is beyond OctoMap's keys",
       "detail": "", "action": "crop the map", "warning": true},
      {"name": "map fit", "value": "on", "reason": "unexplained: 51.9 % by the fitted map",
       "detail": "band of 1000 voxels", "action": "", "warning": false}],
    "parameters": [
      {"key": "voxel_size_m", "value": "0.03", "unit": "m", "help": "edge of a voxel",
       "changed": true},
      {"key": "detector.z", "value": "2", "unit": "", "help": "Z-test threshold",
       "changed": false}],
    "warnings": ["nav.csv: 3 rows <repeated>"],
    "evaluation": {"tau_m": 0.05, "fscore": 0.8991, "precision": 0.9312, "completeness": 0.8692,
                   "accuracy_median_m": 0.01234, "accuracy_p90_m": 0.04567,
                   "accuracy_mean_m": 0.0201, "chamfer_m": 0.0301,
                   "floating_points_over_10cm": 12},
    "mesh_evaluation": {"tau_m": 0.05, "fscore": 0.91, "precision": 0.95, "completeness": 0.87,
                        "accuracy_median_m": 0.011, "accuracy_p90_m": 0.04,
                        "accuracy_mean_m": 0.02, "chamfer_m": 0.03,
                        "floating_points_over_10cm": 3}})");
}

ReportPage samplePage() {
  ReportPage page;
  page.report_json = sampleReport().dump(2);
  page.deliverables = {{"surface_points.ply", 1234, sha256Hex("points")},
                       {"report.json", 99, sha256Hex("report")}};
  page.fans_missing = "no frame";
  return page;
}

TEST(HtmlText, EscapesWhatCouldOpenAnElementOrCloseAnAttribute) {
  EXPECT_EQ(escapeHtml("<script>alert('x') & \"y\"</script>"),
            "&lt;script&gt;alert(&#39;x&#39;) &amp; &quot;y&quot;&lt;/script&gt;");
  EXPECT_EQ(fixedText(0.12345, 3), "0.123");
  EXPECT_EQ(fixedText(NAN, 2), "-");
}

TEST(Sha256, MatchesTheStandardsExamples) {
  EXPECT_EQ(sha256Hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256Hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  const std::string million(1000000, 'a');
  EXPECT_EQ(sha256Hex(million), "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  Sha256 pieces;  // fed unevenly, across block borders
  for (std::size_t at = 0, n = 1; at < million.size(); at += n, n = n * 3 % 997 + 1) {
    pieces.update(std::string_view(million).substr(at, n));
  }
  EXPECT_EQ(pieces.hexDigest(), sha256Hex(million));
}

TEST(Base64, MatchesRfc4648) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\xfe\x00", 3)), "//4A");
}

TEST(ReportHtml, AMissionNameWithAScriptIsShownAsText) {
  const std::string html = reportHtml(samplePage());
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_NE(html.find("riser &lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<b>missions</b>"), std::string::npos);
  EXPECT_NE(html.find("nav.csv: 3 rows &lt;repeated&gt;"), std::string::npos);
}

TEST(ReportHtml, EveryFigureShownIsReportJsons) {
  const ReportPage page = samplePage();
  const std::string html = reportHtml(page);
  EXPECT_EQ(test::figureMismatches(html, page.report_json), "");
  std::set<std::string> shown;
  for (const test::ShownFigure& figure : test::shownFigures(html)) {
    shown.insert(figure.pointer);
  }
  for (const char* pointer : {"/mission_name",           "/sonar/id",
                              "/sonar/range_max_m",      "/frames_used",
                              "/frames_in_mission",      "/surface_points",
                              "/survey/track_length_m",  "/survey/coverage_area_m2",
                              "/evaluation/fscore",      "/evaluation/accuracy_median_m",
                              "/mesh_evaluation/fscore", "/choices/1/reason",
                              "/choices/1/action",       "/choices/2/detail",
                              "/parameters/0/value",     "/warnings/0",
                              "/frames_skipped",         "/crs",
                              "/origin_ned_m/0",         "/total_s"}) {
    EXPECT_TRUE(shown.count(pointer)) << pointer << " is not shown";
  }
  // The check itself finds a figure that differs.
  nlohmann::json other = sampleReport();
  other["evaluation"]["fscore"] = 0.7;
  EXPECT_NE(test::figureMismatches(html, other.dump()).find("/evaluation/fscore"),
            std::string::npos);
  EXPECT_EQ(test::shownChecksums(html),
            (std::map<std::string, std::string>{{"surface_points.ply", sha256Hex("points")},
                                                {"report.json", sha256Hex("report")}}));
}

TEST(ReportHtml, TheWarningChoiceIsHighlighted) {
  const std::string html = reportHtml(samplePage());
  const auto warn_row = html.find("<tr class=\"warn\">");
  ASSERT_NE(warn_row, std::string::npos);
  EXPECT_LT(html.find("map.bt", warn_row), html.find("</tr>", warn_row));
  EXPECT_EQ(html.find("<tr class=\"warn\">", warn_row + 1), std::string::npos);
}

TEST(ReportHtml, LoadsNothing) {
  ReportPage page = samplePage();
  page.plan_svg = "<svg></svg>";
  page.map_views = {{"From above", "points", "\x89PNG"}};
  const std::string html = reportHtml(page);
  for (const char* fetch :
       {"src=\"http", "href=", "url(", "@import", "<link", "<script", "<iframe", "<object"}) {
    EXPECT_EQ(html.find(fetch), std::string::npos) << fetch;
  }
  EXPECT_NE(html.find("src=\"data:image/png;base64,iVBORw==\""), std::string::npos);
  EXPECT_THROW(reportHtml(ReportPage{}), Error);
}

TEST(ReportHtml, WithoutAGroundTruthSaysSo) {
  nlohmann::json report = sampleReport();
  report.erase("evaluation");
  report.erase("mesh_evaluation");
  ReportPage page = samplePage();
  page.report_json = report.dump();
  const std::string html = reportHtml(page);
  EXPECT_NE(html.find("has no ground truth"), std::string::npos);
  EXPECT_EQ(html.find("/evaluation/"), std::string::npos);
  EXPECT_EQ(test::figureMismatches(html, page.report_json), "");
}

SonarModel sampleSonar() {
  return SonarModel("test", RangeBins{1.0, 0.05, 180}, BearingTable::uniform(degToRad(60.0), 64),
                    degToRad(20.0));
}

TEST(SurveyPlan, TrackLengthAndTheAreaTheFansSwept) {
  const SonarModel sonar = sampleSonar();
  PosedFrame first;
  first.index = 0;
  EXPECT_EQ(surveyPlan({}, sonar).track.size(), 0u);
  const SurveyPlan one = surveyPlan({first}, sonar);
  // A fan of 60 degrees (pi / 3) from 1 m to 10 m, level: (pi / 3) / 2 * (10^2 - 1^2).
  const double fan = std::numbers::pi / 6.0 * 99.0;
  EXPECT_NEAR(one.coverage_area_m2, fan, 0.02 * fan);
  PosedFrame second = first;
  second.index = 1;
  second.T_world_sonar.translation() = Eigen::Vector3d(0.0, 3.0, 2.0);  // 3 m east, 2 m down
  const SurveyPlan two = surveyPlan({first, second}, sonar);
  EXPECT_NEAR(two.track_length_m, std::sqrt(13.0), 1e-9);
  EXPECT_DOUBLE_EQ(two.depth_min_m, 0.0);
  EXPECT_DOUBLE_EQ(two.depth_max_m, 2.0);
  EXPECT_GT(two.coverage_area_m2, 1.2 * fan);  // overlapping, each one fan
  EXPECT_LT(two.coverage_area_m2, 2.0 * fan);
  const std::string svg = trackPlanSvg(two, {Eigen::Vector3f(5.0f, 0.0f, 1.0f)});
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_EQ(trackPlanSvg(SurveyPlan{}, {}), "");
}

TEST(MapPictures, ThreeSidesWithThePointsDrawn) {
  EXPECT_TRUE(mapPictures({}, 0.02).empty());
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 50; ++i) {  // a vertical line of points 1 m long
    points.emplace_back(4.0f, 0.0f, 10.0f + 0.02f * static_cast<float>(i));
  }
  points.emplace_back(4.5f, 0.3f, 10.5f);
  const std::vector<MapPicture> views = mapPictures(points, 0.02, 400);
  ASSERT_EQ(views.size(), 3u);
  for (const MapPicture& view : views) {
    EXPECT_EQ(view.image.cols, 400);
    EXPECT_EQ(view.image.type(), CV_8UC3);
    cv::Mat coloured;  // neither white nor grey: the points' colours
    cv::Mat channels[3];
    cv::split(view.image, channels);
    cv::absdiff(channels[0], channels[1], coloured);
    EXPECT_GT(cv::countNonZero(coloured > 30), 50) << view.title;
  }
  EXPECT_DOUBLE_EQ(scaleBarLength(7.3), 5.0);
  EXPECT_DOUBLE_EQ(scaleBarLength(0.3), 0.2);
  EXPECT_DOUBLE_EQ(scaleBarLength(1.0), 1.0);
  EXPECT_EQ(lengthLabel(0.5), "50 cm");
  EXPECT_EQ(lengthLabel(2.0), "2 m");
}

}  // namespace
}  // namespace sonarcarve
