#include "circle_fit.h"

#include <Eigen/Dense>
#include <cmath>

namespace cablefit {

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

  Eigen::MatrixX3d a(n, 3);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = centred.col(i).dot(e1);
    const double y = centred.col(i).dot(e2);
    a.row(i) << 2 * x, 2 * y, 1.0;
    b(i) = x * x + y * y;
  }
  const Eigen::Vector3d abc = a.colPivHouseholderQr().solve(b);
  const double r2 = abc(2) + abc(0) * abc(0) + abc(1) * abc(1);
  if (!(r2 > 0)) return fit;
  fit.centre = mean + abc(0) * e1 + abc(1) * e2;
  fit.normal = normal;
  fit.radius = std::sqrt(r2);
  double sum = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d d = points.col(i) - fit.centre;
    const double h = d.dot(normal);
    const double in_plane = (d - h * normal).norm() - fit.radius;
    sum += h * h + in_plane * in_plane;
  }
  fit.rms_residual = std::sqrt(sum / static_cast<double>(n));
  fit.ok = true;
  return fit;
}

}  // namespace cablefit
