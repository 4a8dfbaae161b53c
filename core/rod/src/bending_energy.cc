// Bending and twist energy of the quaternion rod (Lang, Linn & Arnold 2011, eq. for the discrete
// Darboux vector u = (2/ds) Im(conj(q_a) q_b)). The energy is a polynomial in the quaternion
// components, so its Euclidean derivatives are exact; they are pulled back to the rotation
// chart q(theta) = q * (1 - |theta|^2/8, theta/2) + O(theta^3), whose second derivative
// d2q/dtheta_i dtheta_j = -delta_ij q / 4 gives the extra diagonal term -(g_q . q)/4 I.
#include <array>

#include "cablefit/core/base/internal/quaternion.h"
#include "cablefit/core/rod/internal/rod_energy.h"

namespace cablefit::internal {
namespace {

using Mat34 = Eigen::Matrix<double, 3, 4>;
using Mat44 = Eigen::Matrix4d;

// P_k(a, b) = a^T Q_k b for the bilinear strain P = Im(conj(a) b).
const std::array<Mat44, 3>& BilinearStrain() {
  static const std::array<Mat44, 3> q = [] {
    std::array<Mat44, 3> out;
    for (int i = 0; i < 4; ++i) {
      const Mat34 l = quat::LeftStrain(Eigen::Vector4d::Unit(i));
      for (int k = 0; k < 3; ++k) out[k].row(i) = l.row(k);
    }
    return out;
  }();
  return q;
}

// The frame of item a that the strain to b is measured from (a junction's rest rotation applied).
Eigen::Vector4d StrainBase(const RodEdge& e, const RodState& state) {
  return e.has_rest ? quat::Multiply(state.q[e.a], e.rest) : state.q[e.a];
}

}  // namespace

void AddBendingEnergy(const RodModel& model, const RodState& state, EnergyAccumulator* acc) {
  for (size_t k = 0; k < model.edges.size(); ++k)
    AddEdgeBendingEnergy(model.edges[k], static_cast<int>(k), state, acc);
}

Vec3 RestCurvature(const RodEdge& e, int edge_index, const RodState& state) {
  Vec3 u0 = state.natural_factor * e.natural;
  if (state.drawn_factor != 0.0 && edge_index >= 0 &&
      edge_index < static_cast<int>(state.drawn_curvature.size()))
    u0 += state.drawn_factor * state.drawn_curvature[edge_index];
  return u0;
}

std::vector<Eigen::Vector3d> DrawnCurvature(const RodModel& model, const RodState& state) {
  std::vector<Eigen::Vector3d> u(model.edges.size());
  for (size_t k = 0; k < model.edges.size(); ++k) {
    const RodEdge& e = model.edges[k];
    u[k] = (2.0 / e.ds) * (quat::LeftStrain(StrainBase(e, state)) * state.q[e.b]);
  }
  return u;
}

void AddEdgeBendingEnergy(const RodEdge& e, int edge_index, const RodState& state,
                          EnergyAccumulator* acc) {
  const auto& qk = BilinearStrain();
  {
    const int ia = e.a, ib = e.b;
    // With a rest rotation, a's frame enters as q_a * rest: its chart is rotated by R_rest^T,
    // so a's gradient and Hessian rows are mapped back with R_rest.
    const Eigen::Vector4d qa = StrainBase(e, state);
    const Eigen::Matrix3d back = e.has_rest ? quat::ToMatrix(e.rest) : Eigen::Matrix3d::Identity();
    const Eigen::Vector4d& qb = state.q[ib];
    const Mat34 l = quat::LeftStrain(qa);   // P = l qb
    const Mat34 m = quat::RightStrain(qb);  // P = m qa
    const double c = 2.0 / e.ds;
    const Eigen::Vector3d u = c * (l * qb);
    const Eigen::Vector3d du = u - RestCurvature(e, edge_index, state);
    const Eigen::Vector3d mom = e.stiffness * du;  // internal moment, material frame [N m]
    acc->value += 0.5 * e.ds * du.dot(mom);
    // The chart Jacobians are taken through the strain maps first (P = m qa = l qb): 3 x 3
    // products instead of 4 x 4 ones, in the innermost loop of every solve.
    const Eigen::Matrix<double, 4, 3> ja = quat::ChartJacobian(qa);
    const Eigen::Matrix<double, 4, 3> jb = quat::ChartJacobian(qb);
    const Eigen::Matrix3d a = m * ja;  // dP/dtheta_a
    const Eigen::Matrix3d b = l * jb;  // dP/dtheta_b
    acc->gradient.segment<3>(3 * ia) += back * (2.0 * (a.transpose() * mom));  // ds * c = 2
    acc->gradient.segment<3>(3 * ib) += 2.0 * (b.transpose() * mom);
    if (!acc->hessian) return;
    const double w = 4.0 / e.ds;  // ds * c^2
    const Eigen::Matrix3d km = e.stiffness;
    // g_a . q_a = g_b . q_b = 2 mom . P: the chart's curvature term.
    const double curl = 0.25 * 2.0 * mom.dot(u / c);
    Mat44 strain_moment = Mat44::Zero();
    for (int k = 0; k < 3; ++k) strain_moment += 2.0 * mom[k] * qk[k];
    const Eigen::Matrix3d ka = km * a, kb = km * b;
    const Eigen::Matrix3d daa = w * a.transpose() * ka - curl * Eigen::Matrix3d::Identity();
    acc->hessian->Diag(ia) += back * daa * back.transpose();
    acc->hessian->Diag(ib) += w * b.transpose() * kb - curl * Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d dab = w * a.transpose() * kb + ja.transpose() * strain_moment * jb;
    acc->hessian->AddOffDiagonal(ia, ib, back * dab);
  }
}

}  // namespace cablefit::internal
