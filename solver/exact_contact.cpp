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
    : model_(model), dofs_(dofs), pattern_(pattern), pairs_(std::move(pairs)) {
  rows_.resize(pairs_.pairs.size());
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    const ContactPair& p = pairs_.pairs[i];
    Row& row = rows_[i];
    row.g0 = p.g0;
    row.first = entries_.size();
    for (std::size_t k = 0; k < p.node.size(); ++k) {
      for (int dir = 0; dir < 2; ++dir) {
        // cos(90 degrees) is 6e-17, not 0: such a component is no coupling (and would give a pair
        // whose only free unknown is across the normal a vanishing penalty).
        const double coefficient = p.weight[k] * p.normal[dir];
        if (std::abs(coefficient) <= 1.0e-12 * std::abs(p.weight[k])) continue;
        const Index eq = dofs.equation(p.node[k], dir);
        if (eq >= 0) {
          entries_.push_back({eq, coefficient});
        } else {
          row.g0 += coefficient * dofs.prescribed(p.node[k], dir);
        }
      }
    }
    row.last = entries_.size();
    row.first_product = positions_.size();
    const std::span<const Entry> e = entries(row);
    for (std::size_t a = 0; a < e.size(); ++a) {
      for (std::size_t b = a; b < e.size(); ++b) {
        const Index position = pattern.find(e[a].equation, e[b].equation);
        assert(position >= 0 && "a pair's nodes belong to one gap element, or the pattern's extra couplings hold them");
        positions_.push_back(position);
        products_.push_back(e[a].coefficient * e[b].coefficient);
      }
    }
    row.last_product = positions_.size();
  }
  diagonal_.resize(static_cast<std::size_t>(pattern.n));
  for (Index j = 0; j < pattern.n; ++j) diagonal_[j] = pattern.find(j, j);
  b_.resize(static_cast<std::size_t>(pattern.n));
}

double ExactContact::residual(const Row& row, std::span<const double> u) const {
  double g = row.g0;
  for (const Entry& e : entries(row)) g += e.coefficient * u[e.equation];
  return g;
}

void ExactContact::factor_active(SparseCholesky& cholesky, std::span<const double> values,
                                 const std::vector<std::uint8_t>& active) {
  values_.assign(values.begin(), values.end());
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (!active[i]) continue;
    const Row& row = rows_[i];
    for (std::size_t k = row.first_product; k < row.last_product; ++k) values_[positions_[k]] += row.rho * products_[k];
  }
  cholesky.factorize(values_);
}

void ExactContact::update_active(const std::vector<std::uint8_t>& held, const std::vector<std::uint8_t>& active) {
  for (const bool add : {true, false}) {
    columns_.clear();
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      if (held[i] == active[i] || static_cast<bool>(active[i]) != add) continue;
      // rho_i c_i c_i^T = w w^T with w = sqrt(rho_i) c_i.
      const Row& row = rows_[i];
      for (const Entry& e : entries(row)) columns_.add(e.equation, std::sqrt(row.rho) * e.coefficient);
      columns_.end_column();
    }
    updatable_.update(columns_, add);
  }
}

double ExactContact::multipliers(const Solver& solve, std::span<const double> rhs,
                                 const std::vector<std::uint8_t>& active, std::vector<double>& force,
                                 std::span<double> u, double length, int& iterations) {
  double previous = std::numeric_limits<double>::infinity();
  double worst = 0.0;
  int stalled = 0;
  for (int m = 0; m < max_multiplier_iterations; ++m) {
    // K_A u = f + C_A^T (lambda - rho g0): the penalty's pull toward g = 0 plus the forces so far.
    std::copy(rhs.begin(), rhs.end(), b_.begin());
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      if (!active[i]) continue;
      const Row& row = rows_[i];
      const double load = force[i] - row.rho * row.g0;
      for (const Entry& e : entries(row)) b_[e.equation] += e.coefficient * load;
    }
    solve(b_, u);
    ++iterations;
    // lambda <- lambda - rho g(u). With the new lambda, K u = f + C_A^T lambda holds exactly: u is in
    // equilibrium with the updated forces, and g_A is what is left to remove.
    worst = 0.0;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      if (!active[i]) continue;
      const double g = residual(rows_[i], u);
      force[i] -= rows_[i].rho * g;
      worst = std::max(worst, std::abs(g));
    }
    if (!std::isfinite(worst)) throw SolverError("the contact solve produced non-finite displacements");
    double scale = length;
    for (double x : u) scale = std::max(scale, std::abs(x));
    if (worst <= round_off * scale) break;
    // Below round-off nothing more can be gained: stop when two steps in a row fail to halve it.
    stalled = worst > 0.5 * previous ? stalled + 1 : 0;
    if (stalled >= 2) break;
    previous = worst;
  }
  return worst;
}

void ExactContact::refine_equilibrium(const Solver& solve, std::span<const double> values,
                                      std::span<const double> rhs, const std::vector<std::uint8_t>& active,
                                      std::vector<double>& force, std::span<double> u) {
  // r = f + C_A^T lambda - K u, K symmetric from its upper triangle.
  std::copy(rhs.begin(), rhs.end(), b_.begin());
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (!active[i]) continue;
    for (const Entry& e : entries(rows_[i])) b_[e.equation] += e.coefficient * force[i];
  }
  for (Index j = 0; j < pattern_.n; ++j) {
    for (Index k = pattern_.colptr[j]; k < pattern_.colptr[j + 1]; ++k) {
      const Index i = pattern_.rowind[k];
      b_[i] -= values[k] * u[j];
      if (i != j) b_[j] -= values[k] * u[i];
    }
  }
  std::vector<double> du(u.size());
  solve(b_, du);
  for (std::size_t j = 0; j < u.size(); ++j) u[j] += du[j];
  for (std::size_t i = 0; i < rows_.size(); ++i) {
    if (!active[i]) continue;
    double c_du = 0.0;
    for (const Entry& e : entries(rows_[i])) c_du += e.coefficient * du[e.equation];
    force[i] -= rows_[i].rho * c_du;
  }
}

