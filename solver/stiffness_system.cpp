#include "stiffness_system.hpp"

#include <algorithm>
#include <cassert>

#include "element_data.hpp"

namespace saasgaps {

const std::array<LocalPair, 36> upper_pairs = [] {
  std::array<LocalPair, 36> pairs{};
  int k = 0;
  for (int b = 0; b < 8; ++b) {
    for (int a = 0; a <= b; ++a) pairs[k++] = {a, b};
  }
  return pairs;
}();

StiffnessSystem::StiffnessSystem(const Model& model, const DofMap& dofs) : model_(model), dofs_(dofs) {
  const std::size_t slots = model.elements.size() + model.gap_count();
  equations_.resize(slots);
  for (std::size_t s = 0; s < slots; ++s) {
    const SlotNodes corners = slot_nodes(s);
    equations_[s] = dofs.element_equations(corners.nodes, corners.count);
  }

  pattern_ = CscPattern::from_cliques(dofs.size(), slots, [this](std::size_t s) {
    return std::span<const Index>(equations_[s]);
  });

  scatter_.assign(36 * slots, -1);
  has_prescribed_.assign(slots, false);
  for (std::size_t s = 0; s < slots; ++s) {
    const auto& eq = equations_[s];
    for (int k = 0; k < 36; ++k) {
      const auto [a, b] = upper_pairs[k];
      if (eq[a] >= 0 && eq[b] >= 0) scatter_[36 * s + k] = pattern_.find(eq[a], eq[b]);
    }
    const SlotNodes corners = slot_nodes(s);
    for (int a = 0; a < corners.count; ++a) {
      for (int dir = 0; dir < 2; ++dir) {
        const int node = corners.nodes[a];
        if (dofs.equation(node, dir) == DofMap::prescribed_dof && dofs.prescribed(node, dir) != 0.0) {
          has_prescribed_[s] = true;
        }
      }
    }
  }
  for (std::size_t s = model.elements.size(); s < slots; ++s) {
    for (int k = 0; k < 36; ++k) {
      if (scatter_[36 * s + k] >= 0) gap_positions_.push_back(scatter_[36 * s + k]);
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

StiffnessSystem::SlotNodes StiffnessSystem::slot_nodes(std::size_t slot) const {
  const std::size_t solids = model_.elements.size();
  if (slot < solids) return {model_.elements[slot].nodes, model_.elements[slot].node_count};
  const GapElement& gap = model_.gaps->elements[slot - solids];
  return {gap.nodes, gap.node_count};
}

void StiffnessSystem::assemble_external_loads() {
  external_.assign(static_cast<std::size_t>(dofs_.size()), 0.0);
  const auto add = [this](int node, const Vec2& force) {
    for (int dir = 0; dir < 2; ++dir) {
      const Index eq = dofs_.equation(node, dir);
      if (eq >= 0) external_[eq] += force[dir];
    }
  };
  for (const NodalForce& f : model_.loads.nodal_forces) add(f.node, Vec2(f.f_r, f.f_z));
  for (const EdgePressure& p : model_.loads.pressures) {
    const Element& el = model_.elements[p.element];
    const auto x = corner_coordinates(model_, el.nodes, el.node_count);
    Vec2 centroid = Vec2::Zero();
    for (int a = 0; a < el.node_count; ++a) centroid += x[a] / el.node_count;
    const Vec2 a(model_.nodes[p.node_a].r, model_.nodes[p.node_a].z);
    const Vec2 b(model_.nodes[p.node_b].r, model_.nodes[p.node_b].z);
    const Vec2 tangent = (b - a).normalized();
    Vec2 inward(-tangent.y(), tangent.x());
    if (inward.dot(centroid - 0.5 * (a + b)) < 0.0) inward = -inward;
    const Vec2 traction = p.normal * inward + p.shear * tangent;
    const auto loads = edge_traction_loads(a, b, traction, model_.analysis, model_.thickness);
    add(p.node_a, loads[0]);
    add(p.node_b, loads[1]);
  }
}

void StiffnessSystem::scatter(std::size_t slot, const ElementMatrices& m, std::vector<double>& rhs) {
  const Index* positions = &scatter_[36 * slot];
  for (int k = 0; k < 36; ++k) {
    if (positions[k] >= 0) values_[positions[k]] += m.K(upper_pairs[k].a, upper_pairs[k].b);
  }
  const auto& eq = equations_[slot];
  for (int a = 0; a < 8; ++a) {
    if (eq[a] >= 0) rhs[eq[a]] += m.f[a];
  }
  if (!has_prescribed_[slot]) return;
  // Move K_fp u_p of prescribed displacements to the right-hand side.
  const auto& nodes = slot_nodes(slot).nodes;
  for (int b = 0; b < 8; ++b) {
    if (eq[b] != DofMap::prescribed_dof) continue;
    const double u = dofs_.prescribed(nodes[b / 2], b % 2);
    if (u == 0.0) continue;
    for (int a = 0; a < 8; ++a) {
      if (eq[a] >= 0) rhs[eq[a]] -= m.K(a, b) * u;
    }
  }
}

void StiffnessSystem::assemble_solids(const LawOf& law_of) {
  if (values_.empty()) {
    values_.assign(static_cast<std::size_t>(pattern_.nnz()), 0.0);
  } else {
    std::fill(values_.begin(), values_.end(), 0.0);
  }
  solid_rhs_ = external_;
  for (std::size_t e = 0; e < model_.elements.size(); ++e) {
    scatter(e, element_matrices(solid_element_data(model_, e, law_of(e))), solid_rhs_);
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
    scatter(solids + g, element_matrices(gap_element_data(model_, g, law_of(g))), rhs_);
  }
}

}  // namespace saasgaps
