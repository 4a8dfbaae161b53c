// Building blocks of the self-contained HTML reports (per case and per run): escaping, number
// formatting with units, one inline style sheet and a few lines of inline JavaScript that make
// tables sortable. No external resource is ever referenced, so a report opens offline.
#pragma once

#include <string>
#include <utility>

namespace cablefit::addin {

/// `text` with &, <, >, " and ' escaped for HTML text and attribute values.
std::string HtmlEscape(const std::string& text);

/// `value` with `digits` significant digits, plain or scientific as reads best ("0.0123",
/// "1.23e-06"); "–" for NaN/Inf.
std::string FormatNumber(double value, int digits = 3);

/// A length in millimetres, the one length unit of every report: "12.3 mm", "450 mm",
/// "0.0081 mm".
std::string FormatLength(double metres);

/// A deviation in `unit` ("m" -> FormatLength, else number + unit).
std::string FormatDeviation(double value, const std::string& unit);

/// An arc-length interval [m] as "0.187 \u2013 0.260" (millimetre resolution, no unit).
std::string FormatInterval(const std::pair<double, double>& interval);

/// Seconds as "0.8 s", "12 s", "2 min 5 s".
std::string FormatSeconds(double seconds);

/// The unit of a diagnosis parameter (recording-v1 names plus the force fits' nuisances);
/// `x_unit`/`y_unit` are a force curve's units, used for offsets and loop areas. "" if unknown.
std::string ParameterUnit(const std::string& name, const std::string& x_unit,
                          const std::string& y_unit);

/// What a parameter whose name does not say it means ("f_slip_1": "slip force of hysteresis
/// element 1 ..."); "" for the self-explaining ones.
std::string ParameterMeaning(const std::string& name);

/// A parameter value with its unit; radians also in degrees ("0.191 rad (10.97°)").
std::string FormatParameter(double value, const std::string& unit);

/// `<!DOCTYPE html>` ... `<body>` with the shared style sheet and `title`.
std::string PageHead(const std::string& title);
/// The sortable-table script and `</body></html>`; `footer` (already HTML) goes above it.
std::string PageTail(const std::string& footer);

/// CSS class of an effect's badge: "ok" for none, "effect" otherwise, "fail" for errors.
std::string EffectBadge(const std::string& effect);

}  // namespace cablefit::addin
