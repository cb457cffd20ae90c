#include "exact_contact.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string_view>

#include "errors.hpp"
#include "plural.hpp"

namespace saasgaps {

ExactContact::ExactContact(const Model& model, const DofMap& dofs, const CscPattern& pattern, ContactPairs pairs)
    : model_(model), pairs_(std::move(pairs)), rows_(dofs, pattern) {
  for (const ContactPair& p : pairs_.pairs) {
    std::vector<Vec2> coefficients(p.node.size());
    for (std::size_t k = 0; k < p.node.size(); ++k) coefficients[k] = p.coefficient(k);
    rows_.add(p.node, coefficients, p.g0);
  }
}

ContactReport ExactContact::solve(SparseCholesky& cholesky, std::span<const double> values,
                                  std::span<const double> rhs, ContactState& state, std::span<double> u) {
  const std::size_t n = rows_.size();
  ContactReport report;
  rows_.set_penalties(values);
  // Warm start: the last active set. Otherwise where contact begins (contact_start): every pair of
  // a uniform gap (fits, pressed contacts: one active set), the first point of contact of a curved
  // one (Hertz: 8 active sets where starting from every pair peels the contact open three pairs at a
  // time, 13), and with an interference every pair whose gap is within the largest interference
  // (an eccentric fit: one factorization where the pairs with g0 <= 0 alone took two).
  std::vector<double> g0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!rows_.empty(i)) g0.push_back(rows_.g0(i));
  }
  std::vector<std::uint8_t> active(n, 0);
  if (state.active.size() == n) {
    active = state.active;
  } else {
    const double start = contact_start(g0);
    for (std::size_t i = 0; i < n; ++i) active[i] = rows_.g0(i) <= start;
  }
  std::vector<double> force = state.force.size() == n ? state.force : std::vector<double>(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (rows_.empty(i)) active[i] = 0;  // both nodes prescribed: nothing to enforce
    if (!active[i]) force[i] = 0.0;
  }
  double length = 0.0;
  for (std::size_t i = 0; i < n; ++i) length = std::max(length, std::abs(rows_.g0(i)));

  const auto key_of = [](const std::vector<std::uint8_t>& set) {
    return std::hash<std::string_view>{}(std::string_view(reinterpret_cast<const char*>(set.data()), set.size()));
  };
  std::vector<std::size_t> seen;
  std::vector<double> g(n, 0.0);
  // The primal-dual active-set step from the current forces and displacements: keep the pairs that
  // press, add the pairs that penetrate; violations (length units: a pulling force over the pair's
  // stiffness, or a penetration) above `tolerance` change.
  std::vector<std::uint8_t> next;
  int changes = 0;
  std::size_t worst_pair = n;
  double worst_violation = 0.0;
  const auto step = [&](double tolerance) {
    next = active;
    changes = 0;
    worst_pair = n;
    worst_violation = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (rows_.empty(i)) continue;
      g[i] = rows_.value(i, u);
      const double violation = active[i] ? -force[i] / rows_.stiffness(i) : -g[i];
      if (violation > tolerance) {
        next[i] = active[i] ? 0 : 1;
        ++changes;
        if (violation > worst_violation) {
          worst_violation = violation;
          worst_pair = i;
        }
      }
    }
  };
  // Only the set that settles needs its answer to round-off. After each multiplier step of the
  // others, the forces and gaps are within about the step's residual: a pair that violates the set
  // by a thousand times that changes it whatever the remaining digits, so the set's remaining
  // iterations would be wasted (each one a solve). The set that settles is iterated to round-off as
  // before: no pair violates it.
  bool early = false, stopped_early = false;
  const ConstraintRows::Decided decided = [&](double residual) {
    const double noise = std::max(residual, ConstraintRows::round_off * ConstraintRows::scale(length, u));
    step(10.0 * noise);
    early = worst_violation > 1.0e3 * noise;
    stopped_early = stopped_early || early;
    return early;
  };
  for (int iteration = 1;; ++iteration) {
    seen.push_back(key_of(active));
    // A factorization, or a rank-k update of the last one for a small change (ConstraintRows::hold).
    if (rows_.hold(cholesky, values, active)) ++report.factorizations;
    report.active_set_iterations = iteration;
    early = false;
    double worst = rows_.multipliers(rhs, active, force, u, length, report.multiplier_iterations, {}, decided);
    const double scale = ConstraintRows::scale(length, u);
    if (!early && worst > accepted_residual * scale) {
      std::ostringstream text;
      text << "the exact contact solve could not enforce contact to round-off (residual " << worst / scale
           << " of the model's length scale after " << ConstraintRows::max_multiplier_iterations << " multiplier iterations)";
      throw SolverError(text.str());
    }
    // Noise level of the gap functions: what the multiplier iterations could not remove.
    step(std::max(10.0 * worst, ConstraintRows::round_off * scale));
    if (changes == 0 && stopped_early && worst > 0.1 * ConstraintRows::round_off * scale) {
      // Settled from the less accurate forces of an early stop, its residual just under round-off:
      // one more step takes it as far below as a set iterated throughout ends (the report's problem
      // 1: gap closures 100 % within 6e-11 % instead of 1.07e-9 %), and the set is checked again.
      worst = rows_.multipliers(rhs, active, force, u, length, report.multiplier_iterations);
      step(std::max(10.0 * worst, ConstraintRows::round_off * ConstraintRows::scale(length, u)));
    }
    if (changes == 0) {
      rows_.refine_equilibrium(values, rhs, active, force, u);
      state.active = active;
      state.force = force;
      report.complementarity = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        if (rows_.empty(i)) continue;
        const double r = std::abs(std::min(force[i] / rows_.stiffness(i), g[i]));
        report.complementarity = std::max(report.complementarity, r / scale);
        report.pairs_in_contact += active[i];
      }
      return report;
    }
    if (iteration >= max_active_set_iterations) {
      std::ostringstream text;
      text << "the exact contact solve did not settle after " << max_active_set_iterations
           << " active-set iterations: " << plural(changes, "pair") << (changes == 1 ? " still changes" : " still change")
           << ", the worst between nodes "
           << model_.nodes[pairs_.pairs[worst_pair].node[0]].id << " and "
           << model_.nodes[pairs_.pairs[worst_pair].node[1]].id;
      throw SolverError(text.str());
    }
    // A set seen before would cycle: change only the worst pair, which always makes progress.
    if (std::find(seen.begin(), seen.end(), key_of(next)) != seen.end()) {
      next = active;
      next[worst_pair] = active[worst_pair] ? 0 : 1;
    }
    active = std::move(next);
    for (std::size_t i = 0; i < n; ++i) {
      if (!active[i]) force[i] = 0.0;
    }
  }
}

void ExactContact::add_nodal_forces(const ContactState& state, std::span<double> forces) const {
  const std::vector<ContactPair>& pairs = pairs_.pairs;
  if (state.force.size() != pairs.size()) return;  // nothing solved yet
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& pair = pairs[i];
    for (std::size_t k = 0; k < pair.node.size(); ++k) {
      const auto node = static_cast<std::size_t>(pair.node[k]);
      const Vec2 c = pair.coefficient(k);
      forces[2 * node] += state.force[i] * c[0];
      forces[2 * node + 1] += state.force[i] * c[1];
    }
  }
}

}  // namespace saasgaps
