// Closed-form responses of the two force rigs of recording-v1 ("force_curve").
//
// pinned_bending: an inextensible planar Euler elastica of length L and bending stiffness B,
// pinned at the origin, the other end on a roller sliding along x; first (post-)buckling mode.
// With modulus k (k = sin(alpha/2), alpha = end rotation), Love, "A Treatise on the Mathematical
// Theory of Elasticity" (4th ed., 1927) §263, and Timoshenko & Gere, "Theory of Elastic
// Stability" (2nd ed., 1961) §2.7:
//   L = 2 K(k) sqrt(B / P)           ->  P = 4 K(k)^2 B / L^2
//   x_end = 2 (2 E(k) - K(k)) sqrt(B / P)  ->  d = L - x_end = 2 L (1 - E(k) / K(k))
// d(k) increases monotonically from 0 (k = 0, P = pi^2 B / L^2, Euler's load) and reaches
// d = L (the roller arrives at the pin) at k ~ 0.9089.
//
// clamped_torsion: a straight cable clamped at both ends, far end rotated by `angle` about x:
// uniform twist angle / L, reaction moment M = GJ angle / L.
#pragma once

#include <Eigen/Core>

#include "cablefit/core/rod/recording_case.h"
#include "cablefit/core/rod/rod_spec.h"

namespace cablefit {

/// End shortening per length, d / L = 2 (1 - E(k)/K(k)), of the first-mode pinned elastica.
double ElasticaShorteningRatio(double k);

/// Elliptic modulus k in [0, 1) of the first-mode pinned elastica whose end shortening is
/// `shortening` [m] for `length` [m]. Bisection on the monotonic d(k) to double precision.
/// Throws InvalidInput unless 0 <= shortening < length (the roller cannot pass the pin).
double ElasticaModulus(double length, double shortening);

/// Axial reaction P [N] of the pinned elastica (bending stiffness [N m^2], length [m]) at end
/// shortening [m]. Continuous at 0 where it equals Euler's load pi^2 B / L^2.
double PinnedElasticaForce(double bending_stiffness, double length, double shortening);

/// Reaction moment [N m] of the clamped torsion rig for far-end rotation `angle` [rad].
double ClampedTorsionMoment(double torsional_stiffness, double length, double angle);

/// The stiffness that scales the rig's response: the smaller principal bending stiffness
/// (planar buckling picks the weak axis) for pinned_bending, GJ for clamped_torsion [N m^2].
double RigStiffness(const RodSpec& nominal, const ForceTestSpec& test);

/// The nominal model's response per recorded row: force [N] for pinned_bending at the
/// displacements `x` [m], moment [N m] for clamped_torsion at the angles `x` [rad].
/// Both responses are proportional to RigStiffness(). Throws InvalidInput for non-finite x,
/// non-positive length or stiffness, or a displacement outside [0, length).
Eigen::VectorXd NominalForceCurve(const RodSpec& nominal, const ForceTestSpec& test,
                                  const Eigen::VectorXd& x);  // n [m] or [rad] -> n [N] or [N m]

}  // namespace cablefit
