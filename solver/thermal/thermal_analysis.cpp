#include "solver/thermal/thermal_analysis.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "solver/lac/sparse_cholesky.hpp"
#include "solver/recovery/flux_recovery.hpp"
#include "solver/thermal/contact_conductance.hpp"
#include "solver/thermal/thermal_system.hpp"
#include "solver/thermal/transient_coupling.hpp"

namespace saasgaps {

namespace {

/// The recovered heat flux and its error estimate (solver/recovery/flux_recovery.hpp) of the
/// result's temperatures, with the conductivities the last solve used.
void estimate_flux_error(const Model& model, std::span<const Conductivity> k, ThermalResult& result) {
  const auto started = std::chrono::steady_clock::now();
  std::vector<Eigen::Matrix2d> tensors;
  tensors.reserve(k.size());
  for (const Conductivity& c : k) tensors.push_back(c.tensor());
  FluxRecovery r = recover_heat_flux(model, result.T, tensors);
  result.recovered_flux = std::move(r.flux);
  result.heat_error = std::move(r.element_error);
  result.heat_error_estimate = r.estimate;
  result.recovery_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

double largest_magnitude(std::span<const double> T) {
  double m = 0.0;
  for (double t : T) m = std::max(m, std::abs(t));
  return m;
}

double largest_change(std::span<const double> a, std::span<const double> b) {
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

bool same_conductivities(std::span<const Conductivity> a, std::span<const Conductivity> b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Conductivity& x, const Conductivity& y) {
    return x.k1 == y.k1 && x.k2 == y.k2 && x.angle_deg == y.angle_deg;
  });
}

/// One conduction system with its factorization: assemble, factorize when the matrix changed, solve.
class ConductionSolver {
 public:
  explicit ConductionSolver(const Model& model)
      : system_(model),
        // AMD, not METIS: on a scalar node graph its ordering costs a tenth of METIS's and the
        // factorization it gives, once or a few times a run, stays far cheaper than METIS's saving
        // (docs/performance.md, heat conduction).
        cholesky_(system_.pattern(), {}, nullptr, FillOrdering::minimum_degree),
        values_(static_cast<std::size_t>(system_.pattern().nnz())),
        rhs_(static_cast<std::size_t>(system_.dofs().size())),
        x_(rhs_.size()) {}

  [[nodiscard]] const ThermalSystem& system() const { return system_; }
  [[nodiscard]] int factorizations() const { return factorizations_; }
  [[nodiscard]] int rhs_only_solves() const { return rhs_only_solves_; }

  /// current: where radiating edges are linearized (ThermalSystem::assemble).
  std::vector<double> solve(std::span<const Conductivity> k, double inverse_dt, std::span<const double> previous,
                            std::span<const double> gap_conductance, std::span<const double> contact_conductance,
                            std::span<const double> current) {
    // The matrix is a function of k, the capacity rates (c at T_n, dt), the conductances and, with
    // radiation, of `current`: while the first three are those of the last assembly and nothing
    // radiates, only the rhs is assembled (the same bits, a fraction of the work).
    std::vector<double> rates = system_.capacity_rates(inverse_dt, previous);
    const bool same_matrix = !system_.radiates() && !loads_.empty() && same_conductivities(k, k_) && rates == rates_ &&
                             std::ranges::equal(gap_conductance, gaps_) &&
                             std::ranges::equal(contact_conductance, pairs_);
    if (same_matrix) {
      system_.assemble_rhs(k, inverse_dt, previous, gap_conductance, contact_conductance, loads_, rhs_);
      ++rhs_only_solves_;
      cholesky_.solve(rhs_, x_);
      return system_.node_temperatures(x_);
    }
    system_.assemble(k, inverse_dt, previous, gap_conductance, contact_conductance, current, values_, rhs_,
                     system_.radiates() ? nullptr : &loads_);
    k_.assign(k.begin(), k.end());
    rates_ = std::move(rates);
    gaps_.assign(gap_conductance.begin(), gap_conductance.end());
    pairs_.assign(contact_conductance.begin(), contact_conductance.end());
    if (values_ != factored_) {
      try {
        cholesky_.factorize(values_);
      } catch (const NotPositiveDefinite& e) {
        throw singular(e);
      }
      factored_ = values_;
      ++factorizations_;
    }
    cholesky_.solve(rhs_, x_);
    return system_.node_temperatures(x_);
  }

