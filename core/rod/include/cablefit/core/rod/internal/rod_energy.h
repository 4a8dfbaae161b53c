// The energy terms of the discrete rod, one per file, all behind one small interface: each adds
// its value, its gradient and its Hessian with respect to the body-frame rotation increments
// theta of every item (chart q(theta) = q * exp(theta)), evaluated at theta = 0.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "cablefit/core/rod/internal/block_tree.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/rod/rod_state.h"

namespace cablefit::internal {

struct EnergyAccumulator {
  double value = 0.0;          // [J]
  Eigen::VectorXd gradient;    // 3 * items [N m]
  BlockTree* hessian = nullptr;  // null: value and gradient only
  void Reset(const RodModel& model, BlockTree* h) {
    const int items = static_cast<int>(model.items.size());
    value = 0.0;
    gradient.setZero(3 * items);
    hessian = h;
    if (h) {
      if (h->size() != items || h->Order() != model.item_order)
        h->ResizeTree(model.item_parent, model.item_order);
      h->SetZero();
    }
  }
};

/// Bending and twist: sum over edges of ds/2 (u - u0)^T K (u - u0).
void AddBendingEnergy(const RodModel& model, const RodState& state, EnergyAccumulator* acc);
/// One edge's share of it (e.g. the moment one branch exerts on a junction); `edge_index` is
/// its index in model.edges (it selects the edge's drawn rest curvature).
void AddEdgeBendingEnergy(const RodEdge& edge, int edge_index, const RodState& state,
                          EnergyAccumulator* acc);
/// The rest Darboux vector u0 of an edge in `state` (natural and drawn parts with their factors).
Vec3 RestCurvature(const RodEdge& edge, int edge_index, const RodState& state);
/// The Darboux vector of every edge in `state`: as rest curvature, it makes that shape stress-free.
std::vector<Eigen::Vector3d> DrawnCurvature(const RodModel& model, const RodState& state);

/// Gravity and dead point loads (linear in the element tangents).
void AddLoadEnergy(const RodModel& model, const RodState& state, EnergyAccumulator* acc);

/// Rotational springs of compliant clamps.
void AddSupportSpringEnergy(const RodModel& model, const RodState& state, EnergyAccumulator* acc);

/// Adds a . d3(q_item) with its exact gradient and Hessian (shared by loads and constraints).
void AddLinearTangentTerm(const Eigen::Vector4d& q, const Vec3& a, int item, EnergyAccumulator* acc);

/// num_constraints x 3 items [m], row-major: each row is non-zero along one tree path.
using SparseJacobian = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// Position constraints c (num_constraints) and their Jacobian, in the rows' basis (each
/// support's rows measured from its row_reference; internal/constraint_basis.h turns them into
/// the physical rows, measured from `reference`).
void EvaluatePositionConstraints(const RodModel& model, const RodState& state, Eigen::VectorXd* c,
                                 SparseJacobian* jacobian);

/// Force every support exerts on the cable through its constraint rows (world, [N]), from the
/// physical multipliers (state.lambda, rows measured from `reference`); the anchor's entry is
/// only what other rows pass to it (its own follows from global balance).
std::vector<Vec3> SupportReactions(const RodModel& model, const RodState& state);

/// Adds the curvature of lambda . c to the Hessian (no value, no gradient); lambda and c in the
/// rows' basis.
void AddConstraintCurvature(const RodModel& model, const RodState& state,
                            const Eigen::VectorXd& lambda, BlockTree* hessian);

/// The constraint rows of support `k` as a (rows x 3) projector.
Eigen::Matrix<double, Eigen::Dynamic, 3> ConstraintProjector(const RodSupport& support,
                                                             const RodState& state, int k);

}  // namespace cablefit::internal
