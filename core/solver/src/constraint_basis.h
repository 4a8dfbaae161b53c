// The two bases of the supports' position rows (rod_model.h, RodSupport::row_reference): the
// physical rows c_phys, each measured from the support's `reference` (their multipliers are the
// reactions, their compliance the stretch between the two), and the rows the Newton system is
// eliminated in, c_rows = T c_phys, each measured from its row_reference:
//   c_rows_k = c_phys_k - P_k sum_{m in row_chain(k)} c_phys_m,
// T unit lower triangular in RodModel::row_support_order. The system in the rows' basis is the
// physical one transformed by T (J_rows = T J_phys, lambda_phys = T^T lambda_rows, C_rows =
// T C_phys T^T): the same steps and inertia (a congruence), with rows that overlap little. On a
// single cable the two bases are the same (identity()).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/rod/rod_state.h"

namespace cablefit {

class ConstraintBasis {
 public:
  /// The basis of `model`'s rows at `state` (a sliding support's projector follows its frame).
  ConstraintBasis(const RodModel& model, const RodState& state);

  bool identity() const { return identity_; }
  /// Constraint values (or J x) in the rows' basis -> physical: T^-1 y.
  Eigen::VectorXd ToPhysical(const Eigen::VectorXd& rows) const;
  /// Multipliers in the rows' basis -> physical: T^T lambda.
  Eigen::VectorXd MultipliersToPhysical(const Eigen::VectorXd& rows) const;
  /// Physical multipliers -> the rows' basis: T^-T lambda.
  Eigen::VectorXd MultipliersToRows(const Eigen::VectorXd& physical) const;

  /// One block of the rows' compliance C_rows = T C_phys T^T [m/N]: rows of support `a` x rows
  /// of support `b` (top-left part of `value`).
  struct Block {
    int a = 0, b = 0;
    Eigen::Matrix3d value = Eigen::Matrix3d::Zero();
  };
  /// Per support (index into model.supports), its diagonal block (zero without rows).
  const std::vector<Eigen::Matrix3d>& compliance_diagonal() const { return diagonal_; }
  /// The blocks between two supports, a < b, sorted by (a, b); empty on a single cable.
  const std::vector<Block>& compliance_coupling() const { return coupling_; }
  /// C_rows as a dense num_constraints x num_constraints matrix.
  Eigen::MatrixXd DenseCompliance() const;

 private:
  const RodModel* model_;
  bool identity_ = true;
  std::vector<Eigen::Matrix3d> projector_;  // per support: P_k in its top rows (rows x 3)
  std::vector<Eigen::Matrix3d> diagonal_;
  std::vector<Block> coupling_;
};

}  // namespace cablefit