 private:
  [[nodiscard]] SingularModelError singular(const NotPositiveDefinite& e) const {
    std::vector<NodeDof> where;
    for (Index column : e.columns()) where.push_back(system_.dofs().node_dof(column));
    std::ostringstream text;
    text << "the conduction matrix is singular: no temperature or film holds the temperature of the body at";
    const std::size_t shown = std::min<std::size_t>(where.size(), 12);
    for (std::size_t i = 0; i < shown; ++i) text << (i ? ", node " : " node ") << where[i].node_id;
    if (where.size() > shown) text << " and " << where.size() - shown << " more";
    return SingularModelError(text.str(), std::move(where));
  }

  ThermalSystem system_;
  SparseCholesky cholesky_;
  std::vector<double> values_;
  std::vector<double> factored_;  // the values of the current factorization
  // The inputs of the last assembled matrix, and its elements' load parts (none with radiation).
  std::vector<Conductivity> k_;
  std::vector<double> rates_;
  std::vector<double> gaps_;
  std::vector<double> pairs_;
  ConductionLoads loads_;
  std::vector<double> rhs_;
  std::vector<double> x_;
  int factorizations_ = 0;
  int rhs_only_solves_ = 0;
};

/// A row of `kind` at position `index` with the extremes of T filled in.
ThermalRecord temperature_row(ThermalRowKind kind, int index, std::span<const double> T) {
  ThermalRecord row;
  row.kind = kind;
  row.index = index;
  if (!T.empty()) {
    const auto [lowest, highest] = std::minmax_element(T.begin(), T.end());
    row.min_T = *lowest;
    row.max_T = *highest;
  }
  return row;
}

/// The row of a steady pass: its conduction solve and its change from the previous pass's T.
void report_steady(IterationObserver* observer, const ThermalResult& heat, int pass, double pass_change) {
  if (!observer) return;
  ThermalRecord row = temperature_row(ThermalRowKind::steady, pass, heat.T);
  row.pass = pass;
  row.iterations = heat.iterations;
  row.max_change = heat.last_change;
  row.pass_change = pass_change;
  observer->on_thermal(row);
}

bool touching(GapState s) { return s == GapState::closed || s == GapState::overclosed; }

}  // namespace

std::vector<double> gap_conductances(const Model& model, std::span<const GapResult> gaps) {
  if (!model.gaps || !model.gaps->conductance || model.gaps->elements.empty()) return {};
  const InterfaceConductance& c = *model.gaps->conductance;
  std::vector<double> H(model.gaps->elements.size());
  for (std::size_t g = 0; g < H.size(); ++g) {
    const double w = gap_width(model, model.gaps->elements[g]);
    if (!gaps.empty() && touching(gaps[g].state)) {
      H[g] = closed_conductance(c, std::max(0.0, -gaps[g].sigma_m));  // sigma_m < 0 is compression
      continue;
    }
    // Open: gas across the current opening; faces closer than 10^-6 of the width count as touching.
    const double opening = w * (1.0 + (gaps.empty() ? 0.0 : gaps[g].eps_m));
    H[g] = opening > 1.0e-6 * w ? c.gas_conductivity / opening : closed_conductance(c, 0.0);
  }
  return H;
}

ThermalResult solve_steady_conduction(const Model& model, std::span<const double> gap_conductance,
                                      std::span<const double> contact_conductance) {
  ConductionSolver solver(model);
  const ThermalSystem& system = solver.system();
  const std::vector<double> initial_contact =
      contact_conductance.empty() ? system.contact().conductances({}) : std::vector<double>{};
  if (contact_conductance.empty()) contact_conductance = initial_contact;
  std::vector<double> T(model.nodes.size(), model.reference_temperature);
  std::vector<Conductivity> k = system.conductivities(T);
  ThermalResult result;
  double change = 0.0;
  for (int pass = 1; pass <= max_conduction_iterations; ++pass) {
    std::vector<double> next = solver.solve(k, 0.0, {}, gap_conductance, contact_conductance, T);
    change = largest_change(next, T);
    T = std::move(next);
    std::vector<Conductivity> k_next = system.conductivities(T);
    // Radiation is linearized at T: only a change below the tolerance ends its iteration.
    const bool settled = (same_conductivities(k_next, k) && !system.radiates()) ||
                         change <= steady_tolerance * (1.0 + largest_magnitude(T));
    if (settled) {
      result.iterations = pass;
      result.last_change = change;
      result.factorizations = solver.factorizations();
      result.rhs_only_solves = solver.rhs_only_solves();
      result.flux = system.fluxes(k_next, T);
      result.T = std::move(T);
      estimate_flux_error(model, k_next, result);
      return result;
    }
    k = std::move(k_next);
  }
  std::ostringstream text;
  text << "the steady conduction did not converge in " << max_conduction_iterations
       << " passes of the k(T) and radiation iteration: the last changed a node temperature by " << change
       << " (a conductivity that varies too steeply with T)";
  throw SolverError(text.str());
}

ThermalResult solve_transient_conduction(const Model& model, std::span<const double> gap_conductance,
                                         std::span<const double> contact_conductance, const OutputTimeHook& at_output,
                                         IterationObserver* observer) {
  const Thermal& thermal = *model.thermal;
  ConductionSolver solver(model);
  const ThermalSystem& system = solver.system();
  InterfaceConductances H{{gap_conductance.begin(), gap_conductance.end()},
                          {contact_conductance.begin(), contact_conductance.end()}};
  if (H.pairs.empty()) H.pairs = system.contact().conductances({});
  std::vector<double> T(model.nodes.size(), thermal.initial_temperature);
  ThermalResult result;
  // Times count whole steps from the last output time (no drift from summing dt), so every full
  // step has exactly the length time_step and reuses the factorization.
  const double step = thermal.time_step;
  const double sliver = 1.0e-9 * step;
  double t = 0.0;
  for (std::size_t k = 0; k < thermal.output_times.size(); ++k) {
    const double output = thermal.output_times[k];
    const double start = t;
    double step_change = 0.0;  // the largest single-step change of this interval, for its row
    for (long taken = 1; output - t > sliver; ++taken) {
      const double remaining = output - t;
      const double dt = std::abs(remaining - step) <= sliver ? step : std::min(step, remaining);
      // Radiating edges: Newton on the step's nonlinear system from the previous temperatures.
      std::vector<double> guess = T;
      for (int pass = 1;; ++pass) {
        std::vector<double> next = solver.solve(system.conductivities(T), 1.0 / dt, T, H.gaps, H.pairs, guess);
        const double change = largest_change(next, guess);
        guess = std::move(next);
        if (!system.radiates() || change <= steady_tolerance * (1.0 + largest_magnitude(guess))) break;
        if (pass == max_conduction_iterations) {
          throw SolverError("the radiation did not converge in a time step ending at t = " + std::to_string(t + dt) +
                            ": the last of " + std::to_string(pass) + " Newton passes changed a node temperature by " +
                            std::to_string(change));
        }
      }
      if (observer) step_change = std::max(step_change, largest_change(guess, T));
      T = std::move(guess);
      t = remaining - dt <= sliver ? output : start + static_cast<double>(taken) * step;
      ++result.time_steps;
    }
    t = output;
    result.times.push_back(output);
    result.history.push_back(T);
    if (observer) {
      ThermalRecord row = temperature_row(ThermalRowKind::transient, static_cast<int>(result.times.size()), T);
      row.time = output;
      row.time_steps = result.time_steps;
      row.max_change = step_change;
      observer->on_thermal(row);
    }
    if (!at_output) continue;
    std::optional<InterfaceConductances> next = at_output(k, T);
    if (!next) break;
    H = std::move(*next);
  }
  result.factorizations = solver.factorizations();
  result.rhs_only_solves = solver.rhs_only_solves();
  const std::vector<Conductivity> k_last = system.conductivities(T);
  result.flux = system.fluxes(k_last, T);
  result.T = std::move(T);
  estimate_flux_error(model, k_last, result);
  return result;
}

Model with_temperatures(const Model& model, const std::vector<double>& T) {
  Model m = model;
  m.loads.node_temperature = T;
  for (Step& step : m.steps) {
    if (step.loads) step.loads->node_temperature = T;
  }
  return m;
}

Model with_temperature_steps(const Model& model, const ThermalResult& transient) {
  Model m = model;
  m.steps.clear();
  for (std::size_t k = 0; k < transient.times.size(); ++k) {
    std::ostringstream name;
    name << "t = " << transient.times[k];
    Step step;
    step.name = name.str();
    step.loads = model.loads;
    step.loads->node_temperature = transient.history[k];
    m.steps.push_back(std::move(step));
  }
  return m;
}

Solution solve_with_heat(const Model& model, IterationObserver* observer, const RestartState* resume,
                         const ResumeOptions& options, const OrderingCache* cache, const ContactMethodFactory& contact) {
  if (!model.thermal) return solve(model, observer, resume, options, cache, contact);
  std::vector<double> H = gap_conductances(model, {});
  const ContactConductance pairs(model);
  if (model.thermal->type == ThermalType::transient) {
    if (!H.empty() || pairs.row_count() > 0) return solve_coupled_transient(model, observer, resume, options, cache, contact);
    ThermalResult heat = solve_transient_conduction(model, {}, {}, {}, observer);
    Solution s = solve(with_temperature_steps(model, heat), observer, resume, options, cache, contact);
    s.thermal = std::move(heat);
    return s;
  }
  ThermalResult heat = solve_steady_conduction(model, H, pairs.conductances({}));
  report_steady(observer, heat, 1, 0.0);
  Solution s = solve(with_temperatures(model, heat.T), observer, resume, options, cache, contact);
  if (H.empty() && pairs.row_count() == 0) {
    s.thermal = std::move(heat);
    return s;
  }
  // Conducting gaps or pairs: alternate conduction and stress until states and temperatures settle.
  const auto states = [&pairs](const Solution& solution) {
    std::vector<bool> touch = pairs.touching(solution.contact);
    for (const GapResult& g : solution.gaps) touch.push_back(touching(g.state));
    return touch;
  };
  for (int pass = 2; pass <= max_coupling_passes; ++pass) {
    const std::vector<bool> before = states(s);
    ThermalResult next =
        solve_steady_conduction(model, gap_conductances(model, s.gaps), pairs.conductances(s.contact));
    const double change = largest_change(next.T, heat.T);
    heat = std::move(next);
    heat.passes = pass;
    report_steady(observer, heat, pass, change);
    s = solve(with_temperatures(model, heat.T), observer, nullptr, options, cache, contact);
    if (states(s) == before && change <= coupling_tolerance * (1.0 + largest_magnitude(heat.T))) {
      s.thermal = std::move(heat);
      return s;
    }
  }
  throw SolverError("the thermal and contact solutions did not settle in " + std::to_string(max_coupling_passes) +
                    " passes (contact states or temperatures kept changing)");
}

}  // namespace saasgaps
