#include "solver/contact/frictional_contact.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string_view>

#include "solver/base/errors.hpp"
#include "solver/base/plural.hpp"

namespace saasgaps {

void finish_increment(FrictionState& state) {
  for (std::size_t i = 0; i < state.size(); ++i) {
    if (state.state[i] == static_cast<std::uint8_t>(SlipState::slip)) {
      state.slip[i] += std::abs(state.position[i] - state.previous[i]);
    }
    state.previous[i] = state.position[i];
  }
}

FrictionalContact::FrictionalContact(const Model& model, const DofMap& dofs, const CscPattern& pattern,
                                     ContactPairs pairs, std::vector<double> friction)
    : model_(model), pairs_(std::move(pairs)), mu_(std::move(friction)), rows_(dofs, pattern) {
  assert(mu_.size() == pairs_.pairs.size());
  assert(std::all_of(mu_.begin(), mu_.end(), [](double mu) { return mu >= 0.0; }) && "the reader refuses mu < 0");
  for (const ContactPair& p : pairs_.pairs) {
    // The gap row by its gradient (a mortar row on a curved side bends with its normal field); the
    // tangential row by its weights along the point's tangent.
    std::vector<Vec2> coefficients(p.node.size());
    for (std::size_t k = 0; k < p.node.size(); ++k) coefficients[k] = p.coefficient(k);
    rows_.add(p.node, coefficients, p.g0);
    rows_.add(p.node, p.weight, tangent(p), 0.0);
  }
}

void FrictionalContact::add_nodal_forces(const FrictionState& state, std::span<double> forces) const {
  const std::vector<ContactPair>& pairs = pairs_.pairs;
  if (state.normal_force.size() != pairs.size() || state.tangential_force.size() != pairs.size()) return;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const ContactPair& pair = pairs[i];
    const Vec2 t = tangent(pair);
    for (std::size_t k = 0; k < pair.node.size(); ++k) {
      const auto node = static_cast<std::size_t>(pair.node[k]);
      const Vec2 f = state.normal_force[i] * pair.coefficient(k) + state.tangential_force[i] * pair.weight[k] * t;
      forces[2 * node] += f[0];
      forces[2 * node + 1] += f[1];
    }
  }
}

namespace {

constexpr auto open = static_cast<std::uint8_t>(SlipState::open);
constexpr auto stick = static_cast<std::uint8_t>(SlipState::stick);
constexpr auto slip = static_cast<std::uint8_t>(SlipState::slip);

/// One byte per point: its state, and for a slipping point its direction.
std::size_t key_of(const std::vector<std::uint8_t>& state, const std::vector<std::int8_t>& direction) {
  std::string bytes(state.size(), '\0');
  for (std::size_t i = 0; i < state.size(); ++i) bytes[i] = static_cast<char>(state[i] + 4 * (direction[i] + 1));
  return std::hash<std::string_view>{}(bytes);
}

}  // namespace

