// Unit-quaternion helpers for the rod discretisation. Quaternions are Eigen::Vector4d stored
// (w, x, y, z); a material frame is R(q) = [d1 d2 d3]. Kept private to core.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace cablefit::internal::quat {

using Q = Eigen::Vector4d;

inline Q Multiply(const Q& a, const Q& b) {
  const Eigen::Vector3d av = a.tail<3>(), bv = b.tail<3>();
  Q r;
  r[0] = a[0] * b[0] - av.dot(bv);
  r.tail<3>() = a[0] * bv + b[0] * av + av.cross(bv);
  return r;
}

inline Q Conjugate(const Q& a) { return Q(a[0], -a[1], -a[2], -a[3]); }

inline Eigen::Matrix3d ToMatrix(const Q& q) {
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
}

inline Q FromMatrix(const Eigen::Matrix3d& r) {
  Eigen::Quaterniond e(r);
  e.normalize();
  return Q(e.w(), e.x(), e.y(), e.z());
}

/// d3 = R(q) e3, exact for unit q.
inline Eigen::Vector3d D3(const Q& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return Eigen::Vector3d(2 * (x * z + w * y), 2 * (y * z - w * x), w * w - x * x - y * y + z * z);
}

/// exp of a rotation vector theta (body frame), as a unit quaternion.
inline Q Exp(const Eigen::Vector3d& theta) {
  const double a = theta.norm();
  if (a < 1e-8) {
    Q r(1.0 - a * a / 8.0, theta[0] / 2, theta[1] / 2, theta[2] / 2);
    return r.normalized();
  }
  const double s = std::sin(a / 2) / a;
  return Q(std::cos(a / 2), s * theta[0], s * theta[1], s * theta[2]);
}

/// Rotation vector of a unit quaternion (shortest, |angle| <= pi).
inline Eigen::Vector3d Log(Q q) {
  if (q[0] < 0) q = -q;
  const Eigen::Vector3d v = q.tail<3>();
  const double sn = v.norm();
  if (sn < 1e-12) return 2.0 * v;
  return (2.0 * std::atan2(sn, q[0]) / sn) * v;
}

/// Im(conj(a) b) = L(a) b: L is 3x4, linear in a.
inline Eigen::Matrix<double, 3, 4> LeftStrain(const Q& a) {
  Eigen::Matrix<double, 3, 4> l;
  l.col(0) = -a.tail<3>();
  l.block<3, 3>(0, 1) = a[0] * Eigen::Matrix3d::Identity();
  l(0, 2) += a[3];   // -[a_v]x
  l(0, 3) -= a[2];
  l(1, 1) -= a[3];
  l(1, 3) += a[1];
  l(2, 1) += a[2];
  l(2, 2) -= a[1];
  return l;
}

/// Im(conj(a) b) = M(b) a: M is 3x4, linear in b.
inline Eigen::Matrix<double, 3, 4> RightStrain(const Q& b) {
  Eigen::Matrix<double, 3, 4> m;
  m.col(0) = b.tail<3>();
  m.block<3, 3>(0, 1) = -b[0] * Eigen::Matrix3d::Identity();
  m(0, 2) -= b[3];   // +[b_v]x
  m(0, 3) += b[2];
  m(1, 1) += b[3];
  m(1, 3) -= b[1];
  m(2, 1) -= b[2];
  m(2, 2) += b[1];
  return m;
}

/// d q(theta) / d theta at theta = 0 for the chart q(theta) = q * exp(theta): 4x3.
inline Eigen::Matrix<double, 4, 3> ChartJacobian(const Q& q) {
  Eigen::Matrix<double, 4, 3> j;
  j.row(0) = -0.5 * q.tail<3>().transpose();
  Eigen::Matrix3d b = q[0] * Eigen::Matrix3d::Identity();
  b(0, 1) -= q[3];  // +[q_v]x
  b(0, 2) += q[2];
  b(1, 0) += q[3];
  b(1, 2) -= q[1];
  b(2, 0) -= q[2];
  b(2, 1) += q[1];
  j.bottomRows<3>() = 0.5 * b;
  return j;
}

inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0;
  return s;
}

}  // namespace cablefit::internal::quat
