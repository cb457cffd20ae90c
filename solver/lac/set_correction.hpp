#pragma once
/// Solves with the penalized matrix of an active set B on the supernodal factorization of a nearby
/// set A, with no new factorization and no update of the factor. With D the rows where B differs
/// from A (s_r = +1 for a row B adds, -1 for one it drops) and rho_r their penalties,
///   K_B = K_A + sum_{r in D} s_r rho_r c_r c_r^T,
/// so K_B x = b  <=>  K_A x = b + C_D^T y,   y_r = -s_r rho_r c_r . x   (the difference moved to the
/// right-hand side). With yhat = L^-1 P b and Z = L^-1 P C_D^T (SparseCholesky::forward_columns,
/// over D's reach alone), c_D . x = Z^T yhat + T y for T = Z^T Z, hence
///   (I + S T) y = -S Z^T yhat,   S = diag(s_r rho_r),     x = P^T L^-T (yhat + Z y).
/// A solve is one forward solve, a dense |D| x |D| solve (I + S T is factorized once per set) and
/// one backward solve: the cost of a supernodal solve, against a simplicial one on an updated factor
/// (1.2-1.4 times as much) and the update itself (at 10^6 unknowns a rank-145 downdate cost more
/// than a factorization). The dropped rows' diagonal of I + S T is about 1/penalty_factor (their
/// penalty cancels most of their flexibility), which costs that many digits of y and leaves x
/// within the round-off the contact solver accepts.

#include <memory>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "solver/lac/sparse_cholesky.hpp"
#include "solver/lac/sparse_columns.hpp"

namespace saasgaps {

class SetCorrection {
 public:
  /// Holds the correction of `cholesky`'s last factorization by the rows `rows` (one column c_r
  /// each) with signed penalties s_r rho_r. The factorization must stay as it is while this is used.
  void set(SparseCholesky& cholesky, const SparseColumns& rows, std::span<const double> signed_penalties);
  /// The same for rows whose forward solves were done already: columns `subset` of `window`
  /// (SparseCholesky::forward_columns of a superset of the rows, on the factorization held now) and
  /// its Gram matrix `window_gram` (Z'Z, column-major), the look-ahead's condensation having computed
  /// both. Saves the forward solves over the rows' reach (0.23 s of a 1.0 s factorization for the
  /// 318 rows of the quad8 eccentric ring fit at 1.5 x 10^5 unknowns). The window's Z is shared, not
  /// copied: at 10^6 unknowns a copy of 826 of a 949-row window's columns was 168 MB of fresh pages.
  void set(SparseCholesky& cholesky, std::shared_ptr<const SparseCholesky::Reach> window,
           std::span<const double> window_gram, std::span<const std::size_t> subset,
           std::span<const double> signed_penalties);
  /// x = K_B^-1 b.
  void solve(std::span<const double> b, std::span<double> x);
  /// Rows in D.
  [[nodiscard]] std::size_t rank() const { return static_cast<std::size_t>(penalty_.size()); }
  /// The factor by which the correction's round-off exceeds a solve's: the largest ratio of a row's
  /// flexibility with and without its change (1 + rho_r f_r, or its inverse; f_r the row's
  /// flexibility without its penalty). About penalty_factor for contact rows between parts held
  /// otherwise; enormous for a row whose penalty is all that holds a part.
  [[nodiscard]] double loss() const { return loss_; }

 private:
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  /// From reach_ and T = Z'Z: penalty_, loss_ and lu_.
  void prepare(std::span<const double> signed_penalties, const Eigen::MatrixXd& t);

  SparseCholesky* cholesky_ = nullptr;
  std::shared_ptr<const SparseCholesky::Reach> reach_;
  /// D's columns among reach_'s (all of them, in order, when the correction solved its own).
  std::vector<Eigen::Index> subset_;
  Eigen::VectorXd penalty_;                // s_r rho_r
  double loss_ = 1.0;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;  // of I + S T
  std::vector<double> y_;                  // the forward solve, in the factor's order
};

}  // namespace saasgaps
