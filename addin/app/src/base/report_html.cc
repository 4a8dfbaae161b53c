#include "cablefit/app/base/report_html.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace cablefit::addin {

std::string HtmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string FormatNumber(double value, int digits) {
  if (!std::isfinite(value)) return "\u2013";
  char buf[64];
  const double a = std::abs(value);
  if (a != 0.0 && (a < 1e-3 || a >= 1e6))
    std::snprintf(buf, sizeof buf, "%.*e", digits - 1, value);
  else
    std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  return buf;
}

std::string FormatLength(double metres) {
  if (!std::isfinite(metres)) return "\u2013";
  // Always millimetres, as a harness drawing is dimensioned: a column of lengths then compares
  // at a glance. Whole millimetres from 100 mm on, three significant digits below.
  const double mm = metres * 1e3;
  const double a = std::abs(mm);
  char buf[64];
  if (a >= 100.0) {
    std::snprintf(buf, sizeof buf, "%.0f mm", mm);
    return buf;
  }
  return FormatNumber(mm) + " mm";
}

std::string FormatDeviation(double value, const std::string& unit) {
  if (unit == "m") return FormatLength(value);
  return FormatNumber(value) + " " + unit;
}

std::string FormatInterval(const std::pair<double, double>& interval) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3f \u2013 %.3f", interval.first, interval.second);
  return buf;
}

std::string FormatSeconds(double seconds) {
  char buf[64];
  if (seconds < 0.1)
    std::snprintf(buf, sizeof buf, "%.0f ms", seconds * 1e3);
  else if (seconds < 10.0)
    std::snprintf(buf, sizeof buf, "%.1f s", seconds);
  else if (seconds < 120.0)
    std::snprintf(buf, sizeof buf, "%.0f s", seconds);
  else
    std::snprintf(buf, sizeof buf, "%d min %d s", static_cast<int>(seconds / 60.0),
                  static_cast<int>(std::fmod(seconds, 60.0)));
  return buf;
}

std::string ParameterUnit(const std::string& name, const std::string& x_unit,
                          const std::string& y_unit) {
  if (name == "curvature") return "1/m";
  if (name == "direction" || name == "angle" || name == "principal_angle" ||
      name == "total_bend_angle" || name == "rotation_at_clamp" || name == "alternative_angle")
    return "rad";
  if (name == "ratio" || name == "axis") return "\u2013";
  if (name == "s" || name == "s_start" || name == "s_end" || name == "width") return "m";
  if (name == "force" || name == "force_vector") return "N";
  if (name == "stiffness") return "N m/rad";
  if (name == "torque") return "N m";
  if (name == "sensor_offset" || name == "slip_force_total" || name == "noise_sigma") return y_unit;
  // Iwan elements of a hysteresis fit: stiffness k_<i> and slip force f_slip_<i>.
  if (name.rfind("f_slip_", 0) == 0) return y_unit;
  if (name.rfind("k_", 0) == 0) return y_unit.empty() ? "" : y_unit + "/" + x_unit;
  if (name == "element_count") return "\u2013";
  if (name == "loop_area" || name == "recorded_loop_area")
    return y_unit.empty() ? "" : y_unit + " \u00b7 " + x_unit;
  return "";
}

std::string ParameterMeaning(const std::string& name) {
  // The numbered parameters of a hysteresis fit: Iwan elements (a spring in series with a
  // slider), each sticking up to its slip force.
  if (name.rfind("f_slip_", 0) == 0)
    return "slip force of hysteresis element " + name.substr(7) + " (slider in series with k_" +
           name.substr(7) + ")";
  if (name.rfind("k_", 0) == 0) return "stiffness of hysteresis element " + name.substr(2);
  if (name == "element_count") return "hysteresis elements fitted";
  if (name == "slip_force_total") return "sum of the elements' slip forces";
  if (name == "sensor_offset") return "constant offset of the recorded force or moment";
  if (name == "noise_sigma") return "scatter of the recording about the fitted curve";
  if (name == "loop_area") return "area of the fitted hysteresis loop";
  if (name == "recorded_loop_area") return "area of the recorded hysteresis loop";
  return "";
}

std::string FormatParameter(double value, const std::string& unit) {
  std::string text = FormatNumber(value, 4);
  if (!unit.empty() && unit != "\u2013") text += " " + unit;
  if (unit == "rad" && std::isfinite(value)) {
    char buf[48];
    std::snprintf(buf, sizeof buf, " (%.2f\u00b0)", value * 180.0 / std::numbers::pi);
    text += buf;
  }
  return text;
}

std::string EffectBadge(const std::string& effect) {
  if (effect == "none") return "ok";
  if (effect.empty() || effect == "failed") return "fail";
  return "effect";
}

