#include "solver/gaps/gap_elements.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "solver/assembly/element_data.hpp"
#include "solver/assembly/stiffness_system.hpp"
#include "solver/base/errors.hpp"
#include "solver/gaps/gap_faces.hpp"

namespace saasgaps {

GapElements::GapElements(const Model& model, const GapSettings& settings)
    : model_(model), settings_(settings), closure_(settings_) {
  face_area_.reserve(settings_.elements.size());
  for (const GapElement& gap : settings_.elements) face_area_.push_back(gap_face_area(model_, gap));
}

double load_norm(std::span<const double> rhs) {
  double sum = 0.0;
  for (double f : rhs) sum += std::abs(f);
  return sum;
}

void GapElements::check_floor_share(std::vector<FloorLoad> floor, double carried, double largest_share,
                                    const ContactOutcome& outcome, std::string_view which) const {
  double floor_force = 0.0;
  for (const FloorLoad& f : floor) floor_force += f.force;
  if (!(floor_force > largest_share * carried)) return;
  std::sort(floor.begin(), floor.end(), [](const FloorLoad& a, const FloorLoad& b) { return a.force > b.force; });
  std::ostringstream text;
  text << "the contact problem has no solution: " << 100.0 * floor_force / carried
       << " % of the load is carried by the floor stiffness of " << which << " (";
  const std::size_t shown = std::min<std::size_t>(floor.size(), 6);
  for (std::size_t k = 0; k < shown; ++k) {
    const GapElement& gap = settings_.elements[floor[k].gap];
    text << (k ? "; " : "") << "gap " << gap.id << " at nodes";
    for (int a = 0; a < gap.node_count; ++a) text << ' ' << model_.nodes[gap.nodes[a]].id;
    text << ", closure " << outcome.gaps[floor[k].gap].closure << " %";
  }
  if (floor.size() > shown) text << "; and " << floor.size() - shown << " more";
  text << "): a body is pushed away from every support, or the floor modulus " << closure_.floor_modulus()
       << " (the last tensile_schedule value) is not negligible";
  throw SolverError(text.str());
}

GapModuli GapElements::floor_moduli() const {
  GapModuli m;
  m.tensile = closure_.floor_modulus();
  m.normal.assign(settings_.elements.size(), m.tensile);
  m.schedule_step = static_cast<int>(settings_.tensile_schedule.size()) - 1;
  return m;
}

void GapElements::advance(GapHistory& history, GapModuli next, int finished_iterations) {
  if (finished_iterations > 0) {
    history.previous_normal = std::move(history.used.normal);
    history.previous_strain = std::move(history.strain);
    history.previous_tensile = history.used.tensile;
  }
  // The strains of K+1 are measured after its solve (keep_strains).
  history.strain.clear();
  history.used = std::move(next);
}

void GapElements::assemble(StiffnessSystem& system, const GapModuli& moduli) const {
  system.assemble_gaps([&](std::size_t g) { return closure_.law(g, moduli, model_.analysis); });
}

void GapElements::measure(const GapHistory& history, std::span<const double> displacement,
                          ContactOutcome& outcome) const {
  const auto& elements = settings_.elements;
  outcome.gaps.resize(elements.size());
  for (std::size_t g = 0; g < elements.size(); ++g) {
    const GapElement& gap = elements[g];
    const ElementData data = gap_element_data(model_, g, closure_.law(g, history.used, model_.analysis));
    const ElementState es = element_state(data, values(element_displacements(displacement, gap.node_span())));
    GapResult& r = outcome.gaps[g];
    r.id = gap.id;
    r.eps_m = normal_component(es.strain, gap.angle_deg, 1.0);
    r.closure = -100.0 * r.eps_m;
    r.modulus = history.used.normal[g];
    r.sigma_m = normal_component(es.stress, gap.angle_deg, 2.0);
  }
}

void GapElements::add_nodal_forces(const GapHistory& history, std::span<const double> displacement,
                                   std::span<double> forces) const {
  const auto& elements = settings_.elements;
  for (std::size_t g = 0; g < elements.size(); ++g) {
    const GapElement& gap = elements[g];
    const ElementMatrices m =
        element_matrices(gap_element_data(model_, g, closure_.law(g, history.used, model_.analysis)));
    const ElementVector internal = internal_forces(m, element_displacements(displacement, gap.node_span()));
    for (int a = 0; a < gap.node_count; ++a) {
      forces[2 * static_cast<std::size_t>(gap.nodes[a])] -= internal[2 * a];
      forces[2 * static_cast<std::size_t>(gap.nodes[a]) + 1] -= internal[2 * a + 1];
    }
  }
}

void GapElements::keep_strains(const ContactOutcome& outcome, GapHistory& history) const {
  const std::size_t n = outcome.gaps.size();
  if (history.strain.empty()) {
    history.strain.resize(n);  // O(gaps), not O(elements)
    for (std::size_t g = 0; g < n; ++g) history.strain[g] = outcome.gaps[g].eps_m;
    return;
  }
  for (std::size_t g = 0; g < n; ++g) {
    const double here = outcome.gaps[g].eps_m, saved = history.strain[g];
    if (std::abs(here - saved) > 1e-9 * (1.0 + std::abs(saved))) {
      throw SolverError("the restart state does not belong to this model: gap " +
                        std::to_string(settings_.elements[g].id) + " has strain " + std::to_string(here) +
                        " here and " + std::to_string(saved) + " in the state");
    }
  }
}

void GapElements::add_columns(const GapHistory& history, IterationRecord& row) {
  row.tensile_modulus = history.used.tensile;
  row.extrapolated = history.used.extrapolated;
}

}  // namespace saasgaps
