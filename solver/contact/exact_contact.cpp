#include "solver/contact/exact_contact.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <sstream>
#include <string_view>

#include "solver/base/errors.hpp"
#include "solver/base/plural.hpp"
#include "solver/lac/condensed_lcp.hpp"

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
  int first_step = 0;  // report.multiplier_iterations when the current set began
  const auto set_steps = [&] { return report.multiplier_iterations - first_step; };
  const ConstraintRows::Decided decided = [&](double residual) {
    const double noise = std::max(residual, ConstraintRows::round_off * ConstraintRows::scale(length, u));
    step(10.0 * noise);
    // A set that predict() will look ahead from takes a second step first: the first step's forces
    // are the penalty method's, within 1/penalty_factor, and the condensed problem would inherit
    // that error in every row outside its window (misjudging rows that press that little).
    early = worst_violation > 1.0e3 * noise && (set_steps() > 1 || !rows_.factorized(active));
    stopped_early = stopped_early || early;
    return early;
  };
  for (int iteration = 1;; ++iteration) {
    seen.push_back(key_of(active));
    first_step = report.multiplier_iterations;
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
    const auto was_seen = [&](const std::vector<std::uint8_t>& set) {
      return std::find(seen.begin(), seen.end(), key_of(set)) != seen.end();
    };
    if (rows_.factorized(active)) {
      const double noise = std::max(10.0 * worst, ConstraintRows::round_off * ConstraintRows::scale(length, u));
      std::vector<std::uint8_t> guess = predict(active, force, u, g, changes, noise);
      if (!guess.empty() && guess != active && !was_seen(guess)) next = std::move(guess);
    }
    // A set seen before would cycle: change only the worst pair, which always makes progress.
    if (was_seen(next)) {
      next = active;
      next[worst_pair] = active[worst_pair] ? 0 : 1;
    }
    active = std::move(next);
    for (std::size_t i = 0; i < n; ++i) {
      if (!active[i]) force[i] = 0.0;
    }
  }
}

std::vector<std::uint8_t> ExactContact::predict(const std::vector<std::uint8_t>& active, std::span<const double> force,
                                                std::span<const double> u, std::span<const double> g, int changes,
                                                double tolerance) {
  // The window: the rows that violate the set; the first rings of their neighbours whatever
  // their margins (beside a released row its load arrives at once); then grown into the
  // neighbours of smallest margin first, the rows nearest to changing, which is where the boundary
  // moves (not into rows that press hard); and if the rows have no neighbours (gap pairs of
  // unconnected parts), the rows of smallest margin.
  const std::size_t wanted = std::clamp(window_per_change * static_cast<std::size_t>(changes), min_window, max_window);
  std::vector<std::uint8_t> in_window(rows_.size(), 0);
  std::vector<std::size_t> window;
  std::vector<double> margin(rows_.size());
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (rows_.empty(i)) continue;
    margin[i] = active[i] ? force[i] / rows_.stiffness(i) : g[i];
    if (-margin[i] > tolerance && window.size() < max_window) {  // violates the set
      window.push_back(i);
      in_window[i] = 1;
    }
  }
  for (std::size_t first = 0, rings = 0; rings < whole_rings; ++rings) {
    const std::size_t last = window.size();
    for (std::size_t k = first; k < last; ++k) {
      for (const std::size_t j : rows_.neighbours(window[k])) {
        if (in_window[j] || rows_.empty(j) || window.size() >= max_window) continue;
        in_window[j] = 1;
        window.push_back(j);
      }
    }
    first = last;
  }
  const auto larger_margin = [&](std::size_t a, std::size_t b) { return margin[a] > margin[b]; };
  std::priority_queue<std::size_t, std::vector<std::size_t>, decltype(larger_margin)> candidates(larger_margin);
  const auto offer_neighbours = [&](std::size_t r) {
    for (const std::size_t j : rows_.neighbours(r)) {
      if (in_window[j] || rows_.empty(j)) continue;
      in_window[j] = 1;  // offered once
      candidates.push(j);
    }
  };
  for (std::size_t k = 0, taken = window.size(); k < taken; ++k) offer_neighbours(window[k]);
  while (window.size() < wanted && !candidates.empty()) {
    const std::size_t r = candidates.top();
    candidates.pop();
    window.push_back(r);
    offer_neighbours(r);
  }
  for (; !candidates.empty(); candidates.pop()) in_window[candidates.top()] = 0;  // offered, not taken
  if (window.size() < wanted) {
    std::vector<std::size_t> rest;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      if (!in_window[i] && !rows_.empty(i)) rest.push_back(i);
    }
    const std::size_t more = std::min(rest.size(), wanted - window.size());
    std::partial_sort(rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(more), rest.end(),
                      [&](std::size_t a, std::size_t b) { return margin[a] < margin[b]; });
    window.insert(window.end(), rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(more));
  }
  std::sort(window.begin(), window.end());
  Eigen::MatrixXd s;
  Eigen::VectorXd q;
  if (!rows_.condense(window, active, force, u, s, q)) return {};
  std::vector<std::uint8_t> start(window.size());
  std::vector<double> stiffness(window.size());
  for (std::size_t k = 0; k < window.size(); ++k) {
    start[k] = active[window[k]];
    stiffness[k] = rows_.stiffness(window[k]);
  }
  const LcpSolution lcp = solve_condensed_lcp(s, q, std::move(start), stiffness, tolerance);
  if (!lcp.settled) return {};
  std::vector<std::uint8_t> next = active;
  for (std::size_t k = 0; k < window.size(); ++k) next[window[k]] = lcp.active[k];
  return next;
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
