// Pinned elastica (Love §263; Timoshenko & Gere §2.7) and uniform torsion, see force_rig.h.
#include "cablefit/core/force/force_rig.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "cablefit/core/base/errors.h"
#include "cablefit/core/force/force_elliptic.h"

namespace cablefit {

double ElasticaShorteningRatio(double k) {
  const CompleteElliptic ke = CompleteEllipticIntegrals(k);
  return 2.0 * (1.0 - ke.E / ke.K);
}

double ElasticaModulus(double length, double shortening) {
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw InvalidInput("pinned_bending: cable length must be positive");
  }
  if (!std::isfinite(shortening) || shortening < 0.0 || shortening >= length) {
    std::ostringstream msg;
    msg << "pinned_bending: displacement " << shortening << " m is outside the geometric range [0, "
        << length << ") m (the roller would pass the pinned end)";
    throw InvalidInput(msg.str());
  }
  if (shortening == 0.0) return 0.0;
  const double target = shortening / length;
  // d/L(k) is monotonic; d/L = 1 is reached at k ~ 0.909, so [0, 0.99] brackets every valid d.
  double lo = 0.0;
  double hi = 0.99;
  while (true) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;  // interval exhausted at double precision
    if (ElasticaShorteningRatio(mid) < target) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

double PinnedElasticaForce(double bending_stiffness, double length, double shortening) {
  const double k = ElasticaModulus(length, shortening);
  const double big_k = CompleteEllipticIntegrals(k).K;
  return 4.0 * big_k * big_k * bending_stiffness / (length * length);
}

double ClampedTorsionMoment(double torsional_stiffness, double length, double angle) {
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw InvalidInput("clamped_torsion: cable length must be positive");
  }
  return torsional_stiffness * angle / length;
}

double RigStiffness(const RodSpec& nominal, const ForceTestSpec& test) {
  if (test.type == ForceTestType::kClampedTorsion) {
    return nominal.material.torsional_stiffness;
  }
  // bending_stiffness is the geometric mean of B_max and B_min = B_max / bending_ratio.
  const double ratio = nominal.material.bending_ratio >= 1.0 ? nominal.material.bending_ratio : 1.0;
  return nominal.material.bending_stiffness / std::sqrt(ratio);
}

Eigen::VectorXd NominalForceCurve(const RodSpec& nominal, const ForceTestSpec& test,
                                  const Eigen::VectorXd& x) {
  const double stiffness = RigStiffness(nominal, test);
  const char* rig = ToString(test.type);
  if (!(stiffness > 0.0) || !std::isfinite(stiffness)) {
    throw InvalidInput(std::string(rig) + ": the rig stiffness (" +
                       (test.type == ForceTestType::kClampedTorsion ? "torsional_stiffness"
                                                                    : "bending_stiffness") +
                       ") must be positive");
  }
  if (!(nominal.length > 0.0) || !std::isfinite(nominal.length)) {
    throw InvalidInput(std::string(rig) + ": cable length must be positive");
  }
  Eigen::VectorXd y(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) {
      throw InvalidInput(std::string(rig) + ": row " + std::to_string(i + 1) +
                         " has a non-finite displacement/angle");
    }
    y[i] = test.type == ForceTestType::kClampedTorsion
               ? ClampedTorsionMoment(stiffness, nominal.length, x[i])
               : PinnedElasticaForce(stiffness, nominal.length, x[i]);
  }
  return y;
}

}  // namespace cablefit
