#pragma once
/// The contact seam: how a run enforces contact across its gaps. The analysis loop (analysis.cpp)
/// calls one ContactMethod and never asks which one it is; each method lives in its own file pair
/// and owns its part of the restart state, its post-processing, its history columns and its
/// messages. make_contact_method() is the one place that chooses a method by gaps.method.
///
/// Per iteration K+1 the loop calls
///   begin_iteration  (what the method adds to K and f, from the state after K, assembled on top of
///                     the solids: the gap elements at this iteration's moduli)
///   solve            (K u = f with contact enforced)
///   evaluate         (closure, pressure, state and verdict per gap, from the displacements)
///   check_solved     (may throw: the solved iteration shows the problem has no answer)
///   add_columns      (the method's own columns of the history row)
/// and stops when the materials' verdict AND the method's verdict (ContactOutcome::converged) hold.

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "solver/assembly/dof_map.hpp"
#include "solver/lac/csc_pattern.hpp"
#include "solver/lac/sparse_cholesky.hpp"
#include "solver/model/model.hpp"
#include "solver/state/restart_state.hpp"
#include "solver/state/solution.hpp"

namespace saasgaps {

class StiffnessSystem;
struct SurfaceContact;

/// What a method finds in one iteration's displacements: one row per gap element (model order) and
/// the summary columns of the history (the report's Tables I-V).
struct ContactOutcome {
  std::vector<GapResult> gaps;   ///< id, eps_M, closure (%), E_M used, sigma_m, state, GAP-CONV?, failure
  int nonconverged = 0;          ///< gaps that fail the method's test: the method's veto
  int closed = 0;                ///< gaps the method counts as closed (the report's "closed gaps")
  double average_closure = 0.0;  ///< mean closure (%) of those; 0 when none
  double max_closure = 0.0;      ///< largest closure (%) of all gaps
  [[nodiscard]] bool converged() const { return nonconverged == 0; }
};

class ContactMethod {
 public:
  virtual ~ContactMethod() = default;

  /// Iteration state.iteration + 1 begins (state.iteration = 0: the first). Sets what the method adds
  /// to the system from the state after iteration K, records it in its part of the state (the gap
  /// moduli in state.gaps), and assembles it into `system` on top of the solids.
  virtual void begin_iteration(RestartState& state, StiffnessSystem& system) = 0;

  /// Solves the assembled K u = f (values: upper triangle in the system's pattern) for the free
  /// unknowns u, with contact enforced; the method's warm start and result go in its part of the state
  /// (state.contact). This default, for methods that enforce contact through K alone: factorize and
  /// solve. Throws NotPositiveDefinite for a singular K.
  virtual void solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
                     RestartState& state, std::span<double> u);

  /// Measures iteration K (state.displacement, state.gaps) into `outcome`: the same code runs after a
  /// solve and after a resume, which is what makes a restart exact. Keeps or checks the strains of
  /// state.gaps (see keep_gap_strains).
  virtual void evaluate(RestartState& state, ContactOutcome& outcome) const = 0;

  /// Right after a solve (not after a resume): throws SolverError when the iteration shows the contact
  /// problem has no meaningful answer. Default: nothing to check.
  virtual void check_solved(const RestartState& state, const ContactOutcome& outcome) const;

  /// The method's own columns of the history row of iteration K (the per-gap and summary columns come
  /// from the outcome). Default: none.
  virtual void add_columns(const RestartState& state, IterationRecord& row) const;

  /// Adds to `forces` (f_r, f_z per node, every node) the forces the method's contact exerts on the
  /// nodes in iteration K's state (state.displacement, state.gaps.used, state.contact): what the
  /// support reactions balance besides the solids and the loads (reactions.hpp). Default: none.
  virtual void add_nodal_forces(const RestartState& state, std::span<double> forces) const;

  /// What "converged in K iterations" goes on to say about the contact (empty: nothing). Default: "".
  [[nodiscard]] virtual std::string converged_note(const RestartState& state, const ContactOutcome& outcome) const;

  /// The contact surface pairs' points (result `contact`) of iteration K. Default: none.
  [[nodiscard]] virtual std::vector<ContactPairResult> surface_results(const RestartState& state) const;
};

/// What a method is built from: the model, its gap settings with a restart's changes applied (null
/// when the model has no gaps), and the system's numbering and sparsity pattern.
struct ContactSetup {
  const Model& model;
  const GapSettings* gaps = nullptr;
  const DofMap& dofs;
  const CscPattern& pattern;
  /// The rows of model.contact (mortar_method.hpp), whose couplings the pattern holds; null or
  /// without pairs when the model has no contact surfaces.
  const SurfaceContact* surfaces = nullptr;
};

/// Builds the contact method of one run. solve() takes one; make_contact_method is the default, and a
/// test (or a new method under trial) passes its own.
using ContactMethodFactory = std::function<std::unique_ptr<ContactMethod>(const ContactSetup&)>;

}  // namespace saasgaps
