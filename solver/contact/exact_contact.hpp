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
/// until A repeats; an active set seen before (a cycle) changes only its worst pair. Only the set
/// that settles is solved to round-off: a set that some pair violates by a thousand times a multiplier
/// step's residual stops there (docs/contact.md, section 3). The first A is
/// the last solve's, or the pairs whose initial gap is within 1 % of the smallest, or, with an
/// interference of contact surfaces (some g0 < 0), every pair whose initial gap is at most the
/// largest interference -min g0 (contact_start).
///
/// Looking ahead: the PDAS step moves the contact boundary only as far as one solve shows it (an
/// eccentric fit: by 40, 13, 6, 3, 1 and 1 rows, a set each). Whenever the set is held by a fresh
/// supernodal factorization (the first set of a cold start), the rows near the boundary are
/// condensed onto their multipliers through forward solves over their reach in the factor
/// (ConstraintRows::condense) and their small complementarity problem is solved exactly
/// (condensed_lcp.hpp): its answer is the next set, which the solver then checks as any other.
///
/// Equilibrium refinement (ConstraintRows::refine_equilibrium): the settled set's answer is corrected
/// once so that K u = f + C^T lambda holds to the round-off of K alone, not of K_A.

#include <cstdint>
#include <span>
#include <vector>

#include "solver/assembly/dof_map.hpp"
#include "solver/contact/constraint_rows.hpp"
#include "solver/contact/contact_pair.hpp"
#include "solver/lac/csc_pattern.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/state/contact_state.hpp"

namespace saasgaps {

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
  /// Active sets tried before giving up (each one factorization or rank-k update).
  static constexpr int max_active_set_iterations = 60;
  /// Largest constraint residual accepted when the multiplier iterations stagnate before round-off
  /// (ConstraintRows: the penalties, the update rank and the round-off level).
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
  /// Rows condensed by predict(): this many per row that violates the set, within these bounds.
  /// max_window was 256, then 512; at 1024 a surface of up to a thousand rows whose first set is
  /// far from the answer is condensed whole, and the look-ahead from the first set finds the final
  /// set in one step: the eccentric ring fit on quad8 (183 of 367 rows violating the first set at
  /// 1.5 x 10^5 unknowns) took 9 sets, 2 factorizations and 12 solves with a window of 256, and
  /// takes 2, 1 and 4 with the window of all 367; at 10^6 unknowns (949 rows) 12 sets and 3
  /// factorizations with 512, 2 and 1 with 1024 (the condensation of 949 rows: forward solves over a
  /// reach of 25,419 rows of L in 0.46 s against a 4.7 s factorization). Windows over 256 come only
  /// from sets that more than 85 rows violate, which the straight-edge fits (at most 47 rows at
  /// 1.5 x 10^5) do not reach.
  static constexpr std::size_t window_per_change = 3, min_window = 64, max_window = 1024;
  /// Rings of neighbours round the violating rows that the window takes whatever their margins.
  static constexpr std::size_t whole_rings = 2;

  /// The next active set as the condensed problem of the rows nearest to changing sees it
  /// (ConstraintRows::condense, solve_condensed_lcp): the rows that violate `active` and those
  /// whose margin (lambda_i / k_i when pressing, g_i when open) is smallest, window_per_change
  /// times as many in all; the other rows keep their state. Needs rows_.factorized(active).
  /// Empty when the condensed problem has no answer.
  std::vector<std::uint8_t> predict(const std::vector<std::uint8_t>& active, std::span<const double> force,
                                    std::span<const double> u, std::span<const double> g, int changes,
                                    double tolerance);

  const Model& model_;
  ContactPairs pairs_;
  ConstraintRows rows_;  // row i: pair i's gap function
};

}  // namespace saasgaps
