#include "cablefit/core/solver/tolerance_corners.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include <Eigen/Geometry>
#include <Eigen/SVD>

namespace cablefit {
namespace {

// Up to this many quantities every pair's arrangement vertex is a start (k^2 / 2 of them).
constexpr int kPairStartsUpTo = 12;

Eigen::VectorXd Signs(const Eigen::VectorXd& x) {
  Eigen::VectorXd s(x.size());
  // Ties go to +1 so the result does not depend on round-off in a zero.
  for (Eigen::Index i = 0; i < x.size(); ++i) s[i] = x[i] < 0 ? -1.0 : 1.0;
  return s;
}

// The corner as a key with its sign fixed (first entry +1), so a corner and its opposite meet.
std::vector<signed char> PairKey(const Eigen::VectorXd& eps) {
  const double flip = eps[0] < 0 ? -1.0 : 1.0;
  std::vector<signed char> key(static_cast<size_t>(eps.size()));
  for (Eigen::Index i = 0; i < eps.size(); ++i)
    key[static_cast<size_t>(i)] = static_cast<signed char>(flip * eps[i]);
  return key;
}

}  // namespace

std::vector<Eigen::VectorXd> AllCorners(int k) {
  if (k < 0 || k > 20) throw std::invalid_argument("AllCorners: k must be in [0, 20]");
  std::vector<Eigen::VectorXd> out;
  out.reserve(size_t{1} << k);
  for (unsigned long m = 0; m < (1ul << k); ++m) {
    Eigen::VectorXd eps(k);
    // Bit q set = +1: the first corner is all minus, the last all plus.
    for (int q = 0; q < k; ++q) eps[q] = (m >> q) & 1ul ? 1.0 : -1.0;
    out.push_back(eps);
  }
  return out;
}

std::vector<Eigen::VectorXd> WorstCorners(const std::vector<Eigen::Matrix3Xd>& sensitivity,
                                          int max_corners, std::vector<double>* predicted) {
  const int k = static_cast<int>(sensitivity.size());
  if (k == 0) return {};
  const Eigen::Index points = sensitivity[0].cols();
  for (const Eigen::Matrix3Xd& s : sensitivity)
    if (s.cols() != points) throw std::invalid_argument("WorstCorners: sensitivities differ in size");
  // Per distinct pair: the largest linearised displacement any point gets from it.
  std::map<std::vector<signed char>, double> best;
  Eigen::Matrix3Xd J(3, k);
  for (Eigen::Index j = 0; j < points; ++j) {
    for (int q = 0; q < k; ++q) J.col(q) = sensitivity[static_cast<size_t>(q)].col(j);
    if (J.norm() == 0) continue;
    const Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(J, Eigen::ComputeThinU);
    // Starts: the singular directions, each quantity's own direction and, for a handful of
    // quantities, the normals of every pair (the vertices of the sign arrangement: with them the
    // search is close to exhaustive over the zonotope's vertices).
    std::vector<Eigen::Vector3d> starts;
    for (int c = 0; c < svd.matrixU().cols(); ++c) starts.push_back(svd.matrixU().col(c));
    for (int q = 0; q < k; ++q) starts.push_back(J.col(q));
    if (k <= kPairStartsUpTo)
      for (int q = 0; q < k; ++q)
        for (int r = q + 1; r < k; ++r) starts.push_back(J.col(q).cross(J.col(r)));
    Eigen::VectorXd eps = Signs(J.transpose() * starts[0]);
    double size = (J * eps).norm();
    for (const Eigen::Vector3d& d : starts) {
      if (d.norm() == 0) continue;
      Eigen::VectorXd e = Signs(J.transpose() * d);
      // Each step does not decrease |J e| (a majorise-minimise step); k + 1 steps bound the
      // cycle of a tie.
      for (int it = 0; it <= k; ++it) {
        const Eigen::Vector3d v = J * e;
        if (v.norm() == 0) break;
        const Eigen::VectorXd next = Signs(J.transpose() * v);
        if (next == e) break;
        e = next;
      }
      const double n = (J * e).norm();
      if (n > size) {
        size = n;
        eps = e;
      }
    }
    double& b = best[PairKey(eps)];
    b = std::max(b, size);
  }
  std::vector<std::pair<double, std::vector<signed char>>> order;
  for (const auto& [key, size] : best) order.emplace_back(size, key);
  // Largest first; equal sizes by key, so the order never depends on the map's internals.
  std::stable_sort(order.begin(), order.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<Eigen::VectorXd> out;
  if (predicted) predicted->clear();
  for (const auto& [size, key] : order) {
    if (static_cast<int>(out.size()) + 2 > std::max(2, max_corners)) break;
    Eigen::VectorXd eps(k);
    for (int q = 0; q < k; ++q) eps[q] = key[static_cast<size_t>(q)];
    out.push_back(eps);
    out.push_back(-eps);
    if (predicted) predicted->insert(predicted->end(), {size, size});
  }
  return out;
}

}  // namespace cablefit
