// Circle fits for cable cross-sections; references in circle_fit.h.
#include "cablefit/formats/internal/circle_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

namespace cablefit::internal {
namespace {

constexpr double kTukeyC = 4.685;  // 95 % efficiency under Gaussian noise
constexpr int kMaxIterations = 30;

}  // namespace

double RobustScale(Eigen::VectorXd values) {
  if (values.size() == 0) return 0.0;
  values = values.cwiseAbs();
  auto mid = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), mid, values.end());
  return 1.4826 * *mid;
}

double ArcSpan(const Eigen::Matrix2Xd& points, const Eigen::Vector2d& centre) {
  if (points.cols() < 2) return 0.0;
  std::vector<double> angles(static_cast<std::size_t>(points.cols()));
  for (Eigen::Index i = 0; i < points.cols(); ++i) {
    const Eigen::Vector2d d = points.col(i) - centre;
    angles[static_cast<std::size_t>(i)] = std::atan2(d.y(), d.x());
  }
  std::sort(angles.begin(), angles.end());
  double largest_gap = angles.front() + 2.0 * M_PI - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i)
    largest_gap = std::max(largest_gap, angles[i] - angles[i - 1]);
  return 2.0 * M_PI - largest_gap;
}

CircleFitResult FitCircleKnownRadius(const Eigen::Matrix2Xd& points, const Eigen::Vector2d& initial,
                                     double radius, double scale_floor) {
  CircleFitResult fit;
  fit.centre = initial;
  fit.radius = radius;
  const Eigen::Index m = points.cols();
  if (m < 3) return fit;
  Eigen::VectorXd residual(m);
  Eigen::Matrix2Xd unit(2, m);
  double scale = 0.0;
  for (int it = 0; it < kMaxIterations; ++it) {
    for (Eigen::Index i = 0; i < m; ++i) {
      const Eigen::Vector2d d = points.col(i) - fit.centre;
      const double rho = std::max(d.norm(), 1e-12);
      unit.col(i) = d / rho;
      residual(i) = rho - radius;
    }
    // Re-estimate the scale only early: later, Tukey's zero weights would shrink it to nothing.
    if (it < 4) scale = std::max(RobustScale(residual), scale_floor);
    const double cutoff = kTukeyC * scale;
    Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
    Eigen::Vector2d rhs = Eigen::Vector2d::Zero();
    for (Eigen::Index i = 0; i < m; ++i) {
      const double w = TukeyWeight(residual(i) / cutoff);
      normal += w * unit.col(i) * unit.col(i).transpose();
      rhs += w * unit.col(i) * residual(i);
    }
    // A little damping keeps a nearly straight (very short) arc from sending the centre away.
    normal += 1e-9 * normal.trace() * Eigen::Matrix2d::Identity();
    if (normal.determinant() <= 0.0) return fit;
    const Eigen::Vector2d step = normal.ldlt().solve(rhs);
    if (!step.allFinite()) return fit;
    fit.centre += step;
    if (step.norm() < 1e-9 * std::max(radius, 1e-6)) break;
  }
  for (Eigen::Index i = 0; i < m; ++i) residual(i) = (points.col(i) - fit.centre).norm() - radius;
  fit.scale = std::max(RobustScale(residual), 0.0);
  fit.converged = fit.centre.allFinite() && (fit.centre - initial).norm() < 10.0 * radius;
  return fit;
}

CircleFitResult FitCircleAlgebraic(const Eigen::Matrix2Xd& points, const Eigen::VectorXd& weights) {
  CircleFitResult fit;
  const Eigen::Index m = points.cols();
  if (m < 3 || !(weights.sum() > 0.0)) return fit;
  // Centre the data first: the algebraic fit is badly conditioned in absolute coordinates.
  const Eigen::Vector2d mean = (points * weights) / weights.sum();
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::Vector2d q = points.col(i) - mean;
    const Eigen::Vector3d row(q.x(), q.y(), 1.0);
    a += weights(i) * row * row.transpose();
    b += weights(i) * row * (-q.squaredNorm());
  }
  const Eigen::Vector3d x = a.ldlt().solve(b);
  if (!x.allFinite()) return fit;
  const Eigen::Vector2d c(-0.5 * x(0), -0.5 * x(1));
  const double r2 = c.squaredNorm() - x(2);
  if (!(r2 > 0.0)) return fit;
  fit.centre = c + mean;
  fit.radius = std::sqrt(r2);
  fit.converged = true;
  return fit;
}

CircleFitResult FitCircleFree(const Eigen::Matrix2Xd& points, const Eigen::VectorXd& weights) {
  CircleFitResult fit;
  const Eigen::Index m = points.cols();
  if (m < 4 || weights.sum() <= 0.0) return fit;
  const CircleFitResult start = FitCircleAlgebraic(points, weights);
  if (!start.converged) return fit;
  const Eigen::Vector2d mean = (points * weights) / weights.sum();
  Eigen::Vector2d c = start.centre - mean;
  double r = start.radius;
  for (int it = 0; it < 10; ++it) {  // Gauss-Newton on (cx, cy, r)
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    for (Eigen::Index i = 0; i < m; ++i) {
      const Eigen::Vector2d d = points.col(i) - mean - c;
      const double rho = std::max(d.norm(), 1e-12);
      const Eigen::Vector3d j(-d.x() / rho, -d.y() / rho, -1.0);
      jtj += weights(i) * j * j.transpose();
      jtr += weights(i) * j * (rho - r);
    }
    const Eigen::Vector3d step = -jtj.ldlt().solve(jtr);
    if (!step.allFinite()) return fit;
    c += step.head<2>();
    r += step(2);
    if (step.norm() < 1e-12) break;
  }
  fit.centre = c + mean;
  fit.radius = r;
  fit.converged = std::isfinite(r) && r > 0.0;
  return fit;
}

CircleFit FitCircle(const Eigen::Matrix3Xd& points) {
  CircleFit fit;
  const Eigen::Index n = points.cols();
  if (n < 3) return fit;
  const Eigen::Vector3d mean = points.rowwise().mean();
  const Eigen::Matrix3Xd centred = points.colwise() - mean;  // 3 x n
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(centred * centred.transpose());
  // Eigenvalues ascending: the smallest is the plane normal, the largest two span the plane.
  const Eigen::Vector3d normal = pca.eigenvectors().col(0);
  const Eigen::Vector3d e1 = pca.eigenvectors().col(2);
  const Eigen::Vector3d e2 = normal.cross(e1);
  if (pca.eigenvalues()(1) <= 1e-12 * pca.eigenvalues()(2)) return fit;  // collinear
  Eigen::Matrix2Xd in_plane(2, n);
  for (Eigen::Index i = 0; i < n; ++i)
    in_plane.col(i) << centred.col(i).dot(e1), centred.col(i).dot(e2);
  const CircleFitResult circle = FitCircleAlgebraic(in_plane, Eigen::VectorXd::Ones(n));
  if (!circle.converged) return fit;
  fit.centre = mean + circle.centre.x() * e1 + circle.centre.y() * e2;
  fit.normal = normal;
  fit.radius = circle.radius;
  double sum = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d d = points.col(i) - fit.centre;
    const double h = d.dot(normal);
    const double off = (d - h * normal).norm() - fit.radius;
    sum += h * h + off * off;
  }
  fit.rms_residual = std::sqrt(sum / static_cast<double>(n));
  fit.ok = true;
  return fit;
}

}  // namespace cablefit::internal
