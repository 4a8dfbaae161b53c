#include "cablefit/app/report/report_pictures.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <mutex>
#include <numeric>

#include "cablefit/core/solver/rod_simulation.h"
#include "cablefit/formats/deviation_views.h"
#include "cablefit/formats/plot.h"
#include "cablefit/formats/png_file.h"
#include "cablefit/app/diagnose/diagnose_output.h"
#include "cablefit/app/base/report_html.h"
#include "base/render_lock.h"

namespace cablefit::addin {
namespace {

using Intervals = std::vector<std::pair<double, double>>;

Intervals SeenIntervals(const DiagnosedCase& d) {
  if (d.observation.coverage.empty()) return {{0.0, d.recording.nominal.length}};
  return d.observation.coverage;
}

bool Seen(const Intervals& seen, double s) {
  for (const auto& [a, b] : seen)
    if (s >= a && s <= b) return true;
  return false;
}

/// The parts of [0, length] not in `seen` (seen intervals sorted by start).
Intervals Gaps(Intervals seen, double length) {
  std::sort(seen.begin(), seen.end());
  Intervals gaps;
  double at = 0.0;
  for (const auto& [a, b] : seen) {
    if (a > at + 1e-9) gaps.emplace_back(at, std::min(a, length));
    at = std::max(at, b);
  }
  if (at < length - 1e-9) gaps.emplace_back(at, length);
  return gaps;
}

/// Linear interpolation of deviation samples (s sorted ascending) at `s`, clamped at the ends.
double Interpolate(const Eigen::VectorXd& s, const Eigen::VectorXd& v, double at) {
  const Eigen::Index n = s.size();
  if (n == 0) return 0.0;
  if (at <= s[0]) return v[0];
  if (at >= s[n - 1]) return v[n - 1];
  const auto it = std::upper_bound(s.data(), s.data() + n, at);
  const Eigen::Index i = it - s.data();
  const double t = (at - s[i - 1]) / std::max(s[i] - s[i - 1], 1e-300);
  return v[i - 1] + t * (v[i] - v[i - 1]);
}

/// Deviation samples sorted by s.
void SortByS(Eigen::VectorXd* s, Eigen::VectorXd* v) {
  std::vector<Eigen::Index> order(static_cast<std::size_t>(s->size()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return (*s)[a] < (*s)[b]; });
  Eigen::VectorXd ss(s->size()), vv(v->size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    ss[static_cast<Eigen::Index>(k)] = (*s)[order[k]];
    vv[static_cast<Eigen::Index>(k)] = (*v)[order[k]];
  }
  *s = ss;
  *v = vv;
}

SupportMarkerKind MarkerKind(SupportKind kind) {
  switch (kind) {
    case SupportKind::kClip: return SupportMarkerKind::kClip;
    case SupportKind::kPin: return SupportMarkerKind::kPin;
    default: return SupportMarkerKind::kClamp;
  }
}

// Long: the stretches seen and unseen, the blamed interval and the supports are laid into one
// scene on one colour scale.
/// A simulated centreline drawn as tubes coloured by the deviation of the recording from it:
/// one coloured tube per seen stretch, grey tubes where nothing was seen (no colour is invented
/// there). The blamed interval is highlighted on every tube it overlaps.
Scene ModelScene(const DiagnosedCase& d, const Polyline& nodes, Eigen::VectorXd dev_s,
                 Eigen::VectorXd dev, const std::string& title) {
  const RodSpec& spec = d.recording.nominal;
  const double length = spec.length;
  SortByS(&dev_s, &dev);
  const Polyline line = SampleCenterline(nodes, UniformArcLengths(length, kCenterlineRows));
  const Intervals seen = SeenIntervals(d);
  Scene scene;
  scene.title = title;
  const double radius = std::max(0.5 * spec.material.diameter, length / 160.0);
  int start = 0;
  while (start < line.size() - 1) {
    const bool seen_here = Seen(seen, 0.5 * (line.s[start] + line.s[start + 1]));
    int end = start + 1;
    while (end < line.size() - 1 && Seen(seen, 0.5 * (line.s[end] + line.s[end + 1])) == seen_here)
      ++end;
    SceneTube tube;
    tube.name = seen_here ? "seen" : "not seen";
    tube.radius = radius;
    tube.centreline.s = line.s.segment(start, end - start + 1);
    tube.centreline.points = line.points.middleCols(start, end - start + 1);
    if (seen_here) {
      tube.deviation.resize(tube.centreline.s.size());
      for (Eigen::Index i = 0; i < tube.deviation.size(); ++i)
        tube.deviation[i] = Interpolate(dev_s, dev, tube.centreline.s[i]);
    } else {
      tube.flat_colour = Rgb{185, 185, 185};
    }
    scene.tubes.push_back(std::move(tube));
    start = end;
  }
  // Every effect found is highlighted where it acts and labelled with its share there.
  std::vector<std::pair<double, double>> spans;
  for (const FoundEffectSummary& f : d.effects)
    if (f.interval) spans.push_back(*f.interval);
  if (spans.empty() && d.interval) spans.push_back(*d.interval);
  for (const auto& [from, to] : spans) {
    for (std::size_t t = 0; t < scene.tubes.size(); ++t) {
      const Eigen::VectorXd& s = scene.tubes[t].centreline.s;
      const double a = std::max(from, s[0]);
      const double b = std::min(to, s[s.size() - 1]);
      if (b > a) scene.highlights.push_back({static_cast<int>(t), a, b});
    }
  }
  for (std::size_t i = 0; i < d.effects.size(); ++i) {
    const FoundEffectSummary& f = d.effects[i];
    SceneLabel label;
    label.text = (d.effects.size() > 1 ? std::to_string(i + 1) + ": " : "") + f.effect + " " +
                 FormatNumber(100.0 * f.share, 2) + " %";
    if (f.clamp && static_cast<std::size_t>(*f.clamp) < spec.supports.size())
      label.position = spec.supports[static_cast<std::size_t>(*f.clamp)].position;
    else if (f.interval)
      label.position = SampleCenterline(nodes, Eigen::VectorXd::Constant(
                                                   1, 0.5 * (f.interval->first + f.interval->second)))
                           .points.col(0);
    else
      continue;
    scene.labels.push_back(label);
  }
  // The recorded centre line, one ghost per seen stretch so that no line is drawn across a gap.
  for (const auto& [a, b] : seen) {
    std::vector<Eigen::Index> in;
    for (Eigen::Index i = 0; i < d.observation.s.size(); ++i)
      if (d.observation.s[i] >= a && d.observation.s[i] <= b) in.push_back(i);
    if (in.size() < 2) continue;
    SceneGhost ghost;
    ghost.name = "recorded centre line";
    ghost.points.resize(3, static_cast<Eigen::Index>(in.size()));
    for (std::size_t k = 0; k < in.size(); ++k)
      ghost.points.col(static_cast<Eigen::Index>(k)) = d.observation.points.col(in[k]);
    scene.ghosts.push_back(std::move(ghost));
  }
  scene.scan_points = d.scan_points;
  for (std::size_t i = 0; i < spec.supports.size(); ++i) {
    SceneSupport s;
    s.kind = MarkerKind(spec.supports[i].kind);
    s.position = spec.supports[i].position;
    // The clamp index diagnosis.json uses, and which end it holds.
    s.label = std::to_string(i);
    if (i == 0) s.label += " start";
    else if (i + 1 == spec.supports.size()) s.label += " end";
    scene.supports.push_back(s);
  }
  scene.highlighted_support = d.clamp ? *d.clamp : -1;
  scene.highlight_label = d.effects.size() > 1 ? "where the effects act" : "where the effect acts";
  scene.gravity = spec.gravity;
  return scene;
}

/// One deviation trace along s, broken (NaN) wherever consecutive points straddle a gap.
DeviationTrace Trace(const std::string& name, Eigen::VectorXd s, Eigen::VectorXd v,
                     const Intervals& gaps) {
  SortByS(&s, &v);
  std::vector<double> ts, tv;
  for (Eigen::Index i = 0; i < s.size(); ++i) {
    if (i > 0) {
      for (const auto& [a, b] : gaps) {
        // Midpoint test: the gap ends and the seen samples may disagree by a sample spacing.
        if (s[i - 1] < 0.5 * (a + b) && s[i] > 0.5 * (a + b)) {
          ts.push_back(0.5 * (a + b));
          tv.push_back(std::numeric_limits<double>::quiet_NaN());
          break;
        }
      }
    }
    ts.push_back(s[i]);
    tv.push_back(v[i]);
  }
  DeviationTrace t;
  t.name = name;
  t.s = Eigen::Map<Eigen::VectorXd>(ts.data(), static_cast<Eigen::Index>(ts.size()));
  t.deviation = Eigen::Map<Eigen::VectorXd>(tv.data(), static_cast<Eigen::Index>(tv.size()));
  return t;
}

std::vector<CasePicture> ShapePictures(const std::filesystem::path& dir, const DiagnosedCase& d) {
  const ShapeDiagnosis& sd = *d.shape;
  const std::string model = EffectsName(d);
  std::vector<CasePicture> pictures;
  const Scene nominal = ModelScene(d, sd.nominal_solution.centerline, sd.observation_s,
                                   sd.baseline_deviation,
                                   "nominal model: max deviation " + FormatLength(d.baseline.max));
  const Scene fitted = ModelScene(
      d, sd.fitted_solution.centerline, sd.observation_s, sd.fitted_deviation,
      "fitted model (" + model + "): max deviation " + FormatLength(d.fitted.max));
  RenderOptions ro;
  ro.width = 1600;
  ro.height = 1150;
  ro.show_scan_points = d.scan_points.cols() > 0;
  ro.colour_scale = CommonColourScale(nominal, fitted);
  Image views;
  {
    std::lock_guard lock(RenderMutex());
    views = RenderSideBySide(nominal, fitted, ro);
  }
  WritePng((dir / "deviation-views.png").string(), views);
  std::string caption =
      "Deviation of the recorded centre line from the simulated cable, nominal model (top) and "
      "fitted model (bottom) on one colour scale; grey tube: not seen by the recording; thin line: "
      "the recorded centre line";
  if (d.effects.size() > 1) {
    caption += "; red halo and labels: where each effect acts, with its share of the mismatch";
  } else {
    if (d.interval) caption += "; red halo: the interval where the effect acts";
    if (d.clamp) caption += "; highlighted marker: clamp " + std::to_string(*d.clamp);
  }
  pictures.push_back({"deviation-views.png", caption + "."});

  const Intervals gaps = Gaps(SeenIntervals(d), d.recording.nominal.length);
  const std::vector<DeviationTrace> traces = {
      Trace("nominal", sd.observation_s, sd.baseline_deviation, gaps),
      Trace("fitted (" + model + ")", sd.observation_s, sd.fitted_deviation, gaps)};
  PlotSpec spec = DeviationAlongArcLengthChart(traces, gaps);
  spec.title = "Deviation along the cable";
  spec.x_range = std::make_pair(0.0, d.recording.nominal.length);
  WritePng((dir / "deviation-along-s.png").string(), RenderPlot(spec, PlotOptions{1100, 560}));
  pictures.push_back({"deviation-along-s.png",
                      "Distance of each recorded centre point from the nominal and the fitted "
                      "model along the arc length; shaded: stretches the recording did not see."});
  return pictures;
}

std::vector<CasePicture> ForcePictures(const std::filesystem::path& dir, const DiagnosedCase& d) {
  std::vector<CasePicture> pictures;
  for (std::size_t i = 0; i < d.curves.size(); ++i) {
    const DiagnosedCurve& c = d.curves[i];
    PlotSpec spec = ForceCurveChart(c.recorded, &c.nominal, &c.fitted, true);
    spec.title = c.file + ": recorded, nominal and fitted (" + d.effect + ")";
    const std::string name =
        d.curves.size() == 1 ? "force-curve.png" : "force-curve-" + std::to_string(i + 1) + ".png";
    WritePng((dir / name).string(), RenderPlot(spec, PlotOptions{1100, 680}));
    pictures.push_back({name, "Recorded " + c.recorded.y_name + " against " + c.recorded.x_name +
                                  " (" + c.file + ": loading filled, unloading open, loop shaded)"
                                  " with the nominal and the fitted model."});
  }
  return pictures;
}

}  // namespace

std::vector<CasePicture> WriteCasePictures(const std::string& dir, const DiagnosedCase& d) {
  const std::filesystem::path folder(dir);
  if (d.kind == CaseKind::kShape) return ShapePictures(folder, d);
  return ForcePictures(folder, d);
}

}  // namespace cablefit::addin