namespace {

constexpr const char* kStyle = R"css(
:root { --ink:#1d2430; --muted:#5b6575; --line:#d9dee7; --bg:#f5f7fa; --card:#fff;
        --accent:#1f5fa8; --ok:#2e7d4f; --warn:#b35c00; --fail:#b3261e; }
* { box-sizing: border-box; }
body { margin:0; background:var(--bg); color:var(--ink);
       font:15px/1.5 "DejaVu Sans", "Segoe UI", Helvetica, Arial, sans-serif; }
header.top { background:#1d2a3a; color:#fff; padding:18px 32px; }
header.top h1 { margin:0; font-size:22px; font-weight:600; letter-spacing:.2px; }
header.top .sub { color:#b8c4d4; font-size:13px; margin-top:4px; }
header.top a { color:#b8d4f5; }
main { max-width:1500px; margin:0 auto; padding:20px 32px 40px; }
section.card { background:var(--card); border:1px solid var(--line); border-radius:8px;
               padding:18px 22px; margin:18px 0; box-shadow:0 1px 2px rgba(20,30,50,.05); }
section.card h2 { margin:0 0 12px; font-size:17px; font-weight:600; color:var(--ink); }
p.explanation { font-size:16px; margin:6px 0 0; }
.facts { display:grid; grid-template-columns:repeat(auto-fill,minmax(210px,1fr)); gap:10px 18px; }
.fact { border-left:3px solid var(--line); padding:2px 10px; }
.fact .k { color:var(--muted); font-size:12px; text-transform:uppercase; letter-spacing:.4px; }
.fact .v { font-size:17px; font-weight:600; }
table { border-collapse:collapse; width:100%; font-variant-numeric:tabular-nums; }
th, td { text-align:left; padding:7px 10px; border-bottom:1px solid var(--line); vertical-align:top; }
th { background:#eef1f6; font-weight:600; font-size:13px; color:#334; white-space:nowrap; }
td.num, th.num { text-align:right; white-space:nowrap; }
td:first-child { white-space:nowrap; }
table.sortable th { cursor:pointer; user-select:none; }
table.sortable th:after { content:" \2195"; color:#9aa5b5; font-size:11px; }
table.sortable th.asc:after { content:" \2191"; color:var(--accent); }
table.sortable th.desc:after { content:" \2193"; color:var(--accent); }
tr:hover td { background:#f8fafd; }
.badge { display:inline-block; padding:1px 9px; border-radius:10px; font-size:13px; font-weight:600;
         white-space:nowrap; }
.badge.ok { background:#e3f3e9; color:var(--ok); }
.badge.effect { background:#fdeedd; color:var(--warn); }
.badge.fail { background:#fbe4e2; color:var(--fail); }
.bar { background:#e8ecf2; border-radius:3px; height:10px; min-width:120px; position:relative; }
.bar > span { position:absolute; left:0; top:0; bottom:0; background:var(--accent); border-radius:3px; }
tr.best td { font-weight:600; }
figure { margin:8px 0 18px; }
figure img { max-width:100%; height:auto; border:1px solid var(--line); border-radius:4px;
             background:#fff; display:block; }
figcaption { color:var(--muted); font-size:13px; margin-top:6px; }
.grid2 { display:grid; grid-template-columns:1fr 1fr; gap:18px; }
@media (max-width:1100px) { .grid2 { grid-template-columns:1fr; } }
ul.notes { margin:0; padding-left:20px; color:var(--warn); }
a { color:var(--accent); }
footer { color:var(--muted); font-size:12px; text-align:center; padding:10px 0 30px; }
.error { color:var(--fail); }
p.provenance { color:var(--muted); font-size:12px; overflow-wrap:anywhere; margin:8px 0 0; }
.table-wrap { overflow-x:auto; }
td small { color:var(--muted); }
td.notes { min-width:120px; overflow-wrap:anywhere; }
table.dense td:first-child { white-space:normal; }
table.dense th, table.dense td { padding:6px 6px; font-size:14px; }
table.dense td.num small { white-space:normal; }
code { font-family:"DejaVu Sans Mono", Menlo, Consolas, monospace; font-size:13px; }
)css";

// Click a header to sort by it (numbers by their data-value, else text); again to reverse.
constexpr const char* kSortScript = R"js(
document.querySelectorAll('table.sortable').forEach(function (table) {
  table.querySelectorAll('th').forEach(function (th, col) {
    th.addEventListener('click', function () {
      var body = table.tBodies[0], rows = Array.from(body.rows);
      var asc = !th.classList.contains('asc');
      table.querySelectorAll('th').forEach(function (h) { h.classList.remove('asc', 'desc'); });
      th.classList.add(asc ? 'asc' : 'desc');
      var key = function (r) { var c = r.cells[col]; var v = c.getAttribute('data-value');
        return v !== null && v !== '' && !isNaN(v) ? parseFloat(v) : c.textContent.trim().toLowerCase(); };
      rows.sort(function (a, b) { var x = key(a), y = key(b);
        if (typeof x !== typeof y) { x = String(x); y = String(y); }
        return (x < y ? -1 : x > y ? 1 : 0) * (asc ? 1 : -1); });
      rows.forEach(function (r) { body.appendChild(r); });
    });
  });
});
)js";

}  // namespace

std::string PageHead(const std::string& title) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
         HtmlEscape(title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n";
}

std::string PageTail(const std::string& footer) {
  return "<footer>" + footer + "</footer>\n<script>" + std::string(kSortScript) +
         "</script>\n</body>\n</html>\n";
}

}  // namespace cablefit::addin
