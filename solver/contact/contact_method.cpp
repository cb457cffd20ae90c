#include "solver/contact/contact_method.hpp"

namespace saasgaps {

void ContactMethod::solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
                          RestartState&, std::span<double> u) {
  cholesky.factorize(values);
  cholesky.solve(rhs, u);
}

void ContactMethod::check_solved(const RestartState&, const ContactOutcome&) const {}

void ContactMethod::add_columns(const RestartState&, IterationRecord&) const {}

void ContactMethod::add_nodal_forces(const RestartState&, std::span<double>) const {}

std::string ContactMethod::converged_note(const RestartState&, const ContactOutcome&) const { return {}; }

std::vector<ContactPairResult> ContactMethod::surface_results(const RestartState&) const { return {}; }

}  // namespace saasgaps
