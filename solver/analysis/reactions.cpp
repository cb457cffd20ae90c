#include "solver/analysis/reactions.hpp"

#include <cassert>

#include "solver/assembly/element_data.hpp"
#include "solver/fe/element_kernel.hpp"

namespace saasgaps {

std::vector<NodeReaction> support_reactions(const Model& model, const DofMap& dofs, const LawOf& solid_law,
                                            std::span<const double> displacement,
                                            std::span<const double> contact_forces) {
  return support_reactions(model, dofs, at_every_point(solid_law), displacement, contact_forces);
}

std::vector<NodeReaction> support_reactions(const Model& model, const DofMap& dofs, const PointLawsOf& solid_laws,
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
  const auto touches = [&constrained](std::span<const int> nodes) {
    for (const int a : nodes) {
      if (constrained[static_cast<std::size_t>(a)]) return true;
    }
    return false;
  };

  std::array<Constitutive, max_material_points> scratch;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = model.elements[e];
    if (!touches(el.node_span())) continue;
    const ElementMatrices m = element_matrices(solid_element_data(model, e, solid_laws(e, scratch)));
    const ElementVector u = element_displacements(displacement, el.node_span());
    const ElementVector internal = internal_forces(m, u);
    for (int a = 0; a < el.node_count; ++a) {
      const auto node = static_cast<std::size_t>(el.nodes[static_cast<std::size_t>(a)]);
      residual[2 * node] += internal[2 * a];
      residual[2 * node + 1] += internal[2 * a + 1];
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

std::vector<SetReaction> set_reactions(const Model& model, std::span<const NodeReaction> reactions) {
  std::vector<SetReaction> sums;
  if (model.reaction_groups.empty()) return sums;
  // The reactions are in node order: a node's entry is found by its id's position among them.
  std::vector<int> entry(model.nodes.size(), -1);
  std::size_t k = 0;
  for (std::size_t a = 0; a < model.nodes.size() && k < reactions.size(); ++a) {
    if (model.nodes[a].id == reactions[k].id) entry[a] = static_cast<int>(k++);
  }
  sums.reserve(model.reaction_groups.size());
  for (const ReactionGroup& group : model.reaction_groups) {
    SetReaction sum{group.name, 0.0, 0.0};
    for (const int node : group.nodes) {
      const int e = entry[static_cast<std::size_t>(node)];
      if (e < 0) continue;  // free in this increment: no support, no reaction
      sum.f_r += reactions[static_cast<std::size_t>(e)].f_r;
      sum.f_z += reactions[static_cast<std::size_t>(e)].f_z;
    }
    sums.push_back(std::move(sum));
  }
  return sums;
}

}  // namespace saasgaps
