#pragma once
/// Linear constraint rows of any width over the free unknowns, and the equality-constrained solve on
/// any subset A of them that the exact contact solvers (exact_contact.hpp, frictional_contact.hpp)
/// repeat for each active set:
///   row r:   g_r(u) = g0_r + c_r . u,    c_r = d_r . sum_k w_rk u_k   (d_r a unit direction: a
///            contact normal, or its tangent; prescribed components are folded into g0_r),
///   find u, lambda_A with   K u = f + C_A^T lambda_A + p(lambda),   g_A(u) = 0,
/// where p(lambda) is an optional load that depends on the multipliers (friction's slip forces).
///
/// The equality problem is solved to round-off by augmented-Lagrangian multiplier (Uzawa)
/// iterations on ONE factorization of
///   K_A = K + sum_{r in A} rho_r c_r c_r^T,     rho_r = penalty_factor * min(k_r, jacobi_multiple / (c_r^T diag(K)^-1 c_r)),
///   k_r = c_r^T diag(K) c_r,
///   K_A u = f + p(lambda) + C_A^T (lambda - rho g0),     lambda_r <- lambda_r - rho_r g_r(u),
/// each iteration one pair of triangular solves. After each update K u = f + p + C_A^T lambda holds
/// exactly; g_A is what is left. A change of A by at most max_update_rank rows is a rank-k update
/// and downdate of the factor converted to simplicial form (updatable_factor.hpp), not a factorization.

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "solver/assembly/dof_map.hpp"
#include "solver/base/voigt.hpp"
#include "solver/lac/csc_pattern.hpp"
#include "solver/lac/set_correction.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/lac/updatable_factor.hpp"

namespace saasgaps {

/// Where contact begins, for a cold start: the rows whose initial gap is at most this are active
/// first. Without interference (every g0 >= 0) those within 1 % of the smallest gap; with one
/// (smallest g0 < 0, contact surfaces) every row whose gap is at most the largest interference
/// -min g0: the penetrating rows and the open ones the fit's deformation is likely to close.
double contact_start(std::span<const double> g0);

class ConstraintRows {
 public:
  /// Multiplier iterations per active set (each one solve).
  static constexpr int max_multiplier_iterations = 40;
  /// rho_r / k_r: large enough that each multiplier step gains about four digits, small enough not
  /// to spoil the factorization's accuracy.
  static constexpr double penalty_factor = 1.0e4;
  /// The penalty's stiffness k_r = c_r' diag(K) c_r is capped at this many times the row's Jacobi
  /// stiffness 1 / (c_r' diag(K)^-1 c_r) (force per length: the row's stiffness were its unknowns
  /// uncoupled). k_r overestimates the Jacobi stiffness by (c' D c)(c' D^-1 c) >= (c' c)^2 (Cauchy-
  /// Schwarz): 4 for a node pair (weights +-1) of equal diagonals, 3.5-4.3 on straight 2-node mortar
  /// rows, but 3.0-11.4 on rows over 3-node (quad8) edges, whose weights spread over corner and
  /// mid-side nodes of very different diagonals (the quad8 ring fit at 1.5 x 10^5 unknowns). There
  /// the uncapped penalty was about 20 times a row's true stiffness 1 / f_r (8.5 on straight rows),
  /// and a SetCorrection of such rows lost 1 + rho_r f_r = 2.03e5, over max_correction_loss, so
  /// the eccentric fit on quad8 refactorized. The cap leaves node pairs of equal sides and straight
  /// rows where they were (within 8 %), never raises a penalty, and brings quad8 rows to what
  /// straight rows lose.
  static constexpr double jacobi_multiple = 4.0;
  /// An active-set change of at most this many rows updates the factorization instead of
  /// refactorizing (at larger ranks an update costs as much as a factorization).
  static constexpr int max_update_rank = 100;
  /// A set within this many rows of the one factorized supernodally is solved on that factorization
  /// through a SetCorrection (dense in these rows: the rank's cube stays under 1.1e9 flops, about
  /// 0.1 s). 1024, as ExactContact's largest look-ahead window, so that a set the look-ahead finds is
  /// corrected rather than factorized (the quad8 eccentric fit's final set differs from its first by
  /// 318 rows at 1.5 x 10^5 unknowns and 826 at 10^6; with the window's forward solves shared the
  /// correction of 826 rows took 0.015 s, against a 4.7 s factorization).
  static constexpr std::size_t max_correction_rank = 1024;
  /// ... and when it loses at most this factor of accuracy (SetCorrection::loss), else the factor
  /// is updated or factorized as before. The correction's round-off is about loss x 1e-16 of the
  /// solution (observed 1.6e-12 at a loss of 3.6e4), and the active-set decisions are taken at
  /// 10 round_off = 1e-10 of the length scale: at a loss of 5.4e5 (node-to-node gap pairs of the
  /// eccentric ring fit, whose rows are stiffer than their nodes' diagonal suggests) the sets
  /// cycled; mortar rows of contact surfaces lose 8.5e4 at every size measured and settle as with
  /// updates. A part held by its contact rows alone would lose all its digits.
  static constexpr double max_correction_loss = 2.0e5;
  /// Round-off: residuals below this fraction of the length scale are zero.
  static constexpr double round_off = 1.0e-11;

