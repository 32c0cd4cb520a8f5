// End-to-end: the example mission reconstructed, then its report.html opened by a real browser
// (Debian's Chromium, headless, with every host name unresolvable): the page loads, every
// picture decodes, the figures it shows are report.json's, the checksums are the files', and
// the page renders as more than a blank sheet. Chromium comes with packaging/install-deps.sh;
// without it the test is skipped, saying so.
#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <sstream>

#include "common/sha256.h"
#include "support/cli_runner.h"
#include "support/report_figures.h"
#include "support/test_support.h"

namespace sonarcarve {
namespace {

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string chromium() {
  const test::RunResult found =
      test::runShell("command -v chromium || command -v chromium-browser");
  return found.exit_code == 0 ? found.output.substr(0, found.output.find('\n')) : std::string();
}

// Headless, offline (no host name resolves), no GPU, as root in a container.
std::string browse(const std::string& browser, const std::filesystem::path& profile) {
  return test::quoted(browser) +
         " --headless --disable-gpu --no-sandbox --no-first-run --hide-scrollbars"
         " --host-resolver-rules='MAP * ~NOTFOUND' --user-data-dir=" +
         test::quoted(profile);
}

// The page with a few lines that write, once it has loaded, each picture's decoded width into
// its element, so that --dump-dom shows them.
const char* const kProbe =
    "<script>window.addEventListener('load',()=>{for(const i of document.images)"
    "i.setAttribute('data-natural-width',i.naturalWidth);"
    "document.body.setAttribute('data-loaded','yes')});</script></body>";

class ReportPage : public ::testing::Test {
 protected:
  void SetUp() override {
    browser_ = chromium();
    if (browser_.empty()) {
      GTEST_SKIP() << "chromium is not installed (packaging/install-deps.sh installs it)";
    }
    const test::RunResult run = test::runCli("reconstruct " + test::quoted(test::exampleMission()) +
                                             " --out " + test::quoted(out()));
    ASSERT_EQ(run.exit_code, 0) << run.output;
  }
  std::filesystem::path out() const { return dir_.path() / "out"; }

  test::ScratchDir dir_;
  std::string browser_;
};

TEST_F(ReportPage, OpensOfflineInABrowserWithEveryPictureAndFigure) {
  const std::string html = readText(out() / "report.html");
  ASSERT_FALSE(html.empty());
  std::string probe = html;
  probe.replace(probe.rfind("</body>"), 7, kProbe);
  const auto probe_file = dir_.path() / "probe.html";
  std::ofstream(probe_file) << probe;
  const test::RunResult dom = test::runShell(
      browse(browser_, dir_.path() / "profile") + " --virtual-time-budget=10000 --dump-dom " +
      test::quoted("file://" + probe_file.string()) + " 2>/dev/null");
  ASSERT_EQ(dom.exit_code, 0) << dom.output;
  EXPECT_NE(dom.output.find("data-loaded=\"yes\""), std::string::npos) << dom.output.substr(0, 500);
  // Each <img> tag (not a regex: a picture's data URL is hundreds of kB long).
  int images = 0;
  for (auto at = dom.output.find("<img"); at != std::string::npos;
       at = dom.output.find("<img", at + 1)) {
    ++images;
    const std::string tag = dom.output.substr(at, dom.output.find('>', at) - at);
    const auto width = tag.find("data-natural-width=\"");
    ASSERT_NE(width, std::string::npos) << tag.substr(0, 120);
    EXPECT_GT(std::stoi(tag.substr(width + 20)), 0)
        << "a picture did not decode: " << tag.substr(0, 120);
  }
  EXPECT_EQ(images, 5);  // the map from three sides, the frame before and after denoising
  EXPECT_NE(dom.output.find("<svg class=\"plan\""), std::string::npos);
  // The figures in the page as the browser read it are report.json's.
  const std::string report = readText(out() / "report.json");
  EXPECT_GT(test::shownFigures(dom.output).size(), 40u);
  EXPECT_EQ(test::figureMismatches(dom.output, report), "");
  // The checksums are those of the files beside it.
  const auto sums = test::shownChecksums(html);
  EXPECT_EQ(sums.size(), 6u);
  for (const auto& [name, sum] : sums) {
    EXPECT_EQ(sum, sha256Hex(readText(out() / name))) << name;
  }
}

TEST_F(ReportPage, RendersAsMoreThanABlankPage) {
  const auto shot = dir_.path() / "report.png";
  const test::RunResult run =
      test::runShell(browse(browser_, dir_.path() / "profile") +
                     " --window-size=1280,2400 --screenshot=" + test::quoted(shot) + " " +
                     test::quoted("file://" + (out() / "report.html").string()) + " 2>&1");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const cv::Mat picture = cv::imread(shot.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(picture.empty()) << run.output;
  // Text, tables and pictures: many pixels far from the page's white, some of them coloured.
  cv::Mat grey;
  cv::cvtColor(picture, grey, cv::COLOR_BGR2GRAY);
  EXPECT_GT(cv::countNonZero(grey < 128), picture.total() / 200);
  cv::Mat hsv;
  cv::cvtColor(picture, hsv, cv::COLOR_BGR2HSV);
  cv::Mat channels[3];
  cv::split(hsv, channels);
  EXPECT_GT(cv::countNonZero(channels[1] > 100), picture.total() / 200);
}

}  // namespace
}  // namespace sonarcarve
