#include "cablefit/app/diagnose/shape_explanation.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cablefit::addin {
namespace {

std::string Mm(double metres) {
  std::ostringstream os;
  os.precision(metres < 1e-3 ? 2 : 3);
  os << metres * 1e3 << " mm";
  return os.str();
}

std::string Fixed(double v, int digits) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << v;
  return os.str();
}

double Parameter(const FoundEffect& d, const char* name) {
  const auto it = d.parameters.find(name);
  return it == d.parameters.end() ? 0.0 : it->second;
}

double ClampS(const RodSpec& nominal, double clamp) {
  const auto k = static_cast<size_t>(clamp);
  return k < nominal.supports.size() ? nominal.supports[k].s : 0.0;
}

// What one found effect is, in the cable's terms, ending with `tail`.
std::string Sentence(const FoundEffect& d, const RodSpec& nominal, const std::string& tail) {
  std::ostringstream ex;
  const std::string& improve = tail;
  const double clamp_s = d.clamp ? ClampS(nominal, *d.clamp) : 0.0;
  switch (d.effect) {
    case ShapeEffect::kNone:
      break;
    case ShapeEffect::kIntrinsicCurvature: {
      const double kappa = Parameter(d, "curvature");
      const auto span = d.interval.value_or(std::make_pair(0.0, 0.0));
      ex << "The cable has a natural curvature of " << Fixed(kappa, 2) << " 1/m (bend radius "
         << Fixed(kappa > 0 ? 1e3 / kappa : 0, 0) << " mm) between s=" << Fixed(span.first, 3)
         << " m and s=" << Fixed(span.second, 3)
         << " m — a set from coiling, transport or a kink" << improve;
      break;
    }
    case ShapeEffect::kClampOrientation: {
      const auto it = d.vectors.find("axis");
      const Vec3 axis = it == d.vectors.end() ? Vec3::Zero() : it->second;
      ex << "The clamp at s=" << Fixed(clamp_s, 3) << " m holds the cable "
         << Fixed(Parameter(d, "angle") * 180 / M_PI, 1)
         << " deg off its nominal direction, about axis (" << Fixed(axis[0], 2) << ", "
         << Fixed(axis[1], 2) << ", " << Fixed(axis[2], 2) << ")" << improve;
      break;
    }
    case ShapeEffect::kWeightStiffnessRatio: {
      const double ratio = Parameter(d, "ratio");
      ex << "The cable is " << (ratio > 1 ? "heavier or softer" : "lighter or stiffer")
         << " than specified: its weight-to-bending-stiffness ratio is " << Fixed(ratio, 2)
         << " times the nominal one" << improve;
      break;
    }
    case ShapeEffect::kAnisotropicBending:
      ex << "The cable bends more easily one way than the other: principal bending stiffnesses "
            "differ by a factor "
         << Fixed(Parameter(d, "ratio"), 2) << ", the stiff axis at "
         << Fixed(Parameter(d, "principal_angle") * 180 / M_PI, 0) << " deg from the normal d1"
         << improve;
      break;
    case ShapeEffect::kSupportContact: {
      const auto it = d.vectors.find("force_vector");
      const Vec3 force = it == d.vectors.end() ? Vec3::Zero() : it->second;
      const double size = std::max(force.norm(), 1e-30);
      ex << "Something the model does not have pushes the cable at s="
         << Fixed(Parameter(d, "s"), 3) << " m with " << Fixed(force.norm() * 1e3, 1)
         << " mN (direction " << Fixed(force[0] / size, 2) << ", " << Fixed(force[1] / size, 2)
         << ", " << Fixed(force[2] / size, 2) << ")" << improve;
      break;
    }
    case ShapeEffect::kTwistPreload: {
      const double angle = Parameter(d, "angle");
      ex << "The clamp at s=" << Fixed(clamp_s, 3) << " m is rotated "
         << Fixed(angle * 180 / M_PI, 1)
         << " deg about the cable axis from the normal in the case: the cable carries a torque of "
         << Fixed(Parameter(d, "torque") * 1e3, 2) << " mN m" << improve;
      const auto other = d.parameters.find("alternative_clamp");
      if (other != d.parameters.end())
        ex << " The shape cannot tell which clamp was turned: the clamp at s="
           << Fixed(ClampS(nominal, other->second), 3) << " m turned "
           << Fixed(Parameter(d, "alternative_angle") * 180 / M_PI, 1)
           << " deg gives the same shape (it depends only on the twist between the clamps).";
      break;
    }
    case ShapeEffect::kClampCompliance:
      ex << "The clamp at s=" << Fixed(clamp_s, 3)
         << " m is not rigid: it lets the cable rotate against a rotational stiffness of about "
         << Fixed(Parameter(d, "stiffness"), 3) << " N m/rad" << improve;
      break;
  }
  return ex.str();
}