  struct Entry {
    Index equation = -1;
    double coefficient = 0.0;  ///< w_k d_dir: g = g0 + sum coefficient u[equation]
  };

  /// Loads that depend on the multipliers: adds p(lambda) for the current `force` to b and returns
  /// how far (length units: force over the row stiffness) they moved since the last call.
  using DependentLoad = std::function<double(std::span<const double> force, std::span<double> b)>;

  /// pattern: the upper-triangle pattern of K; it must couple the unknowns of every row added.
  ConstraintRows(const DofMap& dofs, const CscPattern& pattern);

  /// Appends the row g = g0 + direction . sum_k weight_k u_{node_k}; returns its index. Components
  /// along direction below 1e-12 of the weight are no coupling (cos 90 degrees is 6e-17, not 0).
  std::size_t add(std::span<const int> nodes, std::span<const double> weights, const Vec2& direction, double g0);
  /// Appends the row g = g0 + sum_k c_k . u_{node_k}, a direction per node (a row whose direction
  /// varies along its support, as mortar rows on a curved interface do); returns its index.
  /// Components below 1e-12 of |c_k| are no coupling.
  std::size_t add(std::span<const int> nodes, std::span<const Vec2> coefficients, double g0);

  [[nodiscard]] std::size_t size() const { return rows_.size(); }
  /// True when every unknown of the row is prescribed: nothing to enforce.
  [[nodiscard]] bool empty(std::size_t r) const { return rows_[r].first == rows_[r].last; }
  [[nodiscard]] std::span<const Entry> entries(std::size_t r) const {
    return std::span<const Entry>(entries_).subspan(rows_[r].first, rows_[r].last - rows_[r].first);
  }
  /// g0_r as added plus direction . the prescribed displacements of its nodes (DofMap values).
  [[nodiscard]] double prescribed_g0(std::size_t r) const { return rows_[r].prescribed_g0; }
  [[nodiscard]] double g0(std::size_t r) const { return rows_[r].g0; }
  /// Shifts a row's target: g_r = g0 + c_r . u with a new g0 (friction's stick rows: minus the
  /// previous increment's tangential position).
  void set_g0(std::size_t r, double g0) { rows_[r].g0 = g0; }
  /// g_r(u) for the free displacements u.
  [[nodiscard]] double value(std::size_t r, std::span<const double> u) const;
  /// k_r = c_r^T diag(K) c_r of the last set_penalties (force per length).
  [[nodiscard]] double stiffness(std::size_t r) const { return rows_[r].stiffness; }
  /// b += load c_r.
  void add_load(std::size_t r, double load, std::span<double> b) const;

  /// Penalties from this K's diagonal (values on the pattern), and forgets the factorization held:
  /// call once per assembled K, before hold().
  void set_penalties(std::span<const double> values);

