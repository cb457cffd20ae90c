#include "solver/mortar/mortar_method.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "solver/base/errors.hpp"
#include "solver/base/plural.hpp"
#include "solver/mortar/surface_geometry.hpp"

namespace saasgaps {

SurfaceContact surface_contact(const Model& model) {
  SurfaceContact out;
  if (!model.contact) return out;
  for (const SurfaceDefinition& s : model.contact->surfaces) out.surfaces.push_back(contact_surface(model, s.edges));
  // Each surface's geometry once, however many pairs it is in (and none for a surface in no pair).
  std::vector<std::optional<SurfaceGeometry>> geometry(out.surfaces.size());
  const auto geometry_of = [&](int surface) -> const SurfaceGeometry& {
    std::optional<SurfaceGeometry>& g = geometry[static_cast<std::size_t>(surface)];
    if (!g) g.emplace(model.nodes, out.surfaces[static_cast<std::size_t>(surface)]);
    return *g;
  };
  const SurfaceMeasure measure{model.analysis, model.thickness};
  for (const SurfacePair& pair : model.contact->pairs) {
    MortarRows rows = mortar_rows(measure, geometry_of(pair.surfaces[0]), geometry_of(pair.surfaces[1]));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      // Divided by D_j: a gap in length units whose multiplier is a force (mortar_method.hpp).
      ContactPair p;
      const double D = rows.weight[r];
      for (std::size_t e = rows.start[r]; e < rows.start[r + 1]; ++e) {
        p.node.push_back(rows.node[e]);
        p.weight.push_back(rows.mortar[e] / D);
        p.gradient.push_back(rows.coefficient[e] / D);
      }
      p.normal = rows.normal[r];
      p.g0 = rows.g0[r] / D;
      p.area = D;
      out.pairs.pairs.push_back(std::move(p));
    }
    out.rows.push_back(std::move(rows));
    out.first.push_back(out.pairs.pairs.size());
  }
  return out;
}

Cliques contact_couplings(const SurfaceContact& surfaces, const DofMap& dofs) {
  Cliques cliques;
  std::vector<Index> equations;
  for (const ContactPair& p : surfaces.pairs.pairs) {
    equations.clear();
    for (const int node : p.node) {
      for (int dir = 0; dir < 2; ++dir) equations.push_back(dofs.equation(node, dir));
    }
    cliques.add(equations);  // prescribed components (-1) are skipped by the Assembler
  }
  return cliques;
}

std::vector<ContactPairResult> contact_pair_results(const Model& model, const SurfaceContact& surfaces,
                                                    std::size_t offset, const ContactState& contact,
                                                    std::span<const double> displacement,
                                                    const FrictionState* friction) {
  std::vector<ContactPairResult> out;
  const bool solved = contact.force.size() == offset + surfaces.pairs.pairs.size();
  for (std::size_t k = 0; k < surfaces.pair_count(); ++k) {
    const SurfacePair& pair = model.contact->pairs[k];
    ContactPairResult result;
    for (int side = 0; side < 2; ++side) {
      result.surfaces[static_cast<std::size_t>(side)] =
          model.contact->surfaces[static_cast<std::size_t>(pair.surfaces[static_cast<std::size_t>(side)])].name;
    }
    // Side A's nodes: the resultant sums what the rows put on them (ContactPairResult::force).
    const ContactSurface& side_a = surfaces.surfaces[static_cast<std::size_t>(pair.surfaces[0])];
    std::vector<int> on_a(side_a.nodes.begin(), side_a.nodes.end());
    std::sort(on_a.begin(), on_a.end());
    const bool with_friction = friction != nullptr && friction->size() == offset + surfaces.pairs.pairs.size() &&
                               friction->tangential_force.size() == friction->size();
    for (std::size_t i = surfaces.first[k]; i < surfaces.first[k + 1]; ++i) {
      const ContactPair& row = surfaces.pairs.pairs[i];
      if (solved) {
        // The normal and (with friction) the tangential row, as FrictionalContact::add_nodal_forces
        // puts them on the nodes.
        const Vec2 t = FrictionalContact::tangent(row);
        for (std::size_t e = 0; e < row.node.size(); ++e) {
          if (!std::binary_search(on_a.begin(), on_a.end(), row.node[e])) continue;
          result.force += contact.force[offset + i] * row.coefficient(e);
          if (with_friction) result.force += friction->tangential_force[offset + i] * row.weight[e] * t;
        }
      }
      const Node& node = model.nodes[static_cast<std::size_t>(row.node[0])];
      ContactPointResult point;
      point.r = node.r;
      point.z = node.z;
      point.gap = displacement.empty() ? row.g0 : gap_function(row, displacement);
      const bool touching = solved && contact.active[offset + i];
      point.pressure = touching ? std::max(0.0, contact.force[offset + i]) / row.area : 0.0;
      point.state = touching ? ContactPointState::stick : ContactPointState::open;
      if (friction != nullptr && friction->size() == offset + surfaces.pairs.pairs.size()) {
        const std::size_t f = offset + i;
        // A frictionless pair's touching points stay "stick" (the result format's word for touching).
        if (pair.friction > 0.0) point.state = static_cast<ContactPointState>(friction->state[f]);
        // lambda_t is side A's force on side B along t: B's traction on A is its opposite.
        if (touching) point.shear = -friction->tangential_force[f] / row.area;
        // The finished increments' slip, and the current one's when it slips.
        point.slip = friction->slip[f];
        if (friction->state[f] == static_cast<std::uint8_t>(SlipState::slip)) {
          point.slip += std::abs(friction->position[f] - friction->previous[f]);
        }
      }
      result.points.push_back(point);
    }
    out.push_back(std::move(result));
  }
  return out;
}

