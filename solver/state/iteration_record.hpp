#pragma once
/// One row of the iteration history (the columns of the report's Tables I-V), and the observer
/// that receives each row with the state to resume from.

#include <array>
#include <string>
#include <vector>

#include "solver/state/thermal_record.hpp"

namespace saasgaps {

struct RestartState;

struct WatchedElement {
  int id = 0;
  double sigma_r = 0.0, sigma_z = 0.0, tau_rz = 0.0, sigma_theta = 0.0, effective = 0.0;
};

struct WatchedGap {
  int id = 0;
  double modulus = 0.0;  ///< E_M used in the iteration
  double closure = 0.0;  ///< %
  double sigma_m = 0.0;  ///< normal stress across the gap (negative in compression)
};

/// The summed support reactions of a node set that a constraint names (Model::reaction_groups):
/// force units, plane analyses on the whole thickness, axisymmetric ones on the full ring.
struct SetReaction {
  std::string set;
  double f_r = 0.0;
  double f_z = 0.0;
};

/// The resultant force side B of a contact pair exerts on side A (ContactPairResult::force).
struct PairForce {
  std::array<std::string, 2> surfaces;
  double f_r = 0.0;
  double f_z = 0.0;
};

struct IterationRecord {
  int iteration = 0;           ///< counts over the whole run, across steps and increments
  /// Stepped models only: the step (1-based index into Model::steps) and the increment (1-based
  /// within the step) the iteration belongs to; 0 for a model without steps (no such columns).
  int step = 0;
  int increment = 0;
  double tensile_modulus = 0.0;
  int closed_gaps = 0;         ///< closure > 100 %
  int nonconverged_gaps = 0;   ///< GAP-CONV? = NO
  double average_closure = 0.0;
  double max_closure = 0.0;
  int yielded_elements = 0;    ///< YIELD? = YES
  int nonconverged_plastic = 0;  ///< N-L/CONV? = NO
  int bimodulus_changes = 0;   ///< elements that switched tension/compression properties
  bool extrapolated = false;   ///< gap moduli of this iteration used the extrapolation of Fig. 19
  /// Exact mode only (0 in classic): node pairs in contact, the largest complementarity residual
  /// |min(lambda_i / k_i, g_i)| over the model's length scale, and the active sets tried.
  int contact_pairs = 0;
  double complementarity = 0.0;
  int active_set_iterations = 0;
  /// Contact pairs with friction > 0 only (0 otherwise): points that stick and that slip at the
  /// end of the iteration, and the largest residual of Coulomb's law over the touching points, over
  /// the model's length scale (dimensionless, 0 when the law holds exactly; FrictionReport and
  /// docs/contact.md section 9 define it).
  int stick_points = 0;
  int slip_points = 0;
  double friction_residual = 0.0;
  std::vector<WatchedElement> watch_elements;
  std::vector<WatchedGap> watch_gaps;
  std::vector<double> gap_closures;  ///< closure (%) of every gap, in model order: the closure plot
  /// The last row of each converged increment (and of a converged run without steps) only, else
  /// empty: the summed reactions of every reaction group, and the force of every contact pair.
  std::vector<SetReaction> set_reactions;
  std::vector<PairForce> pair_forces;
  double seconds = 0.0;        ///< wall time of the iteration
  int attempt = 1;             ///< which run (1 = first, 2 = first resume, ...) computed the row

  /// Equality of every computed number (wall time excluded): what an exact restart must keep.
  [[nodiscard]] bool same_numbers(const IterationRecord& other) const;
};

/// Receives every finished iteration. The CLI prints it, the service commits it; the solver knows
/// neither.
class IterationObserver {
 public:
  virtual ~IterationObserver() = default;
  /// Called after each iteration with its history row and the complete state to resume after it.
  virtual void on_iteration(const IterationRecord& row, const RestartState& state) = 0;
  /// Polled at every iteration boundary: true stops the run there, its state kept.
  virtual bool stop_requested() { return false; }
  /// Called after each thermal row of a run with `thermal` (thermal_record.hpp), before the stress
  /// iterations that use its temperatures. An observer that shows only stress iterations ignores it.
  virtual void on_thermal(const ThermalRecord& /*row*/) {}
};

}  // namespace saasgaps
