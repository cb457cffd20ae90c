#include "solver/assembly/stiffness_system.hpp"

#include <algorithm>
#include <cassert>

#include "solver/assembly/element_data.hpp"
#include "solver/fe/edge_loads.hpp"
#include "solver/fe/element_kernel.hpp"

namespace saasgaps {

namespace {

/// The corner nodes of clique s: solid elements first, then gap elements.
std::span<const int> clique_nodes(const Model& model, std::size_t s) {
  const std::size_t solids = model.elements.size();
  if (s < solids) return {model.elements[s].nodes.data(), static_cast<std::size_t>(model.elements[s].node_count)};
  const GapElement& gap = model.gaps->elements[s - solids];
  return {gap.nodes.data(), static_cast<std::size_t>(gap.node_count)};
}

}  // namespace

StiffnessSystem::StiffnessSystem(const Model& model, const DofMap& dofs, const Cliques& couplings)
    : model_(model),
      dofs_(dofs),
      assembler_(dofs, model.elements.size() + model.gap_count(),
                 [&model](std::size_t s) { return clique_nodes(model, s); }, couplings) {
  for (std::size_t s = model.elements.size(); s < model.elements.size() + model.gap_count(); ++s) {
    for (Index position : assembler_.positions(s)) {
      if (position >= 0) gap_positions_.push_back(position);
    }
  }
  std::sort(gap_positions_.begin(), gap_positions_.end());
  gap_positions_.erase(std::unique(gap_positions_.begin(), gap_positions_.end()), gap_positions_.end());
  solid_at_gap_positions_.resize(gap_positions_.size());

  // values_ is sized by the first assemble_solids(): one touch of its pages, not a zero fill here
  // and another there.
  rhs_.assign(static_cast<std::size_t>(dofs.size()), 0.0);
  solid_rhs_.assign(rhs_.size(), 0.0);
  assemble_external_loads();
}

void for_each_external_load(const Model& model, const std::function<void(int node, const Vec2& force)>& add) {
  for (const NodalForce& f : model.loads.nodal_forces) add(f.node, Vec2(f.f_r, f.f_z));
  for (const EdgePressure& p : model.loads.pressures) {
    const Element& el = model.elements[static_cast<std::size_t>(p.element)];
    const ElementFamily& family_of_el = family(el.type);
    const auto x = node_coordinates(model, el.node_span());
    const int corners = family_of_el.corner_count;
    Vec2 centroid = Vec2::Zero();
    for (int a = 0; a < corners; ++a) centroid += x[static_cast<std::size_t>(a)] / corners;
    if (family_of_el.quadratic()) {
      // The edge's own curve: its normal and length element along it (fe/edge_loads.hpp).
      const ElementEdge edge = element_edge(model, static_cast<std::size_t>(p.element), p.node_a, p.node_b);
      std::array<Vec2, max_edge_nodes> points;
      for (int k = 0; k < edge.count; ++k) {
        const auto n = static_cast<std::size_t>(edge.node[static_cast<std::size_t>(k)]);
        points[static_cast<std::size_t>(k)] = Vec2(model.nodes[n].r, model.nodes[n].z);
      }
      const Vec2 chord = points[static_cast<std::size_t>(edge.count - 1)] - points[0];
      const Vec2 left(-chord.y(), chord.x());
      const double inward = left.dot(centroid - points[static_cast<std::size_t>(edge.count / 2)]) < 0.0 ? -1.0 : 1.0;
      const auto loads =
          edge_pressure_loads(points, edge.count, p.normal, p.shear, inward, model.analysis, model.thickness);
      for (int k = 0; k < edge.count; ++k) add(edge.node[static_cast<std::size_t>(k)], loads[static_cast<std::size_t>(k)]);
      continue;
    }
    const Vec2 a(model.nodes[p.node_a].r, model.nodes[p.node_a].z);
    const Vec2 b(model.nodes[p.node_b].r, model.nodes[p.node_b].z);
    const Vec2 tangent = (b - a).normalized();
    Vec2 inward(-tangent.y(), tangent.x());
    if (inward.dot(centroid - 0.5 * (a + b)) < 0.0) inward = -inward;
    const Vec2 traction = p.normal * inward + p.shear * tangent;
    const auto loads = edge_traction_loads(a, b, traction, model.analysis, model.thickness);
    add(p.node_a, loads[0]);
    add(p.node_b, loads[1]);
  }
}

void StiffnessSystem::assemble_external_loads() {
  external_.assign(static_cast<std::size_t>(dofs_.size()), 0.0);
  for_each_external_load(model_, [this](int node, const Vec2& force) {
    for (int dir = 0; dir < 2; ++dir) {
      const Index eq = dofs_.equation(node, dir);
      if (eq >= 0) external_[eq] += force[dir];
    }
  });
}

PointLawsOf at_every_point(const LawOf& law_of) {
  return [&law_of](std::size_t e, std::span<Constitutive> scratch) {
    scratch[0] = law_of(e);
    return std::span<const Constitutive>(scratch.first(1));
  };
}

void StiffnessSystem::assemble_solids(const LawOf& law_of) { assemble_solids(at_every_point(law_of)); }

void StiffnessSystem::assemble_solids(const PointLawsOf& laws_of) {
  if (values_.empty()) {
    values_.assign(static_cast<std::size_t>(pattern().nnz()), 0.0);
  } else {
    std::fill(values_.begin(), values_.end(), 0.0);
  }
  solid_rhs_ = external_;
  std::array<Constitutive, max_material_points> scratch;
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const ElementMatrices m = element_matrices(solid_element_data(model_, e, laws_of(e, scratch)));
    assembler_.add(e, ElementBlock::of(m.K, m.f), {values_, solid_rhs_});
  }
  for (std::size_t k = 0; k < gap_positions_.size(); ++k) solid_at_gap_positions_[k] = values_[gap_positions_[k]];
  rhs_ = solid_rhs_;
}

void StiffnessSystem::assemble_gaps(const LawOf& law_of) {
  assert(!values_.empty() && "assemble_solids() comes first");
  for (std::size_t k = 0; k < gap_positions_.size(); ++k) values_[gap_positions_[k]] = solid_at_gap_positions_[k];
  std::copy(solid_rhs_.begin(), solid_rhs_.end(), rhs_.begin());
  const std::size_t solids = model_.elements.size();
  for (std::size_t g = 0; g < model_.gap_count(); ++g) {
    const ElementMatrices m = element_matrices(gap_element_data(model_, g, law_of(g)));
    assembler_.add(solids + g, ElementBlock::of(m.K, m.f), {values_, rhs_});
  }
}

}  // namespace saasgaps
