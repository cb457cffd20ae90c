#include "solver/analysis/reactions.hpp"

#include <cassert>

#include "solver/assembly/element_data.hpp"
#include "solver/fe/element_kernel.hpp"

namespace saasgaps {

std::vector<NodeReaction> support_reactions(const Model& model, const DofMap& dofs, const LawOf& solid_law,
                                            std::span<const double> displacement,
                                            std::span<const double> contact_forces) {
  const std::size_t n = model.nodes.size();
  assert(displacement.size() == 2 * n);
  assert(contact_forces.empty() || contact_forces.size() == 2 * n);
  std::vector<bool> constrained(n, false);
  for (std::size_t a = 0; a < n; ++a) {
    const int node = static_cast<int>(a);
    constrained[a] = dofs.equation(node, 0) < 0 || dofs.equation(node, 1) < 0;
  }
  std::vector<double> residual(2 * n, 0.0);  // written at constrained nodes only
  const auto touches = [&constrained](const std::array<int, 4>& nodes, int count) {
    for (int a = 0; a < count; ++a) {
      if (constrained[nodes[a]]) return true;
    }
    return false;
  };

  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = model.elements[e];
    if (!touches(el.nodes, el.node_count)) continue;
    const ElementMatrices m = element_matrices(solid_element_data(model, e, solid_law(e)));
    // The kernel fills the upper triangle (the assembler reads no more): K_e u_e from it alone.
    const Vec8 u = element_displacements(displacement, el.nodes, el.node_count);
    const Mat8 K = m.K.selfadjointView<Eigen::Upper>();
    const Vec8 internal = K * u - m.f;
    for (int a = 0; a < el.node_count; ++a) {
      residual[2 * el.nodes[a]] += internal[2 * a];
      residual[2 * el.nodes[a] + 1] += internal[2 * a + 1];
    }
  }
  for_each_external_load(model, [&](int node, const Vec2& force) {
    if (!constrained[node]) return;
    residual[2 * node] -= force[0];
    residual[2 * node + 1] -= force[1];
  });

  std::vector<NodeReaction> reactions;
  for (std::size_t a = 0; a < n; ++a) {
    if (!constrained[a]) continue;
    const int node = static_cast<int>(a);
    NodeReaction r{model.nodes[a].id, 0.0, 0.0};
    if (dofs.equation(node, 0) < 0) r.f_r = residual[2 * a] - (contact_forces.empty() ? 0.0 : contact_forces[2 * a]);
    if (dofs.equation(node, 1) < 0) {
      r.f_z = residual[2 * a + 1] - (contact_forces.empty() ? 0.0 : contact_forces[2 * a + 1]);
    }
    reactions.push_back(r);
  }
  return reactions;
}

Vec2 reaction_sum(std::span<const NodeReaction> reactions) {
  Vec2 sum = Vec2::Zero();
  for (const NodeReaction& r : reactions) sum += Vec2(r.f_r, r.f_z);
  return sum;
}

}  // namespace saasgaps