MortarMethod::MortarMethod(const ContactSetup& setup, const SurfaceContact& surfaces,
                           std::unique_ptr<ContactMethod> gaps, bool rows_solved_by_gaps)
    : model_(setup.model), surfaces_(surfaces), gaps_(std::move(gaps)) {
  // mu per row: its pair's friction.
  std::vector<double> mu(surfaces.pairs.pairs.size(), 0.0);
  bool frictional = false;
  for (std::size_t k = 0; k < surfaces.pair_count(); ++k) {
    const double friction = setup.model.contact->pairs[k].friction;
    frictional = frictional || friction > 0.0;
    std::fill(mu.begin() + static_cast<std::ptrdiff_t>(surfaces.first[k]),
              mu.begin() + static_cast<std::ptrdiff_t>(surfaces.first[k + 1]), friction);
  }
  if (frictional && rows_solved_by_gaps) {
    // The reader refuses this combination (/contact/pairs/<k>/friction); a direct caller gets it here.
    throw SolverError("friction on contact surfaces needs gaps.method \"classic\" (or no gap elements): the exact "
                      "gap mode solves the surfaces' rows frictionless");
  }
  if (rows_solved_by_gaps) return;
  if (frictional) {
    friction_.emplace(setup.model, setup.dofs, setup.pattern, surfaces.pairs, std::move(mu));
  } else {
    exact_.emplace(setup.model, setup.dofs, setup.pattern, surfaces.pairs);
  }
}

void MortarMethod::begin_iteration(RestartState& state, StiffnessSystem& system) {
  if (gaps_) gaps_->begin_iteration(state, system);
  // The first iteration of an increment after the first: the last one's converged state is the
  // slip history this one starts from. (A resumed run passes here exactly where the uninterrupted
  // one did: a state is saved after a solve, never between finish and the next solve.)
  if (friction_ && state.position && state.position->iterations == 0) finish_increment(state.friction);
}

void MortarMethod::solve(SparseCholesky& cholesky, std::span<const double> values, std::span<const double> rhs,
                         RestartState& state, std::span<double> u) {
  if (friction_) {
    try {
      friction_report_ = friction_->solve(cholesky, values, rhs, state.friction, u);
    } catch (const SolverError& e) {
      // Which increment failed, so that it can be resumed with smaller increments.
      if (!state.position) throw;
      const StepPosition& p = *state.position;
      const Step& step = model_.steps[static_cast<std::size_t>(p.step)];
      std::ostringstream text;
      text << "step " << p.step + 1 << " \"" << step.name << "\", increment " << p.increment << " of "
           << step.increments << ": " << e.what();
      throw SolverError(text.str());
    }
    return;
  }
  if (!exact_) {
    gaps_->solve(cholesky, values, rhs, state, u);
    return;
  }
  report_ = exact_->solve(cholesky, values, rhs, state.contact, u);
}