std::string Percent(double share) {
  return std::isfinite(share) ? Fixed(100.0 * share, 0) + " %" : "an unknown part";
}

// What the diagnosis found: nothing, one effect, or each of several with its share.
std::string Effect(const ShapeDiagnosis& d, const RodSpec& nominal) {
  const std::string reduces =
      "reduces the max deviation from " + Mm(d.baseline_max) + " to " + Mm(d.fitted_max) + ".";
  if (d.effects.empty()) {
    return "The nominal model explains the recording within its noise (max deviation " +
           Mm(d.baseline_max) + ", rms " + Mm(d.baseline_rms) +
           "); no effect improves it enough to justify its parameters.";
  }
  if (d.effects.size() == 1) return Sentence(d.effects.front(), nominal, "; fitting it " + reduces);
  std::ostringstream ex;
  ex << d.effects.size() << " pieces of physics were left out; fitting them together " << reduces;
  for (size_t i = 0; i < d.effects.size(); ++i)
    ex << " (" << i + 1 << ") "
       << Sentence(d.effects[i], nominal,
                   ": " + Percent(d.effects[i].share) + " of the mismatch (sum of squares).");
  return ex.str();
}

}  // namespace

std::string ExplainShapeDiagnosis(const ShapeDiagnosis& d, const RodSpec& nominal) {
  const std::string effect = Effect(d, nominal);
  std::ostringstream ex;
  if (!d.explained) {
    // A best fit that leaves far more than the noise is not a diagnosis: say what it leaves and
    // what to check instead of a confident story.
    const ShapeAdequacy& a = d.adequacy;
    ex << "No effect of the catalogue, alone or in pairs, explains the recording: the best fit ("
       << ToString(d.effect)
       << ") leaves a max deviation of " << Mm(d.fitted_max) << " (rms " << Mm(d.fitted_rms)
       << ") against a noise of " << Mm(a.noise_sigma) << " (chi-square with "
       << Fixed(a.noise_allowance, 1) << " times that noise: " << Fixed(a.chi_square, 0)
       << " for " << a.degrees_of_freedom << " degrees of freedom, 99.9 % limit "
       << Fixed(a.limit, 0)
       << "). Check the set-up: the clamps (positions, directions, whether every clamp is "
          "listed), the units of the recording and that it belongs to this case. Best candidate: "
       << effect;
    return ex.str();
  }
  ex << effect;
  // A close runner-up is part of the answer: the scores alone do not separate them.
  for (const EffectCandidate& c : d.candidates) {
    if (d.effects.size() > 1) break;
    if (c.effect == d.effect || c.score < 0.25) continue;
    ex << " The recording hardly separates it from " << ToString(c.effect) << " (scores "
       << Fixed(d.confidence, 2) << " and " << Fixed(c.score, 2) << ").";
    break;
  }
  return ex.str();
}

std::string DescribeNote(const DiagnosisNote& note) {
  switch (note.kind) {
    case DiagnosisNote::Kind::kRecordingReversed:
      return "the recording runs from the last clamp to the first (its ends are " +
             Mm(note.gap_as_listed) + " from their clamps as listed, " + Mm(note.gap_reversed) +
             " reversed); it was reversed";
    case DiagnosisNote::Kind::kFitDidNotHold:
      return std::string("the ") + ToString(note.effect) +
             " fit did not hold in the accurate solve (" +
             (note.solved ? "it gave back most of its improvement" : "not solved") +
             "); the next candidate was taken";
    case DiagnosisNote::Kind::kFitFromOtherEquilibrium: {
      const char* from = note.start == NominalStart::kSolverStart ? "the solver's own start"
                         : note.start == NominalStart::kMirroredSag
                             ? "the recorded sag mirrored through the chord"
                             : "the recorded shape";
      return std::string("the ") + ToString(note.effect) +
             " fit started from another equilibrium of the nominal set-up (solved from " + from +
             ") than the one the recorded shape leads to";
    }
  }
  return "";
}

}  // namespace cablefit::addin
