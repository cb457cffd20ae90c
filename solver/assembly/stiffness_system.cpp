#include "solver/assembly/stiffness_system.hpp"

#include <algorithm>
#include <cassert>

#include "solver/assembly/element_data.hpp"
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
    const Element& el = model.elements[p.element];
    const auto x = corner_coordinates(model, el.nodes, el.node_count);
    Vec2 centroid = Vec2::Zero();
    for (int a = 0; a < el.node_count; ++a) centroid += x[a] / el.node_count;
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

void StiffnessSystem::assemble_solids(const LawOf& law_of) {
  if (values_.empty()) {
    values_.assign(static_cast<std::size_t>(pattern().nnz()), 0.0);
  } else {
    std::fill(values_.begin(), values_.end(), 0.0);
  }
  solid_rhs_ = external_;
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    const ElementMatrices m = element_matrices(solid_element_data(model_, e, law_of(e)));
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
