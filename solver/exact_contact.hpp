#pragma once
/// Frictionless unilateral contact solved exactly (gaps.method = "exact"), for one assembled system
///   K u = f + C^T lambda,   g = g0 + C u >= 0,   lambda >= 0,   lambda_i g_i = 0   (every pair i),
/// with K the stiffness with every gap element at the floor modulus, C the rows c_i of the pairs'
/// gap functions over the free unknowns (contact_pairs.hpp) and lambda the contact forces.
///
/// Algorithm (docs/contact.md): a primal-dual active-set method (semismooth Newton on
/// min(lambda, g) = 0). For an active set A the equality-constrained problem g_A = 0 is solved to
/// round-off by augmented-Lagrangian multiplier (Uzawa) iterations on ONE factorization of
///   K_A = K + sum_{i in A} rho_i c_i c_i^T,     rho_i = penalty_factor * c_i^T diag(K) c_i,
///   K_A u = f + C_A^T (lambda - rho (g0)),      lambda_i <- lambda_i - rho_i g_i(u),
/// each iteration one pair of triangular solves; the penalty only speeds the multipliers up, the
/// converged answer has g_A = 0 to round-off whatever rho is. Then
///   A <- { i : lambda_i > tol_lambda_i }  U  { i not in A : g_i < -tol_g }
/// until A repeats; an active set seen before (a cycle) changes only its worst pair. The first A is
/// the last solve's, or the pairs whose initial gap is within 1 % of the smallest, and every pair whose
/// initial gap is <= 0 (closed, or an interference of contact surfaces).
///
/// Equilibrium refinement: K_A is stiffer than K by the penalty, so the round-off of a solve with it,
/// about eps rho |u|, is an out-of-balance force rho / k_i times that of a solve with K (1e-8 of the
/// load on the report's problem 3, enough to show in the support reactions). The settled set's
/// answer is corrected once: r = f + C^T lambda - K u (no penalty in it), K_A du = r, u += du,
/// lambda_A -= rho C_A du, after which K u = f + C^T lambda holds to the round-off of K alone.

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "contact_pairs.hpp"
#include "csc_pattern.hpp"
#include "dof_map.hpp"
#include "sparse_cholesky.hpp"
#include "updatable_factor.hpp"

namespace saasgaps {

/// What the next contact solve starts from and what the last one found (part of the restart state).
struct ContactState {
  std::vector<double> force;          ///< lambda_i >= 0 per pair (force units: the nodal load it puts on each side)
  std::vector<std::uint8_t> active;   ///< 1: pair i was enforced at g_i = 0
  [[nodiscard]] bool empty() const { return active.empty(); }
};

/// Figures of one contact solve, for the history row and the benchmark.
struct ContactReport {
  int pairs_in_contact = 0;
  int active_set_iterations = 0;  ///< factorizations of K_A
  int multiplier_iterations = 0;  ///< solves, over all active sets
  int factorizations = 0;         ///< numeric factorizations of K_A (the others were rank-k updates)
  double complementarity = 0.0;   ///< max_i |min(lambda_i / k_i, g_i)| / length scale (dimensionless)
};

class ExactContact {
 public:
  /// Active sets tried before giving up (each one factorization).
  static constexpr int max_active_set_iterations = 60;
  /// Multiplier iterations per active set (each one solve).
  static constexpr int max_multiplier_iterations = 40;
  /// rho_i / (c_i^T diag(K) c_i): large enough that each multiplier step gains about four digits,
  /// small enough not to spoil the factorization's accuracy.
  static constexpr double penalty_factor = 1.0e4;
  /// An active-set step that changes at most this many pairs updates the factorization (rank-k
  /// update and downdate of a simplicial LDL' copy) instead of refactorizing.
  static constexpr int max_update_rank = 100;
  /// Round-off: residuals below this fraction of the model's length scale are zero.
  static constexpr double round_off = 1.0e-11;
  /// Largest constraint residual accepted when the multiplier iterations stagnate before round_off.
  static constexpr double accepted_residual = 1.0e-8;

  ExactContact(const Model& model, const DofMap& dofs, const CscPattern& pattern, ContactPairs pairs);

  [[nodiscard]] const ContactPairs& pairs() const { return pairs_; }

  /// Adds the contact forces lambda_i w_ik n_i of `state` to the nodal forces (u_r, u_z per node):
  /// the C^T lambda of K u = f + C^T lambda. Nothing before the first solve.
  void add_nodal_forces(const ContactState& state, std::span<double> forces) const;

  /// Solves the contact problem for the assembled K (values, upper triangle in `pattern`) and f (rhs):
  /// the free displacements into u, the forces and active set into state (which, when not empty,
  /// is the warm start). Throws NotPositiveDefinite from the factorization, SolverError when the
  /// active set does not settle.
  ContactReport solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
                      ContactState& state, std::span<double> u);

 private:
  struct Entry {
    Index equation = -1;
    double coefficient = 0.0;  ///< w_k n_dir: g = g0_free + sum coefficient u[equation]
  };
  /// Row i of C, of any width: its entries are entries_[first, last), the upper-triangle positions
  /// of c c^T and the matching coefficient products are positions_/products_[first_product,
  /// last_product).
  struct Row {
    std::size_t first = 0, last = 0;
    std::size_t first_product = 0, last_product = 0;
    double g0 = 0.0;        ///< g0 plus the prescribed displacements' part
    double stiffness = 0.0; ///< k_i = c_i^T diag(K) c_i (recomputed per solve)
    double rho = 0.0;
    [[nodiscard]] bool empty() const { return first == last; }
  };

  [[nodiscard]] std::span<const Entry> entries(const Row& row) const {
    return std::span<const Entry>(entries_).subspan(row.first, row.last - row.first);
  }
  double residual(const Row& row, std::span<const double> u) const;
  using Solver = std::function<void(std::span<const double>, std::span<double>)>;
  void factor_active(SparseCholesky& cholesky, std::span<const double> values, const std::vector<std::uint8_t>& active);
  /// Brings updatable_ from the set `held` to `active` by a rank-k update and downdate.
  void update_active(const std::vector<std::uint8_t>& held, const std::vector<std::uint8_t>& active);
  /// The equilibrium refinement of the settled set (above).
  void refine_equilibrium(const Solver& solve, std::span<const double> values, std::span<const double> rhs,
                          const std::vector<std::uint8_t>& active, std::vector<double>& force, std::span<double> u);
  /// Multiplier iterations on the current factorization; returns the final max |g_A|.
  double multipliers(const Solver& solve, std::span<const double> rhs, const std::vector<std::uint8_t>& active,
                     std::vector<double>& force, std::span<double> u, double length, int& iterations);

  const Model& model_;
  const DofMap& dofs_;
  const CscPattern& pattern_;  // of K (the system's; it outlives the method)
  ContactPairs pairs_;
  std::vector<Row> rows_;
  std::vector<Entry> entries_;    // every row's entries, row after row
  std::vector<Index> positions_;  // every row's upper-triangle positions of c c^T, -1 = none
  std::vector<double> products_;  // the matching coefficient products
  std::vector<Index> diagonal_;  // position of K_jj
  std::vector<double> values_;   // K_A
  std::vector<double> b_;        // right-hand side of K_A u = b
  UpdatableFactor updatable_;    // for small active-set changes
  UpdateColumns columns_;
};

}  // namespace saasgaps
