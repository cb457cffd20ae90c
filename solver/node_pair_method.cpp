#include "node_pair_method.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "errors.hpp"

namespace saasgaps {

NodePairMethod::NodePairMethod(const Model& model, const GapSettings& settings, const DofMap& dofs,
                               const CscPattern& pattern)
    : model_(model), gaps_(model, settings), exact_(model, dofs, pattern, contact_pairs(model)) {}

void NodePairMethod::begin_iteration(RestartState& state, StiffnessSystem& system) {
  GapElements::advance(state.gaps, gaps_.floor_moduli(), state.iteration);
  gaps_.assemble(system, state.gaps.used);
}

void NodePairMethod::solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
                           RestartState& state, std::span<double> u) {
  report_ = exact_.solve(cholesky, values, rhs, state.contact, u);
  load_norm_ = 0.0;
  for (double f : rhs) load_norm_ += std::abs(f);
}

void NodePairMethod::evaluate(RestartState& state, ContactOutcome& outcome) const {
  gaps_.measure(state.gaps, state.displacement, outcome);
  measure_pair_contact(exact_.pairs(), state.contact, state.displacement, outcome);
  gaps_.keep_strains(outcome, state.gaps);
  touching_verdict(outcome);
}

void measure_pair_contact(const ContactPairs& cp, const ContactState& contact, std::span<const double> displacement,
                          ContactOutcome& outcome) {
  const bool solved = contact.force.size() == cp.pairs.size();
  for (std::size_t g = 0; g < outcome.gaps.size(); ++g) {
    double area = 0.0, force = 0.0, closed = 0.0, initial = 0.0;
    bool touching = false;
    for (int k = 0; k < cp.share_count[g]; ++k) {
      const PairShare& share = cp.of_gap[g][k];
      const ContactPair& pair = cp.pairs[share.pair];
      area += share.area;
      initial += share.area * pair.g0;
      closed += share.area * (pair.g0 - gap_function(pair, displacement));
      if (!solved) continue;
      force += share.area * contact.force[share.pair] / pair.area;
      touching = touching || contact.active[share.pair];
    }
    GapResult& r = outcome.gaps[g];
    r.eps_m = -closed / initial;
    r.closure = -100.0 * r.eps_m;
    r.sigma_m -= force / area;
    r.state = touching ? GapState::closed : GapState::open;
  }
}

void touching_verdict(ContactOutcome& outcome) {
  outcome.nonconverged = 0;
  outcome.closed = 0;
  outcome.max_closure = 0.0;
  double closed_sum = 0.0;
  for (std::size_t g = 0; g < outcome.gaps.size(); ++g) {
    GapResult& r = outcome.gaps[g];
    r.converged = true;
    r.failure = GapFailure::none;
    outcome.max_closure = g == 0 ? r.closure : std::max(outcome.max_closure, r.closure);
    if (r.state == GapState::closed) {
      ++outcome.closed;
      closed_sum += r.closure;
    }
  }
  outcome.average_closure = outcome.closed > 0 ? closed_sum / outcome.closed : 0.0;
}

void NodePairMethod::check_solved(const RestartState& state, const ContactOutcome& outcome) const {
  const ContactPairs& cp = exact_.pairs();
  constexpr double largest_floor_share = 0.01;
  double carried = load_norm_;
  for (double lambda : state.contact.force) carried += std::max(0.0, lambda);
  std::vector<std::pair<double, std::size_t>> open;  // floor force, gap
  double open_force = 0.0;
  for (std::size_t g = 0; g < outcome.gaps.size(); ++g) {
    if (outcome.gaps[g].state == GapState::closed) continue;
    double area = 0.0;
    for (int k = 0; k < cp.share_count[g]; ++k) area += cp.of_gap[g][k].area;
    const double force = std::abs(outcome.gaps[g].sigma_m) * area;
    open_force += force;
    open.emplace_back(force, g);
  }
  if (!(open_force > largest_floor_share * carried)) return;
  std::sort(open.begin(), open.end(), std::greater<>());
  std::ostringstream text;
  text << "the contact problem has no solution: " << 100.0 * open_force / carried
       << " % of the load is carried by the floor stiffness of gaps that do not touch (";
  const std::size_t shown = std::min<std::size_t>(open.size(), 6);
  for (std::size_t k = 0; k < shown; ++k) {
    const GapElement& gap = gaps_.settings().elements[open[k].second];
    text << (k ? "; " : "") << "gap " << gap.id << " at nodes";
    for (int a = 0; a < gap.node_count; ++a) text << ' ' << model_.nodes[gap.nodes[a]].id;
  }
  if (open.size() > shown) text << "; and " << open.size() - shown << " more";
  text << "): a body is pushed away from every support, or the floor modulus " << gaps_.closure().floor_modulus()
       << " (the last tensile_schedule value) is not negligible";
  throw SolverError(text.str());
}

void NodePairMethod::add_columns(const RestartState& state, IterationRecord& row) const {
  GapElements::add_columns(state.gaps, row);
  row.contact_pairs = report_.pairs_in_contact;
  row.complementarity = report_.complementarity;
  row.active_set_iterations = report_.active_set_iterations;
}

std::string NodePairMethod::converged_note(const RestartState& state, const ContactOutcome&) const {
  std::ostringstream text;
  text << " (exact contact: " << state.history.back().contact_pairs << " of " << exact_.pairs().pairs.size()
       << " node pairs in contact, complementarity residual " << state.history.back().complementarity << ")";
  return text.str();
}

}  // namespace saasgaps
