#pragma once
/// The classic contact method of SAASGAPS (gaps.method = "classic"): the gap elements' moduli set by
/// section II (a)-(d) from one iteration to the next (gap_closure.hpp), K u = f solved as it stands,
/// and test (e) as the method's verdict. Its state is the gap history (state.gaps); it keeps nothing
/// in state.contact.

#include "solver/contact/contact_method.hpp"
#include "solver/gaps/gap_elements.hpp"

namespace saasgaps {

class GapModulusMethod final : public ContactMethod {
 public:
  GapModulusMethod(const Model& model, const GapSettings& settings);

  /// (a) iteration 1 at E0, (b)-(d) and Fig. 19 after it.
  void begin_iteration(RestartState& state, StiffnessSystem& system) override;
  /// Factorize and solve (the default), keeping |f|_1 for check_solved.
  void solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
             RestartState& state, std::span<double> u) override;
  /// The gap elements' closures and stresses; state by closure: open (eps_M >= 0), partial, closed
  /// (within closure_tolerance of contact), overclosed; the verdict of test (e).
  void evaluate(RestartState& state, ContactOutcome& outcome) const override;
  /// A body held only by the floor springs has no equilibrium: once the tensile schedule has begun
  /// (iteration 2 on), the gaps open at the floor modulus (eps_M >= 0, E_M at most the floor) must carry
  /// at most 10 % of the load, |f|_1 plus the forces of the gaps in compression, or SolverError "the
  /// contact problem has no solution" (GapElements::check_floor_share). A gap open at the floor is a
  /// fixed point of the iteration, so test (e) would otherwise accept the floor springs' answer.
  void check_solved(const RestartState& state, const ContactOutcome& outcome) const override;
  void add_columns(const RestartState& state, IterationRecord& row) const override;
  /// The gap elements' forces.
  void add_nodal_forces(const RestartState& state, std::span<double> forces) const override;
  /// The warning about loaded gaps that do not touch (loaded_open_gaps), or nothing.
  [[nodiscard]] std::string converged_note(const RestartState& state, const ContactOutcome& outcome) const override;

 private:
  [[nodiscard]] GapState state_of(double eps_m) const;
  /// The classic method's blind spot: gaps stiffened above the floor modulus that stopped short of
  /// contact yet carry a real share of the largest gap pressure. Their pressures are where the
  /// iteration stopped, not the contact answer. (A gap at the floor modulus carries only the
  /// negligible spring the exact method keeps too.) Empty when there are none.
  [[nodiscard]] std::string loaded_open_gaps(const RestartState& state, const ContactOutcome& outcome) const;

  GapElements gaps_;
  double load_norm_ = 0.0;  // |f|_1 of the last solve
};

}  // namespace saasgaps
