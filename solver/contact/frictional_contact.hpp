#pragma once
/// Unilateral contact with Coulomb friction, solved exactly, one load increment at a time. Point i
/// (a ContactPair: any number of nodes with weights, unit normal n_i, tangent t_i = (-n_z, n_r)) has
/// two rows (constraint_rows.hpp):
///   g_i(u) = g0_i + n_i . sum_k w_ik u_k     (gap, length; sum_k c_ik . u_k by the pair's gradient
///                                             when it has one: a mortar row of a curved side),
///   h_i(u) =        t_i . sum_k w_ik u_k     (tangential position of side b relative to side a),
/// and the increment from the previous one's converged state (h_i^prev, part of FrictionState) solves
///   K u = f + sum_i (lambda_n,i c_n,i + lambda_t,i c_t,i),
///   g_i >= 0, lambda_n,i >= 0, lambda_n,i g_i = 0                            (Signorini)
///   |lambda_t,i| <= mu_i lambda_n,i;  stick (|lambda_t,i| < mu_i lambda_n,i): v_i = 0,
///   slip: lambda_t,i = -mu_i lambda_n,i s_i,  s_i = sign(v_i)                 (Coulomb)
/// with v_i = h_i(u) - h_i^prev the slip of the increment (backward Euler) and lambda the forces that
/// side a puts on side b (along +n, +t; side a gets the opposite).
///
/// Algorithm (docs/contact.md, "Friction"): a primal-dual active set on the states open / stick /
/// slip (and the slip direction s). For one set the problem is linear and symmetric except for the
/// slip forces -mu lambda_n s c_t, which depend on the normal multipliers: every equality row
/// (normal rows of the points in contact, tangential rows of the sticking ones) goes into ONE
/// factorization of K + sum rho c c^T, and the slip forces are carried as loads updated with the
/// normal multipliers in each augmented-Lagrangian iteration (a fixed point that contracts while mu
/// times the normal-tangential coupling of the interface is below 1; zero for one material on both
/// sides). Then
///   open  -> contact (stick; slip when mu = 0, or, s = sign(v), when k_t |v| > mu k_n (-g): Coulomb
///            on the trial forces of the penetration and the motion made while open)   where g < -tol,
///   contact -> open                               where lambda_n < -tol k_n,
///   stick -> slip, s = -sign(lambda_t)            where |lambda_t| - mu lambda_n > tol k_t,
///   slip  -> stick                                where s v < -tol (it moves against its slip),
/// until nothing changes; a set seen before changes only its worst point. A set's multiplier
/// iterations stop early once a point violates it by 100 times their residual (the forces' error in
/// length units is about that residual; only the last set needs round-off). A warm start's first set
/// is held from the factor of "every touching point sticks", kept across solves while K and the
/// touching points are unchanged (ConstraintRows::hold_from). mu = 0 is exactly
/// ExactContact's algorithm (no tangential row is ever active, every slip force is zero).

#include <cstdint>
#include <span>
#include <vector>

#include "solver/assembly/dof_map.hpp"
#include "solver/contact/constraint_rows.hpp"
#include "solver/contact/contact_pair.hpp"
#include "solver/lac/csc_pattern.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/model/model.hpp"
#include "solver/state/contact_state.hpp"

namespace saasgaps {

/// Ends an increment: slip += |position - previous| at the slipping points, previous = position.
void finish_increment(FrictionState& state);

/// Figures of one frictional contact solve, for the history row and the benchmark.
struct FrictionReport {
  int in_contact = 0;             ///< points stick + slip
  int sticking = 0;
  int slipping = 0;
  int active_set_iterations = 0;
  int multiplier_iterations = 0;  ///< solves, over all active sets
  int factorizations = 0;         ///< numeric factorizations (the other active sets were rank-k updates)
  /// Signorini: max_i |min(lambda_n,i / k_n,i, g_i)| / length scale (dimensionless).
  double complementarity = 0.0;
  /// Coulomb: max over the points in contact, over the length scale, of
  ///   stick: max(|v|, (|lambda_t| - mu lambda_n) / k_t),   slip: max(|lambda_t + mu lambda_n s| / k_t, -s v).
  double friction_residual = 0.0;
};

class FrictionalContact {
 public:
  /// Active sets tried before giving up (each one factorization or rank-k update).
  static constexpr int max_active_set_iterations = 60;
  /// Largest constraint residual accepted (over the length scale) when the multiplier iterations
  /// stagnate before round-off.
  static constexpr double accepted_residual = 1.0e-8;

  /// friction: mu_i >= 0 per pair. The pattern must couple each pair's nodes.
  FrictionalContact(const Model& model, const DofMap& dofs, const CscPattern& pattern, ContactPairs pairs,
                    std::vector<double> friction);

  [[nodiscard]] const ContactPairs& pairs() const { return pairs_; }
  /// t_i = (-n_z, n_r): on a contact surface's point, side A's chain direction.
  static Vec2 tangent(const ContactPair& pair) { return Vec2(-pair.normal.y(), pair.normal.x()); }
  /// Adds the contact forces lambda_n,i c_n,ik + lambda_t,i w_ik t_i of `state` to the nodal forces
  /// (f_r, f_z per node): the C^T lambda of the increment's equilibrium. Nothing before the first solve.
  void add_nodal_forces(const FrictionState& state, std::span<double> forces) const;
  [[nodiscard]] const ConstraintRows& rows() const { return rows_; }
  /// The rows of point i: normal 2 i, tangential 2 i + 1.
  static constexpr std::size_t normal_row(std::size_t i) { return 2 * i; }
  static constexpr std::size_t tangential_row(std::size_t i) { return 2 * i + 1; }

  /// Solves one increment for the assembled K (values on `pattern`) and f (rhs) from state (its
  /// `previous`; the rest, when not empty, is the warm start): the free displacements into u, the
  /// forces, states and positions into state. Throws SolverError naming the reason when the
  /// increment has no solution (a body that friction cannot hold slides away), when the active set
  /// does not settle, or when the multipliers do not converge; NotPositiveDefinite when K is
  /// singular with no point slipping (the usual "not restrained").
  FrictionReport solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
                       FrictionState& state, std::span<double> u);

 private:
  const Model& model_;
  ContactPairs pairs_;
  std::vector<double> mu_;
  ConstraintRows rows_;
};

}  // namespace saasgaps
