#include "cablefit/app/base/report_html.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cablefit/app/report/report_summary.h"

namespace cablefit::addin {
namespace {

TEST(ReportHtml, EscapesMarkup) {
  EXPECT_EQ(HtmlEscape("<a href=\"x\">&'</a>"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
}

TEST(ReportHtml, FormatsNumbersWithUnits) {
  EXPECT_EQ(FormatNumber(0.0123), "0.0123");
  EXPECT_EQ(FormatNumber(1.23456e-6), "1.23e-06");
  EXPECT_EQ(FormatNumber(NAN), "\u2013");
  EXPECT_EQ(FormatLength(0.0123), "12.3 mm");
  // One unit in every report: millimetres, whole ones from 100 mm on.
  EXPECT_EQ(FormatLength(4.5e-6), "0.0045 mm");
  EXPECT_EQ(FormatLength(1.5), "1500 mm");
  EXPECT_EQ(FormatLength(0.8294), "829 mm");
  EXPECT_EQ(FormatDeviation(0.004, "N"), "0.004 N");
  EXPECT_EQ(FormatParameter(std::acos(-1.0), "rad"), "3.142 rad (180.00\u00b0)");
  EXPECT_EQ(ParameterUnit("curvature", "", ""), "1/m");
  EXPECT_EQ(ParameterUnit("stiffness", "", ""), "N m/rad");
  EXPECT_EQ(ParameterUnit("loop_area", "m", "N"), "N \u00b7 m");
  EXPECT_EQ(FormatSeconds(125.0), "2 min 5 s");
}

TEST(RunSummaryHtml, IsSelfContainedSortableAndEscaped) {
  SummaryRow ok;
  ok.name = "case-a";
  ok.link = "case-a/report.html";
  ok.kind = "shape";
  ok.effect = "intrinsic_curvature";
  ok.confidence = 0.9;
  ok.interval = std::make_pair(0.1, 0.2);
  SummaryRow bad;
  bad.name = "in/b/case.json";
  bad.error = "in/b/scan.ply: truncated <vertex> data";
  SummaryRow force;
  force.name = "case-f";
  force.link = "case-f/report.html";
  force.kind = "force";
  force.effect = "stiffness";
  force.interval = std::make_pair(0.0, 0.829);
  force.clamp = 0;
  force.baseline_max = 2.5;
  force.deviation_unit = "N";
  const std::string html = RunSummaryHtml({ok, bad, force}, 3.0, 2);
  // A force case shows no interval or clamp, and its newtons are not in the shape's length
  // column (one column sorts one quantity); lengths in mm.
  EXPECT_EQ(html.find("829 mm"), std::string::npos);
  EXPECT_NE(html.find("100 mm \u2013 200 mm"), std::string::npos);
  EXPECT_NE(html.find("<td class=\"num\">\u2013</td><td class=\"num\">\u2013</td><td class=\"num\" "
                      "data-value=\"2.5\">2.5 N</td>"),
            std::string::npos);
  EXPECT_EQ(ParameterMeaning("f_slip_2").rfind("slip force of hysteresis element 2", 0), 0u);
  EXPECT_EQ(ParameterMeaning("curvature"), "");
  EXPECT_NE(html.find("<table class=\"sortable\">"), std::string::npos);
  EXPECT_NE(html.find("href=\"case-a/report.html\""), std::string::npos);
  EXPECT_NE(html.find("truncated &lt;vertex&gt; data"), std::string::npos);
  EXPECT_NE(html.find("<script>"), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
}

}  // namespace
}  // namespace cablefit::addin
