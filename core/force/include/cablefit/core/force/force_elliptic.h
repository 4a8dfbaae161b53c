// Complete elliptic integrals of the first and second kind, K(k) and E(k), by the
// arithmetic-geometric mean. Source: Abramowitz & Stegun, Handbook of Mathematical Functions,
// 17.6 (AGM for K) and 17.6.3-17.6.4 (E from the same sequence, E = K (1 - sum 2^(n-1) c_n^2)).
#pragma once

namespace cablefit {

struct CompleteElliptic {
  double K = 0.0;  ///< first kind, K(k) = int_0^{pi/2} (1 - k^2 sin^2 t)^(-1/2) dt
  double E = 0.0;  ///< second kind, E(k) = int_0^{pi/2} (1 - k^2 sin^2 t)^(1/2) dt
};

/// K(k) and E(k) for the modulus 0 <= k < 1 (not the parameter m = k^2), to ~1e-15 relative.
/// Throws InvalidInput outside [0, 1).
CompleteElliptic CompleteEllipticIntegrals(double k);

}  // namespace cablefit
