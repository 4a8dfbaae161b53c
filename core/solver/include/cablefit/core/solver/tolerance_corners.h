// Which corners of a tolerance box to solve. A cable's shape depends on k toleranced quantities,
// each varied by eps_q in [-1, 1] times its tolerance; the envelope is the farthest the shape
// gets from nominal. With few quantities every corner (2^k) is solved. With more, the shape is
// linearised: point j moves by J_j eps (J_j: 3 x k sensitivities), whose length is convex in
// eps, so its largest value over the box is at a corner; that corner is found for every point
// and only the distinct ones are solved.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace cablefit {

/// Every corner of [-1, 1]^k, as sign vectors of +-1 (2^k of them, k <= 20).
std::vector<Eigen::VectorXd> AllCorners(int k);

/// The corners that maximise each point's linearised displacement.
/// `sensitivity[q]`: 3 x points [m], the displacement of every point for eps = e_q (the same
/// points for every q). For each point the corner is the best fixed point of d = J eps /
/// |J eps|, eps = sign(J^T d) over several starts (J's singular directions, each quantity's
/// direction and, up to 12 quantities, the normal of every pair of them): the best corner when
/// J has rank one or k <= 2, measured within 0.1 % of it otherwise (tests). Each corner comes
/// with its opposite (same
/// linearised size, the nonlinear shape may differ). Distinct corners, largest predicted
/// displacement first, at most `max_corners` (even: opposites kept in pairs).
/// `predicted` (optional) receives each corner's largest linearised displacement [m].
std::vector<Eigen::VectorXd> WorstCorners(const std::vector<Eigen::Matrix3Xd>& sensitivity,
                                          int max_corners,
                                          std::vector<double>* predicted = nullptr);

}  // namespace cablefit