  /// Makes the solver hold K_A for A = active (one flag per row): a rank-k update of the held factor
  /// when A is within max_update_rank rows of it, else a factorization of `cholesky`. Returns true
  /// when it factorized. Throws NotPositiveDefinite when K_A is singular.
  bool hold(SparseCholesky& cholesky, std::span<const double> values, std::span<const std::uint8_t> active);

  /// hold() for the first set of a solve that starts from a known set `base` (within max_update_rank
  /// rows of `active`): K_base is factorized and kept as a simplicial factor across solves while
  /// `values` and `base` stay the same (compared bit for bit), and each call starts from a copy of
  /// it updated to `active`. The factor held is then a function of (values, base, active) alone,
  /// whatever the solves before did: a run resumed from a saved state factorizes K_base afresh and
  /// holds the very factor the uninterrupted run held. Returns true when it factorized; falls back
  /// to hold() when `active` is too far from `base` or an update loses definiteness. Costs a second
  /// simplicial factor and a copy of the values in memory; when `values` change from call to call
  /// every call factorizes K_base and converts it (a conversion hold() spares a set it never updates).
  bool hold_from(SparseCholesky& cholesky, std::span<const double> values, std::span<const std::uint8_t> base,
                 std::span<const std::uint8_t> active);

  /// Rows whose unknowns are coupled in K's pattern to some unknown of row r (through a node they
  /// share or an element both touch): r's neighbours along its surface. Derived on first use, for
  /// the rows added until then.
  [[nodiscard]] std::span<const std::size_t> neighbours(std::size_t r);

  /// True when the factorization held is the supernodal one of K_A for A = active (the last hold()
  /// factorized it): what condense() works on.
  [[nodiscard]] bool factorized(std::span<const std::uint8_t> active) const;

  /// The rows of `window` condensed onto their multipliers, every other row held as it stands:
  ///   g_W = q + S lambda_W   (lengths),   S = C_W K_O^-1 C_W',
  /// K_O = K plus the penalties of the active rows outside the window, whose forces stay as they
  /// are. Needs factorized(active), and u and force as a multiplier step on that factorization left
  /// them. From T = C_W K_A^-1 C_W' (SparseCholesky::inverse_form), P = diag(rho_r) over the window's
  /// active rows (0 on the others) and the forces y0 = force + P g(u) that u was solved with:
  ///   g_W = g(u) + T (y - y0),   lambda_W = y - P g_W   =>   S = (I - T P)^-1 T,  q = (I - T P)^-1 (g(u) - T y0)
  /// (S = (T^-1 - P)^-1: symmetric). Exact for the window's rows up to the penalty's 1/penalty_factor
  /// on the rows outside, which is what a guess of the next active set needs. Returns false when S
  /// or q is not finite.
  bool condense(std::span<const std::size_t> window, std::span<const std::uint8_t> active,
                std::span<const double> force, std::span<const double> u, Eigen::MatrixXd& s, Eigen::VectorXd& q);

  /// Equilibrium refinement of a settled set. K_A is stiffer than K by the penalty, so the round-off
  /// of a solve with it, about eps rho |u|, is an out-of-balance force rho / k_r times that of a
  /// solve with K (1e-8 of the load on the report's problem 3, enough to show in the support
  /// reactions). Corrected once on the held K_A: r = f + C_L^T force - K u (no penalty in it; L = the
  /// active rows and the `loaded` ones, whose force is a given load such as a slip force),
  /// K_A du = r, u += du, force_A -= rho C_A du; then K u = f + C_L^T force holds to the round-off
  /// of K alone. values: K on the pattern. (It cannot double as a multiplier step: the forces would
  /// then take rho times the round-off of g_A(u), eps rho |u|, which this correction removes.)
  void refine_equilibrium(std::span<const double> values, std::span<const double> rhs,
                          std::span<const std::uint8_t> active, std::span<double> force, std::span<double> u,
                          std::span<const std::uint8_t> loaded = {});

