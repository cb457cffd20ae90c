#include "solver/gaps/gap_closure.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace saasgaps {

namespace {
constexpr double touching = -1.0;  // eps_M when the two faces of a gap meet
}

GapClosure::GapClosure(const GapSettings& settings) : settings_(settings) {
  assert(!settings_.tensile_schedule.empty());
}

double GapClosure::invariance_target(double closure) { return closure > 2.0 ? 0.90 : 0.99; }

GapModuli GapClosure::initial() const {
  GapModuli m;
  m.normal.assign(settings_.elements.size(), settings_.initial_modulus);
  m.tensile = settings_.initial_modulus;
  m.schedule_step = -1;
  return m;
}

GapModuli GapClosure::next(const GapHistory& after) const {
  const auto& schedule = settings_.tensile_schedule;
  GapModuli m;
  m.schedule_step = std::min(after.used.schedule_step + 1, static_cast<int>(schedule.size()) - 1);
  m.tensile = schedule[m.schedule_step];

  // (d) The tensile gaps are about to relax by this much; compressed gaps take the same increment
  // so that they do not swing while the tension side lets go.
  const double tensile_drop = std::max(0.0, after.used.tensile - m.tensile);

  m.normal.resize(after.strain.size());
  for (std::size_t g = 0; g < after.strain.size(); ++g) {
    const double eps = after.strain[g];
    if (eps < 0.0) {
      // (b) Compressed gap, stress invariance: sigma_M = E_K eps_K is kept while the strain is sent
      // to contact, E_K+1 = E_K closure_K / target (Eq. 1).
      const double closure = -eps;
      const double invariant = after.used.normal[g] * closure / invariance_target(closure);
      // A compressed gap is never made softer than an open one.
      m.normal[g] = std::max(invariant, floor_modulus()) + tensile_drop;
    } else {
      // (b) Gap in tension: the user's schedule of decreasing moduli.
      m.normal[g] = m.tensile;
    }
  }

  // Fig. 19: once only compression controls convergence, blend in the modulus extrapolated to
  // contact, E = (1 - f) E_K+1 + f E_X, for the gaps still overclosed.
  const double f = settings_.extrapolation_factor;
  if (f > 0.0 && extrapolation_allowed(after)) {
    for (std::size_t g = 0; g < after.strain.size(); ++g) {
      if (!(after.strain[g] < touching)) continue;
      const double E_x = extrapolated_modulus(after.previous_normal[g], after.previous_strain[g],
                                              after.used.normal[g], after.strain[g]);
      if (E_x <= 0.0) continue;
      m.normal[g] = (1.0 - f) * m.normal[g] + f * E_x;
      m.extrapolated = true;
    }
  }
  return m;
}

bool GapClosure::extrapolation_allowed(const GapHistory& after) const {
  if (!after.has_previous()) return false;
  // Qualification (1): the tensile moduli are at the schedule's smallest value in both iterations
  // of the line fit, so only the compressed gaps move the strains.
  if (after.used.tensile > floor_modulus() || after.previous_tensile > floor_modulus()) return false;
  // Qualification (2): every overclosed gap is moving toward contact; otherwise extrapolating
  // could be "extremely disturbing to the convergence process".
  for (std::size_t g = 0; g < after.strain.size(); ++g) {
    if (after.strain[g] < touching && !(after.strain[g] > after.previous_strain[g])) return false;
  }
  return true;
}

double GapClosure::extrapolated_modulus(double E_previous, double eps_previous, double E_current,
                                        double eps_current) {
  const double d_eps = eps_current - eps_previous;
  const double d_E = E_current - E_previous;
  if (d_eps == 0.0 || d_E == 0.0 || !(eps_previous < 0.0)) return 0.0;
  const double E_x = E_current + (touching - eps_current) * d_E / d_eps;
  return std::isfinite(E_x) ? E_x : 0.0;
}

GapVerdict GapClosure::test(const GapHistory& after) const {
  const double tolerance = settings_.closure_tolerance;
  const std::size_t n = after.strain.size();
  GapVerdict v;
  v.converged.assign(n, false);
  v.failure.assign(n, GapFailure::none);
  double closed_sum = 0.0;
  for (std::size_t g = 0; g < n; ++g) {
    const double eps = after.strain[g];
    const double closure = -100.0 * eps;
    v.max_closure = g == 0 ? closure : std::max(v.max_closure, closure);
    if (closure > 100.0) {
      ++v.closed;
      closed_sum += closure;
    }
    // (e) No gap overclosed beyond the tolerance ...
    const bool not_overclosed = eps > touching - tolerance;
    // ... every gap in tension relaxed to the schedule's smallest modulus ...
    const bool relaxed = eps < 0.0 || after.used.normal[g] <= floor_modulus();
    // ... and the gap has settled: its strain moved by less than the tolerance since the last
    // iteration. (Decoded: Tables I and II stop exactly at the first iteration that passes this;
    // Table III's "-" for iteration 1 is this test having nothing to compare with.)
    const bool settled = after.has_previous() && std::abs(eps - after.previous_strain[g]) <= tolerance;
    // Strict: a gap that does not touch must carry no load, i.e. sit at the floor modulus.
    const bool unloaded = settings_.convergence_test != GapConvergenceTest::strict || eps >= 0.0 ||
                          eps <= touching + tolerance || after.used.normal[g] <= floor_modulus();
    GapFailure& why = v.failure[g];
    if (!not_overclosed) why = GapFailure::overclosed;
    else if (!relaxed) why = GapFailure::not_relaxed;
    else if (!after.has_previous()) why = GapFailure::first_iteration;
    else if (!settled) why = GapFailure::not_settled;
    else if (!unloaded) why = GapFailure::loaded_open;
    v.converged[g] = why == GapFailure::none;
    if (!v.converged[g]) ++v.nonconverged;
  }
  v.average_closure = v.closed > 0 ? closed_sum / v.closed : 0.0;
  return v;
}

Constitutive GapClosure::law(std::size_t g, const GapModuli& moduli, AnalysisType analysis) const {
  // (c) Poisson ratios zero, E_N = E_theta = the current tensile modulus, no thermal expansion; the
  // shear modulus follows E_N down so that open gaps cannot carry load in shear either.
  ElasticConstants c;
  c.E1 = moduli.normal[g];
  c.E2 = moduli.tensile;
  c.E3 = moduli.tensile;
  c.G12 = settings_.shear_ratio * moduli.tensile;
  return constitutive(c, analysis, settings_.elements[g].angle_deg);
}

}  // namespace saasgaps
