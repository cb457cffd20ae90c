#pragma once
/// The exact contact method (gaps.method = "exact"): every gap element at the floor modulus, the gap
/// elements' node pairs (contact_pairs.hpp) enforced as unilateral constraints by ExactContact in
/// each solve. Its state is the pairs' forces and active set (state.contact), the warm start of the
/// next solve; state.gaps records the floor moduli and the pairs' closures. Each iteration solves the
/// contact problem to round-off, so the method never vetoes convergence: the iteration goes on only
/// while the materials change.

#include <span>

#include "solver/contact/contact_method.hpp"
#include "solver/contact/exact_contact.hpp"
#include "solver/gaps/contact_pairs.hpp"
#include "solver/gaps/gap_elements.hpp"

namespace saasgaps {

class NodePairMethod final : public ContactMethod {
 public:
  /// Throws GapPairingError naming every gap element that cannot be paired. `extra` (null: none):
  /// further rows solved with the node pairs, after them (contact surfaces' rows, mortar_method.hpp);
  /// the pattern must hold their couplings.
  NodePairMethod(const Model& model, const GapSettings& settings, const DofMap& dofs, const CscPattern& pattern,
                 const ContactPairs* extra = nullptr);

  /// Every gap at the floor modulus.
  void begin_iteration(RestartState& state, StiffnessSystem& system) override;
  /// ExactContact::solve, warm-started from state.contact.
  void solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
             RestartState& state, std::span<double> u) override;
  /// measure_pair_contact and touching_verdict.
  void evaluate(RestartState& state, ContactOutcome& outcome) const override;
  /// The floor springs of open gaps are there to restrain bodies held only by gaps, not to carry load.
  /// When they carry more than 1 % of it, a body is pushed away from every support and the contact
  /// problem has no solution (or the floor modulus is not negligible): SolverError naming the gaps.
  void check_solved(const RestartState& state, const ContactOutcome& outcome) const override;
  /// Pairs in contact, complementarity residual, active sets of the last solve.
  void add_columns(const RestartState& state, IterationRecord& row) const override;
  /// The floor springs' forces and the pairs' contact forces lambda_i w_ik n_i (K u = f + C^T lambda).
  void add_nodal_forces(const RestartState& state, std::span<double> forces) const override;
  /// "(exact contact: N of M node pairs in contact, complementarity residual r)" (the node pairs
  /// only; the residual is of every row).
  [[nodiscard]] std::string converged_note(const RestartState& state, const ContactOutcome& outcome) const override;

 private:
  GapElements gaps_;
  ExactContact exact_;      // the node pairs first, then the extra rows
  std::size_t node_pairs_;  // how many of exact_'s rows are node pairs
  ContactReport report_;   // of the last solve
  double load_norm_ = 0.0; // |f|_1 of the last solve
};

/// Per gap element, from its node pairs: eps_M = -(area-weighted closure of its pairs) / (area-weighted
/// g0), sigma_m reduced by the contact pressure (the area-weighted mean of its pairs' force / area: a
/// uniform pressure p gives every pair lambda_i = p area_i, hence exactly p on every gap), closure
/// from eps_M, state closed where some pair of the gap is active and open elsewhere. Expects id,
/// modulus and the floor spring's sigma_m from GapElements::measure; the forces and active set from
/// `contact` (ignored when it does not hold one entry per pair: before the first solve).
void measure_pair_contact(const ContactPairs& pairs, const ContactState& contact,
                          std::span<const double> displacement, ContactOutcome& outcome);

/// The verdict of a method that solves the contact problem in every iteration: every gap converged;
/// the closed gaps are the touching ones (state closed), average_closure their mean closure.
void touching_verdict(ContactOutcome& outcome);

}  // namespace saasgaps
