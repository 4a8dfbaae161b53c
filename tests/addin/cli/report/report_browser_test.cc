// The reports open in a real browser (headless Chromium, installed by
// tools/install-deps.sh --with-browser): no console errors, every image loads, the page is not
// blank. The screenshot is kept next to the report for a person to look at.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "cablefit/formats/png_file.h"
#include "cli_runner.h"
#include "test_support.h"

namespace cablefit {
namespace {

namespace fs = std::filesystem;

std::string Slurp(const fs::path& p) { return testing::ReadTextFile(p); }

// Runs headless Chromium on `page`, returns its stderr log; writes `png`.
std::string Screenshot(const fs::path& page, const fs::path& png, const fs::path& profile) {
  const std::string log = (png.parent_path() / "chromium.log").string();
  const std::string cmd =
      "chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run "
      "--disable-background-networking --disable-component-update --disable-sync "
      "--enable-logging=stderr --v=0 --user-data-dir='" + profile.string() +
      "' --window-size=1400,2000 --virtual-time-budget=3000 --screenshot='" + png.string() +
      "' 'file://" + page.string() + "' > /dev/null 2> '" + log + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return Slurp(log);
}

void CheckPage(const fs::path& page, const fs::path& work) {
  ASSERT_TRUE(fs::exists(page)) << page;
  // Every image the page references exists (relative links only: the folder can be copied).
  const std::string html = Slurp(page);
  const std::regex img(R"(<img[^>]*src="([^"]+)\")");
  int images = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), img); it != std::sregex_iterator(); ++it) {
    const std::string src = (*it)[1];
    EXPECT_EQ(src.find("://"), std::string::npos) << src;
    EXPECT_TRUE(fs::exists(page.parent_path() / src)) << src;
    ++images;
  }
  const fs::path png = page.parent_path() / (page.stem().string() + "-screenshot.png");
  const std::string log = Screenshot(page, png, work / "profile");
  EXPECT_EQ(log.find("CONSOLE"), std::string::npos) << log;      // console messages (errors)
  EXPECT_EQ(log.find("Uncaught"), std::string::npos) << log;
  EXPECT_EQ(log.find("Failed to load resource"), std::string::npos) << log;
  ASSERT_TRUE(fs::exists(png)) << log;
  const Image shot = ReadPng(png.string());
  // Not blank: a real page has many distinct colours and a good share of non-white pixels.
  int non_white = 0;
  std::set<int> colours;
  for (size_t i = 0; i + 2 < shot.pixels.size(); i += 3) {
    const int r = shot.pixels[i], g = shot.pixels[i + 1], b = shot.pixels[i + 2];
    if (r + g + b < 720) ++non_white;
    colours.insert((r >> 3) << 10 | (g >> 3) << 5 | (b >> 3));
  }
  EXPECT_GT(non_white, shot.width * shot.height / 50) << page;
  EXPECT_GT(colours.size(), 50u) << page;
  std::printf("%s: %d images, screenshot %dx%d, %zu colours\n", page.c_str(), images, shot.width,
              shot.height, colours.size());
}

TEST(ReportBrowserTest, DiagnoseReportsRenderInChromium) {
  if (std::system("command -v chromium > /dev/null") != 0)
    GTEST_FAIL() << "chromium is not installed (tools/install-deps.sh --with-browser)";
  const fs::path work = testing::FreshTempDir("report");
  const fs::path cases = testing::SourceDir() / "samples" / "cases";
  const auto run = testing::RunCablefit("diagnose '" + (cases / "sample-force-hysteresis").string() +
                                        "' '" + (cases / "sample-none").string() + "' --out '" +
                                        (work / "out").string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  CheckPage(work / "out" / "report.html", work);
  CheckPage(work / "out" / "sample-none" / "report.html", work);
  CheckPage(work / "out" / "sample-force-hysteresis" / "report.html", work);
}

// Runs `script` in `page` in a 1400 px wide headless Chromium and returns what it put in the
// body's data-probe attribute. The page is copied next to the original (images still load).
std::string Probe(const fs::path& page, const std::string& script, const fs::path& profile) {
  const fs::path probe = page.parent_path() / "probe.html";
  std::ofstream(probe) << Slurp(page) << "<script>" << script << "</script>\n";
  const fs::path dom = page.parent_path() / "probe-dom.html";
  const std::string cmd =
      "chromium --headless --no-sandbox --disable-gpu --no-first-run --user-data-dir='" +
      profile.string() + "' --window-size=1400,2000 --virtual-time-budget=3000 --dump-dom 'file://" +
      probe.string() + "' > '" + dom.string() + "' 2> /dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::smatch m;
  const std::string text = Slurp(dom);
  return std::regex_search(text, m, std::regex(R"re(data-probe="([^"]*)")re")) ? m[1].str() : "";
}

// The relax report at 1400 px: nothing scrolls sideways, and clicking "max deviation" sorts
// the rows by their numbers (not as text: 11.2, 12.1, 2.68 was the bug).
TEST(ReportBrowserTest, RelaxReportFitsAndSortsNumbers) {
  const fs::path work = testing::FreshTempDir("relax-report-probe");
  const fs::path harness = testing::SourceDir() / "samples" / "harness";
  const auto run = testing::RunCablefit("relax '" + (harness / "legacy_harness.step").string() +
                                        "' '" + (harness / "branched_tubes.stl").string() +
                                        "' --no-pictures --out '" + (work / "out").string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string result = Probe(work / "out" / "report.html", R"js(
    var over = document.documentElement.scrollWidth - document.documentElement.clientWidth;
    document.querySelectorAll('.table-wrap').forEach(function (e) {
      over = Math.max(over, e.scrollWidth - e.clientWidth); });
    var t = document.querySelector('table.sortable');
    var heads = Array.from(t.tHead.rows[0].cells);
    var k = heads.findIndex(function (h) { return h.textContent.indexOf('max deviation') === 0; });
    heads[k].click();
    var v = Array.from(t.tBodies[0].rows).map(function (r) {
      return parseFloat(r.cells[k].getAttribute('data-value')); });
    var sorted = v.every(function (x, i) { return i === 0 || v[i - 1] <= x; });
    document.body.setAttribute('data-probe', 'overflow=' + over + ';sorted=' + sorted + ';rows=' + v.length);
  )js", work / "profile");
  EXPECT_EQ(result, "overflow=0;sorted=true;rows=8") << result;
}

TEST(ReportBrowserTest, RelaxReportRendersInChromium) {
  const fs::path work = testing::FreshTempDir("relax-report");
  const fs::path step = testing::SourceDir() / "samples" / "harness" / "legacy_harness.step";
  const auto run = testing::RunCablefit("relax '" + step.string() + "' --out '" +
                                        (work / "out").string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  CheckPage(work / "out" / "report.html", work);
}

}  // namespace
}  // namespace cablefit
