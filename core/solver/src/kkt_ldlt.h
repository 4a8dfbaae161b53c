// Exact block LDL^T of the Newton system of a rod or rod network,
//   [H + shift I   J^T] [step  ]     [g]
//   [J             -C ] [lambda] = - [c],
// in the rows' basis (constraint_basis.h): C the supports' axial compliances
// (RodSupport::compliance, 0 for an inextensible cable) carried into that
// basis, block diagonal with a few blocks between supports whose rows share a
// stretch,
// in O(n) however many supports hold the cable. H is a block tree (one 3x3
// block per frame sample, rod_model.h); the rows of support k act only on the
// frames of its stretch, the cable between it and its reference support
// (RodSupport::reference). The unknowns are eliminated block by block: frames
// leaves first as for H alone, and each support's multiplier block right after
// the last frame of its stretch, when its pivot has become the stretch's
// compliance -J_k H^-1 J_k^T. The fill then stays within a small front (the
// next frame and the stretches open across it), found once by an elimination
// tree (George & Liu, "Computer Solution of Large Sparse Positive Definite
// Systems", 1981); the ordering is the one of linear-time multibody solvers
// with Lagrange multipliers (Baraff, "Linear-time dynamics using Lagrange
// multipliers", SIGGRAPH 1996). By Sylvester's law of inertia the pivots'
// eigenvalues have the signs of the KKT matrix's: the Hessian reduced to the
// constraint manifold is positive definite exactly when m of them are negative
// (m = rows), which gives the solver its inertia correction and stability
// verdict without the O(n m) Schur complement J H^-1 J^T.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "cablefit/core/rod/internal/block_tree.h"
#include "cablefit/core/rod/rod_model.h"
#include "cablefit/core/rod/internal/rod_energy.h"
#include "constraint_basis.h"

namespace cablefit {

class KktLdlt {
 public:
  enum class Status {
    kOk,
    /// A pivot of the frames is (numerically) singular: H + shift I is too
    /// indefinite here.
    kSingularPivot,
    /// A support's rows are (numerically) dependent within its stretch, e.g.
    /// the distance along a taut straight stretch, which no rotation changes to
    /// first order (the caller regularises).
    kRankDeficient,
  };

  /// Factorises the system at `h` (masked: held rotations are identity rows)
  /// and `jacobian` (rows of model.supports in the rows' basis, masked columns
  /// pruned), with the compliance `basis` gives; `shift` [N m] is added to the
  /// free rotations' diagonal. The structure is analysed again only when the
  /// Jacobian's or the compliance's pattern changes, so one object serves every
  /// Newton iteration of a model.
  Status Factorize(const RodModel& model, const internal::BlockTree& h,
                   const internal::SparseJacobian& jacobian, const ConstraintBasis& basis,
                   const std::vector<char>& free, double shift);

  /// Negative pivot eigenvalues of the last factorisation: rows + the unstable
  /// directions on the constraint manifold.
  int NegativeCount() const { return negative_; }

  /// Solves the last factorised system for the right-hand side (g, c): step (3
  /// items) [rad], lambda (rows) [N].
  void Solve(const Eigen::VectorXd& g, const Eigen::VectorXd& c, Eigen::VectorXd* step,
             Eigen::VectorXd* lambda) const;

 private:
  void Analyze(const RodModel& model, const internal::BlockTree& h,
               const internal::SparseJacobian& jacobian, const ConstraintBasis& basis);
  bool SamePattern(const internal::SparseJacobian& jacobian, const ConstraintBasis& basis) const;

  // Blocks: items 0 .. ni-1 (3 unknowns each), then one per support with rows
  // (1-3 unknowns, padded to 3 with unit pivots that nothing couples to, so
  // every block is a Matrix3d).
  int num_items_ = 0;
  int num_rows_ = 0;
  std::vector<int> order_;         // blocks in elimination order
  std::vector<int> row_first_;     // per row block: its first constraint row
  std::vector<int> row_count_;     // per row block: its rows
  std::vector<int> block_of_row_;  // constraint row -> row block (index from num_items_)
  // Column v of L below its pivot: entries column_start_[v] .. column_start_[v
  // + 1] - 1, each the block entry_block_[e] (later in the order, sorted by
  // position) and its 3x3 value entry_[e] (rows of that block, columns of v):
  // A_uv while factorising, then L_uv.
  std::vector<int> column_start_;
  std::vector<int> entry_block_;
  std::vector<Eigen::Matrix3d> entry_;
  // Schur updates of column v: for every pair i <= j of its entries, the entry
  // index of block (entry j, entry i), or -1 - block for the diagonal block of
  // entry i.
  std::vector<int> update_start_;
  std::vector<int> update_target_;
  std::vector<Eigen::Matrix3d> pivot_;  // per block: pivot, then its inverse
  std::vector<int> h_entry_;            // per item with a parent: the entry of (parent, item)
  std::vector<int> jac_entry_;          // per Jacobian non-zero: the entry of (row block, item)
  std::vector<int> jac_outer_;          // the pattern analysed for
  std::vector<int> jac_inner_;
  std::vector<int> block_of_support_;  // per support: its row block (index from num_items_), or -1
  std::vector<std::pair<int, int>> coupling_pattern_;  // the compliance blocks analysed for
  std::vector<int> coupling_entry_;    // per coupling block: its entry (later block, earlier one)
  std::vector<char> coupling_flip_;    // 1: the entry holds block (b, a), stored transposed
  int negative_ = 0;
};

}  // namespace cablefit