FrictionReport FrictionalContact::solve(SparseCholesky& cholesky, std::span<const double> values,
                                        std::span<const double> rhs, FrictionState& state, std::span<double> u) {
  const std::size_t n = pairs_.pairs.size();
  FrictionReport report;
  rows_.set_penalties(values);
  if (state.previous.size() != n) state.previous.assign(n, 0.0);
  if (state.slip.size() != n) state.slip.assign(n, 0.0);
  // Stick holds the tangential position where the last increment left it: h_i(u) = h_i^prev.
  for (std::size_t i = 0; i < n; ++i) {
    rows_.set_g0(tangential_row(i), rows_.prescribed_g0(tangential_row(i)) - state.previous[i]);
  }
  const auto usable = [&](std::size_t i) { return !rows_.empty(normal_row(i)); };

  // Warm start: the last solve's states and forces. Otherwise where contact begins (contact_start,
  // as ExactContact), sticking unless mu = 0.
  std::vector<std::uint8_t> points(n, open);
  std::vector<std::int8_t> direction(n, 0);
  std::vector<double> force(2 * n, 0.0);
  const bool warm = state.state.size() == n && state.normal_force.size() == n &&
                    state.tangential_force.size() == n && state.direction.size() == n;
  if (warm) {
    points = state.state;
    direction = state.direction;
    for (std::size_t i = 0; i < n; ++i) {
      force[normal_row(i)] = state.normal_force[i];
      force[tangential_row(i)] = state.tangential_force[i];
    }
  } else {
    std::vector<double> g0;
    for (std::size_t i = 0; i < n; ++i) {
      if (usable(i)) g0.push_back(rows_.g0(normal_row(i)));
    }
    const double start = contact_start(g0);
    for (std::size_t i = 0; i < n; ++i) {
      if (rows_.g0(normal_row(i)) <= start) points[i] = mu_[i] > 0.0 ? stick : slip;
      direction[i] = points[i] == slip ? 1 : 0;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!usable(i)) points[i] = open;  // every unknown prescribed: nothing to enforce
    if (points[i] == open) force[normal_row(i)] = force[tangential_row(i)] = 0.0;
  }
  double length = 0.0;
  for (std::size_t i = 0; i < n; ++i) length = std::max(length, std::abs(rows_.g0(normal_row(i))));

  // The slip forces -mu lambda_n s c_t follow the normal multipliers in every multiplier iteration.
  const ConstraintRows::DependentLoad slip_forces = [&](std::span<const double> lambda, std::span<double> b) {
    double moved = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (points[i] != slip) continue;
      const std::size_t t = tangential_row(i);
      const double load = -mu_[i] * lambda[normal_row(i)] * direction[i];
      if (load == 0.0 && force[t] == 0.0) continue;
      moved = std::max(moved, std::abs(load - force[t]) / rows_.stiffness(t));
      force[t] = load;
      rows_.add_load(t, load, b);
    }
    return moved;
  };

  std::vector<std::size_t> seen;
  std::vector<std::uint8_t> active(2 * n, 0);
  std::vector<double> g(n, 0.0), v(n, 0.0);
  // The primal-dual active-set step on open / stick / slip for the current u and forces, violations
  // in length units beyond `tolerance`: into next, next_direction, changes and the worst point.
  std::vector<std::uint8_t> next;
  std::vector<std::int8_t> next_direction;
  int changes = 0;
  std::size_t worst_point = n;
  double worst_violation = 0.0;
  const auto step = [&](double tolerance) {
    for (std::size_t i = 0; i < n; ++i) {
      g[i] = rows_.value(normal_row(i), u);
      v[i] = rows_.value(tangential_row(i), u);
    }
    next = points;
    next_direction = direction;
    changes = 0;
    worst_point = n;
    worst_violation = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!usable(i)) continue;
      const double k_n = rows_.stiffness(normal_row(i));
      const double k_t = rows_.stiffness(tangential_row(i));
      const double lambda_n = force[normal_row(i)];
      const double lambda_t = force[tangential_row(i)];
      double violation = 0.0;
      std::uint8_t to = points[i];
      std::int8_t to_direction = direction[i];
      if (points[i] == open) {
        violation = -g[i];  // penetration
        // Coulomb's law on the trial forces k_n (-g) and -k_t v of the penetration and the slip it
        // made while open: slip along v where those lie beyond the cone (a point that would pull
        // when sticking and penetrate when open, the end of a surface sliding on, settles there).
        if (mu_[i] > 0.0 && k_t * std::abs(v[i]) > mu_[i] * k_n * -g[i]) {
          to = slip;
          to_direction = v[i] > 0.0 ? 1 : -1;
        } else {
          to = mu_[i] > 0.0 ? stick : slip;
          to_direction = to == slip ? 1 : 0;
        }
      } else if (-lambda_n / k_n > tolerance) {
        violation = -lambda_n / k_n;  // pulling
        to = open;
        to_direction = 0;
      } else if (points[i] == stick) {
        violation = (std::abs(lambda_t) - mu_[i] * lambda_n) / k_t;  // beyond the friction cone
        to = slip;
        to_direction = lambda_t > 0.0 ? -1 : 1;
      } else if (mu_[i] > 0.0) {
        violation = -direction[i] * v[i];  // slipping against its friction force
        to = stick;
        to_direction = 0;
      }
      if (violation > tolerance) {
        next[i] = to;
        next_direction[i] = to_direction;
        ++changes;
        if (violation > worst_violation) {
          worst_violation = violation;
          worst_point = i;
        }
      }
    }
  };
  // A set that will change whatever the last digits: a point violates it by a hundred times the
  // error of this iterate. Its remaining iterations would be wasted: on to the next set. The error
  // (length): the equality rows' residual and how far the slip loads will move with the normal
  // forces just updated. Not the multipliers' residual, which also counts the slip loads' last
  // move: at a point that has just started to slip that is its jump from the sticking force, a
  // change this solve has taken in whole (counted, it would cost every set a second solve).
  bool early = false;
  const ConstraintRows::Decided decided = [&](double) {
    double scale = length;
    for (double x : u) scale = std::max(scale, std::abs(x));
    double residual = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (points[i] == open || !usable(i)) continue;
      const std::size_t t = tangential_row(i);
      residual = std::max(residual, std::abs(rows_.value(normal_row(i), u)));
      if (points[i] == stick) residual = std::max(residual, std::abs(rows_.value(t, u)));
      if (points[i] == slip) {
        const double load = -mu_[i] * force[normal_row(i)] * direction[i];
        residual = std::max(residual, std::abs(load - force[t]) / rows_.stiffness(t));
      }
    }
    step(std::max(10.0 * residual, ConstraintRows::round_off * scale));
    early = worst_violation > 1.0e2 * std::max(residual, ConstraintRows::round_off * scale);
    return early;
  };
  // A warm start's first set is held from the set where every touching point sticks (base): its
  // factor is kept from one solve to the next while K and the touching points stay the same, so an
  // increment that only moves the stick-slip boundary factorizes nothing (a downdate by the
  // slipping points' rows instead). The base is a function of the state alone, so that a resumed
  // run holds the same factor as the uninterrupted one.
  std::vector<std::uint8_t> base;
  if (warm) {
    base.assign(2 * n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      base[normal_row(i)] = points[i] != open;
      base[tangential_row(i)] = points[i] != open && mu_[i] > 0.0;
    }
  }
  for (int iteration = 1;; ++iteration) {
    seen.push_back(key_of(points, direction));
    int slipping = 0;
    for (std::size_t i = 0; i < n; ++i) {
      active[normal_row(i)] = points[i] != open;
      active[tangential_row(i)] = points[i] == stick;
      slipping += points[i] == slip && mu_[i] > 0.0;
    }
    try {
      const bool factorized =
          iteration == 1 && warm ? rows_.hold_from(cholesky, values, base, active) : rows_.hold(cholesky, values, active);
      report.factorizations += factorized ? 1 : 0;
    } catch (const NotPositiveDefinite&) {
      if (slipping == 0) throw;
      std::ostringstream text;
      text << "the frictional contact increment has no solution: with " << plural(slipping, "contact point")
           << " slipping, nothing holds a body along the contact surface (the tangential load exceeds what "
              "friction can carry, mu times the normal force, so the body slides away)";
      throw SolverError(text.str());
    }
    report.active_set_iterations = iteration;
    early = false;
    const double worst =
        rows_.multipliers(rhs, active, force, u, length, report.multiplier_iterations, slip_forces, decided);
    double scale = length;
    for (double x : u) scale = std::max(scale, std::abs(x));
    if (!early && worst > accepted_residual * scale) {
      std::ostringstream text;
      text << "the frictional contact solve could not enforce contact and friction to round-off (residual "
           << worst / scale << " of the model's length scale after " << ConstraintRows::max_multiplier_iterations
           << " multiplier iterations; with " << plural(slipping, "point")
           << " slipping, mu times the coupling of normal and tangential compliance may exceed 1)";
      throw SolverError(text.str());
    }
    // Noise level of the rows: what the multiplier iterations could not remove. (Stopped early, the
    // set's change is the one `decided` found.)
    if (!early) step(std::max(10.0 * worst, ConstraintRows::round_off * scale));
    if (changes == 0) {
      // K u = f + C^T lambda to the round-off of K, the slip forces as given loads.
      std::vector<std::uint8_t> slip_rows(2 * n, 0);
      for (std::size_t i = 0; i < n; ++i) slip_rows[tangential_row(i)] = points[i] == slip;
      rows_.refine_equilibrium(values, rhs, active, force, u, slip_rows);
      for (std::size_t i = 0; i < n; ++i) {
        g[i] = rows_.value(normal_row(i), u);
        v[i] = rows_.value(tangential_row(i), u);
      }
      state.state = points;
      state.direction = direction;
      state.normal_force.resize(n);
      state.tangential_force.resize(n);
      state.position.resize(n);
      for (std::size_t i = 0; i < n; ++i) {
        state.normal_force[i] = force[normal_row(i)];
        state.tangential_force[i] = force[tangential_row(i)];
        state.position[i] = v[i] + state.previous[i];
        if (!usable(i)) continue;
        const double k_n = rows_.stiffness(normal_row(i));
        const double k_t = rows_.stiffness(tangential_row(i));
        const double lambda_n = force[normal_row(i)];
        const double lambda_t = force[tangential_row(i)];
        report.complementarity = std::max(report.complementarity, std::abs(std::min(lambda_n / k_n, g[i])) / scale);
        double law = 0.0;
        if (points[i] == stick) {
          law = std::max(std::abs(v[i]), (std::abs(lambda_t) - mu_[i] * lambda_n) / k_t);
          ++report.sticking;
        } else if (points[i] == slip) {
          law = std::max(std::abs(lambda_t + mu_[i] * lambda_n * direction[i]) / k_t, -direction[i] * v[i]);
          ++report.slipping;
        }
        report.friction_residual = std::max(report.friction_residual, law / scale);
      }
      report.in_contact = report.sticking + report.slipping;
      return report;
    }
    if (iteration >= max_active_set_iterations) {
      std::ostringstream text;
      text << "the frictional contact solve did not settle after " << max_active_set_iterations
           << " active-set iterations: " << plural(changes, "point") << (changes == 1 ? " still changes" : " still change")
           << " between open, stick and slip, the worst between nodes "
           << model_.nodes[pairs_.pairs[worst_point].node[0]].id << " and "
           << model_.nodes[pairs_.pairs[worst_point].node[1]].id;
      throw SolverError(text.str());
    }
    // A set seen before would cycle: change only the worst point, which always makes progress.
    if (std::find(seen.begin(), seen.end(), key_of(next, next_direction)) != seen.end()) {
      const std::uint8_t to = next[worst_point];
      const std::int8_t to_direction = next_direction[worst_point];
      next = points;
      next_direction = direction;
      next[worst_point] = to;
      next_direction[worst_point] = to_direction;
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (next[i] == open) force[normal_row(i)] = force[tangential_row(i)] = 0.0;
    }
    points = std::move(next);
    direction = std::move(next_direction);
  }
}

}  // namespace saasgaps