  /// The length scale residuals are measured against: max(length, max |u|).
  [[nodiscard]] static double scale(double length, std::span<const double> u);

  /// After a multiplier iteration, with its residual: true to stop there (an active-set solver that
  /// already knows the set will change, so that more digits of this set's answer would be wasted).
  using Decided = std::function<bool(double residual)>;

  /// Multiplier iterations on the held K_A: updates force (one per row, the active ones) and u;
  /// returns the final max |g_A| (and the dependent load's last move). Stops at round_off times the
  /// scale max(length, |u|_inf), when two steps in a row fail to halve the residual, or when
  /// `decided` says so.
  double multipliers(std::span<const double> rhs, std::span<const std::uint8_t> active, std::span<double> force,
                     std::span<double> u, double length, int& iterations, const DependentLoad& dependent = {},
                     const Decided& decided = {});

 private:
  /// Row r's entries are entries_[first, last); the upper-triangle positions of c c^T and the
  /// matching coefficient products are positions_/products_[first_product, last_product).
  struct Row {
    std::size_t first = 0, last = 0;
    std::size_t first_product = 0, last_product = 0;
    double prescribed_g0 = 0.0;
    double g0 = 0.0;
    double stiffness = 0.0;
    double rho = 0.0;
  };
  void factor(SparseCholesky& cholesky, std::span<const double> values, std::span<const std::uint8_t> active);
  /// Appends scale c_r to columns_ as a column.
  void add_column(std::size_t r, double scale);
  /// Makes correction_ solve K_active on the supernodal factorization of K_factored_; false (and
  /// nothing held) when it would lose more than max_correction_loss.
  bool correct(std::span<const std::uint8_t> active);
  /// x = K_A^-1 b for the set held, whichever way it is held.
  void solve_held(std::span<const double> b, std::span<double> x);
  /// Brings updatable_ from the set `held_` to `active` by a rank-k update and downdate.
  void update(std::span<const std::uint8_t> active);

  const DofMap& dofs_;
  const CscPattern& pattern_;
  std::vector<Row> rows_;
  std::vector<Entry> entries_;    // every row's entries, row after row
  std::vector<Index> positions_;  // every row's upper-triangle positions of c c^T
  std::vector<double> products_;  // the matching coefficient products
  std::vector<Index> diagonal_;   // position of K_jj
  std::vector<double> values_;    // K_A
  std::vector<double> b_;         // right-hand side of K_A u = b
  // The supernodal factorization holds K_F (F = factored_); small changes from it convert it to
  // simplicial form in place and go to that by rank-k updates and downdates (held_: the simplicial
  // factor's set, empty while the supernodal one is in use).
  SparseCholesky* cholesky_ = nullptr;
  std::vector<std::uint8_t> factored_, held_;
  // A set near factored_ solved on its supernodal factorization (corrected_: that set, empty when
  // none); converted_: the supernodal factorization was converted to simplicial form since it was
  // made, so it can no longer solve.
  SetCorrection correction_;
  std::vector<std::uint8_t> corrected_;
  // condense()'s forward solves on the supernodal factorization held (window_reach_ over the rows
  // window_rows_, window_gram_ = Z'Z), kept for correct() until the next factorization: a set the
  // look-ahead finds differs from the factorized one only in rows of its window.
  std::shared_ptr<const SparseCholesky::Reach> window_reach_;
  std::vector<double> window_gram_;
  std::vector<std::size_t> window_rows_;
  bool converted_ = false;
  UpdatableFactor updatable_;
  SparseColumns columns_;
  // neighbours(): row r's are neighbours_[neighbour_start_[r] .. neighbour_start_[r + 1]).
  std::vector<std::size_t> neighbour_start_, neighbours_;
  // hold_from's factor of K_base (base_: its set, empty when none; base_values_: the K it is of).
  UpdatableFactor base_factor_;
  std::vector<std::uint8_t> base_;
  std::vector<double> base_values_;
};

}  // namespace saasgaps