ContactState MortarMethod::rows_state(const RestartState& state) const {
  if (!friction_) return state.contact;
  ContactState rows;
  const FrictionState& f = state.friction;
  if (f.size() != surfaces_.pairs.pairs.size() || f.normal_force.size() != f.size()) return rows;  // nothing solved
  rows.force = f.normal_force;
  rows.active.resize(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) rows.active[i] = f.state[i] != static_cast<std::uint8_t>(SlipState::open);
  return rows;
}

void MortarMethod::evaluate(RestartState& state, ContactOutcome& outcome) const {
  if (gaps_) {
    gaps_->evaluate(state, outcome);
  } else {
    outcome = ContactOutcome{};
  }
}

void MortarMethod::check_solved(const RestartState& state, const ContactOutcome& outcome) const {
  if (gaps_) gaps_->check_solved(state, outcome);
}

void MortarMethod::add_columns(const RestartState& state, IterationRecord& row) const {
  if (gaps_) gaps_->add_columns(state, row);
  if (friction_) {
    const FrictionReport& r = friction_report_;
    row.contact_pairs = r.in_contact;
    row.complementarity = r.complementarity;
    row.active_set_iterations = r.active_set_iterations;
    row.stick_points = r.sticking;
    row.slip_points = r.slipping;
    row.friction_residual = r.friction_residual;
    return;
  }
  if (!exact_) return;
  row.contact_pairs = report_.pairs_in_contact;
  row.complementarity = report_.complementarity;
  row.active_set_iterations = report_.active_set_iterations;
}

void MortarMethod::add_nodal_forces(const RestartState& state, std::span<double> forces) const {
  if (gaps_) gaps_->add_nodal_forces(state, forces);
  if (exact_) exact_->add_nodal_forces(state.contact, forces);
  if (friction_) friction_->add_nodal_forces(state.friction, forces);
}

std::string MortarMethod::converged_note(const RestartState& state, const ContactOutcome& outcome) const {
  std::ostringstream text;
  if (gaps_) text << gaps_->converged_note(state, outcome);
  // The rows come last in state.contact (after the exact gaps' node pairs, when those solve them).
  const std::size_t rows = surfaces_.pairs.pairs.size();
  const ContactState contact = rows_state(state);
  const std::size_t offset = contact.active.size() >= rows ? contact.active.size() - rows : 0;
  std::size_t touching = 0;
  for (std::size_t i = offset; i < contact.active.size(); ++i) touching += contact.active[i];
  text << " (contact surfaces: " << touching << " of " << plural(static_cast<long long>(rows), "point")
       << " in contact";
  if (friction_ && !state.history.empty()) {
    const IterationRecord& last = state.history.back();
    text << ", " << last.stick_points << " sticking, " << last.slip_points << " slipping";
  }
  if ((exact_ || friction_) && !state.history.empty()) {
    text << ", complementarity residual " << state.history.back().complementarity;
  }
  if (friction_ && !state.history.empty()) text << ", friction residual " << state.history.back().friction_residual;
  text << ")";
  // A pair without rows can never touch: most likely the wrong surfaces, or surfaces facing away.
  for (std::size_t k = 0; k < surfaces_.pair_count(); ++k) {
    if (surfaces_.first[k] != surfaces_.first[k + 1]) continue;
    const auto& pair = model_.contact->pairs[k].surfaces;
    text << "; warning: the surfaces of contact pair " << k + 1 << " (\""
         << model_.contact->surfaces[static_cast<std::size_t>(pair[0])].name << "\", \""
         << model_.contact->surfaces[static_cast<std::size_t>(pair[1])].name
         << "\") never face each other (no node of the first faces the second), so they cannot touch";
  }
  return text.str();
}

std::vector<ContactPairResult> MortarMethod::surface_results(const RestartState& state) const {
  // The rows come after the exact gaps' node pairs when those solve them.
  const std::size_t rows = surfaces_.pairs.pairs.size();
  const ContactState contact = rows_state(state);
  const std::size_t offset = contact.force.size() >= rows ? contact.force.size() - rows : 0;
  return contact_pair_results(model_, surfaces_, offset, contact, state.displacement,
                              friction_ ? &state.friction : nullptr);
}

}  // namespace saasgaps
