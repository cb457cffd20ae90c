#include "solver/gaps/node_pair_method.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "solver/base/errors.hpp"
#include "solver/base/plural.hpp"

namespace saasgaps {

namespace {

ContactPairs with_extra(ContactPairs pairs, const ContactPairs* extra) {
  if (extra != nullptr) pairs.pairs.insert(pairs.pairs.end(), extra->pairs.begin(), extra->pairs.end());
  return pairs;
}

}  // namespace

NodePairMethod::NodePairMethod(const Model& model, const GapSettings& settings, const DofMap& dofs,
                               const CscPattern& pattern, const ContactPairs* extra)
    : gaps_(model, settings),
      exact_(model, dofs, pattern, with_extra(contact_pairs(model), extra)),
      node_pairs_(exact_.pairs().pairs.size() - (extra != nullptr ? extra->pairs.size() : 0)) {}

void NodePairMethod::begin_iteration(RestartState& state, StiffnessSystem& system) {
  GapElements::advance(state.gaps, gaps_.floor_moduli(), state.iteration);
  gaps_.assemble(system, state.gaps.used);
}

void NodePairMethod::solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
                           RestartState& state, std::span<double> u) {
  report_ = exact_.solve(cholesky, values, rhs, state.contact, u);
  load_norm_ = load_norm(rhs);
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
  double carried = load_norm_;
  for (double lambda : state.contact.force) carried += std::max(0.0, lambda);
  std::vector<FloorLoad> open;
  for (std::size_t g = 0; g < outcome.gaps.size(); ++g) {
    if (outcome.gaps[g].state == GapState::closed) continue;
    open.push_back({std::abs(outcome.gaps[g].sigma_m) * gaps_.face_area(g), g});
  }
  constexpr double largest_floor_share = 0.01;
  gaps_.check_floor_share(std::move(open), carried, largest_floor_share, outcome, "gaps that do not touch");
}

void NodePairMethod::add_columns(const RestartState& state, IterationRecord& row) const {
  GapElements::add_columns(state.gaps, row);
  row.contact_pairs = report_.pairs_in_contact;
  row.complementarity = report_.complementarity;
  row.active_set_iterations = report_.active_set_iterations;
}

void NodePairMethod::add_nodal_forces(const RestartState& state, std::span<double> forces) const {
  gaps_.add_nodal_forces(state.gaps, state.displacement, forces);
  exact_.add_nodal_forces(state.contact, forces);
}

std::string NodePairMethod::converged_note(const RestartState& state, const ContactOutcome&) const {
  std::ostringstream text;
  std::size_t touching = 0;
  for (std::size_t i = 0; i < node_pairs_ && i < state.contact.active.size(); ++i) touching += state.contact.active[i];
  text << " (exact contact: " << touching << " of " << plural(static_cast<long long>(node_pairs_), "node pair")
       << " in contact, complementarity residual " << state.history.back().complementarity << ")";
  return text.str();
}

}  // namespace saasgaps