ContactReport ExactContact::solve(SparseCholesky& cholesky, std::span<const double> values,
                                  std::span<const double> rhs, ContactState& state, std::span<double> u) {
  const std::size_t n = rows_.size();
  ContactReport report;
  // Penalties from this K's diagonal: c_i^T diag(K) c_i is the stiffness the pair's nodes have.
  for (Row& row : rows_) {
    row.stiffness = 0.0;
    for (const Entry& e : entries(row)) {
      row.stiffness += e.coefficient * e.coefficient * values[diagonal_[e.equation]];
    }
    row.rho = penalty_factor * row.stiffness;
  }
  // Warm start: the last active set. Otherwise the pairs whose initial gap is within 1 % of the
  // smallest, where contact begins: every pair of a uniform gap (fits, pressed contacts: one active
  // set), the first point of contact of a curved one (Hertz: 8 active sets where starting from every
  // pair peels the contact open three pairs at a time, 13).
  double smallest = std::numeric_limits<double>::infinity();
  for (const Row& row : rows_) {
    if (!row.empty()) smallest = std::min(smallest, row.g0);
  }
  std::vector<std::uint8_t> active(n, 0);
  if (state.active.size() == n) {
    active = state.active;
  } else {
    // Rows already closed or penetrating (an interference: g0 <= 0) start active too.
    const double start = std::max(0.0, smallest + 0.01 * std::abs(smallest));
    for (std::size_t i = 0; i < n; ++i) active[i] = rows_[i].g0 <= start;
  }
  std::vector<double> force = state.force.size() == n ? state.force : std::vector<double>(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (rows_[i].empty()) active[i] = 0;  // both nodes prescribed: nothing to enforce
    if (!active[i]) force[i] = 0.0;
  }
  double length = 0.0;
  for (const Row& row : rows_) length = std::max(length, std::abs(row.g0));

  const auto key_of = [](const std::vector<std::uint8_t>& set) {
    return std::hash<std::string_view>{}(std::string_view(reinterpret_cast<const char*>(set.data()), set.size()));
  };
  std::vector<std::size_t> seen;
  std::vector<double> g(n, 0.0);
  // The supernodal factorization holds K + rho C_F^T C_F for the set F = factored; small changes from
  // it go to a simplicial copy by rank-k updates and downdates (`held`: the copy's set).
  std::vector<std::uint8_t> factored, held;
  const Solver by_factorization = [&cholesky](std::span<const double> b, std::span<double> x) { cholesky.solve(b, x); };
  const Solver by_update = [this](std::span<const double> b, std::span<double> x) { updatable_.solve(b, x); };
  const Solver* solver = &by_factorization;
  for (int iteration = 1;; ++iteration) {
    seen.push_back(key_of(active));
    // The step's rank: pairs that change from the set the factor (or its updated copy) holds.
    const std::vector<std::uint8_t>& from = held.empty() ? factored : held;
    int distance = 0;
    for (std::size_t i = 0; i < n && !from.empty(); ++i) distance += from[i] != active[i];
    bool updated = false;
    if (!factored.empty() && distance <= max_update_rank) {
      try {
        if (held.empty()) {
          updatable_.copy(cholesky);
          held = factored;
        }
        update_active(held, active);
        held = active;
        solver = &by_update;
        updated = true;
      } catch (const NotPositiveDefinite&) {
        held.clear();  // a downdate lost definiteness to round-off: factorize afresh
      }
    }
    if (!updated) {
      factor_active(cholesky, values, active);
      ++report.factorizations;
      factored = active;
      held.clear();
      solver = &by_factorization;
    }
    report.active_set_iterations = iteration;
    const double worst = multipliers(*solver, rhs, active, force, u, length, report.multiplier_iterations);
    double scale = length;
    for (double x : u) scale = std::max(scale, std::abs(x));
    if (worst > accepted_residual * scale) {
      std::ostringstream text;
      text << "the exact contact solve could not enforce contact to round-off (residual " << worst / scale
           << " of the model's length scale after " << max_multiplier_iterations << " multiplier iterations)";
      throw SolverError(text.str());
    }
    // Noise level of the gap functions: what the multiplier iterations could not remove.
    const double tolerance = std::max(10.0 * worst, round_off * scale);
    for (std::size_t i = 0; i < n; ++i) g[i] = residual(rows_[i], u);

    // The primal-dual active-set step: keep the pairs that press, add the pairs that penetrate.
    std::vector<std::uint8_t> next = active;
    int changes = 0;
    std::size_t worst_pair = n;
    double worst_violation = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (rows_[i].empty()) continue;
      // Violations in length units: a pulling force over the pair's stiffness, or a penetration.
      const double violation = active[i] ? -force[i] / rows_[i].stiffness : -g[i];
      if (violation > tolerance) {
        next[i] = active[i] ? 0 : 1;
        ++changes;
        if (violation > worst_violation) {
          worst_violation = violation;
          worst_pair = i;
        }
      }
    }
    if (changes == 0) {
      refine_equilibrium(*solver, values, rhs, active, force, u);
      state.active = active;
      state.force = force;
      report.complementarity = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        if (rows_[i].empty()) continue;
        const double r = std::abs(std::min(force[i] / rows_[i].stiffness, g[i]));
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
      forces[2 * node] += state.force[i] * pair.weight[k] * pair.normal[0];
      forces[2 * node + 1] += state.force[i] * pair.weight[k] * pair.normal[1];
    }
  }
}

}  // namespace saasgaps
