#include "dof_map.hpp"

namespace saasgaps {

DofMap::DofMap(const Model& model)
    : equation_(2 * model.nodes.size(), 0), value_(2 * model.nodes.size(), 0.0) {
  for (const Constraint& c : model.constraints) {
    if (c.u_r) {
      equation_[2 * c.node] = prescribed_dof;
      value_[2 * c.node] = *c.u_r;
    }
    if (c.u_z) {
      equation_[2 * c.node + 1] = prescribed_dof;
      value_[2 * c.node + 1] = *c.u_z;
    }
  }
  for (std::size_t k = 0; k < equation_.size(); ++k) {
    if (equation_[k] == prescribed_dof) continue;
    equation_[k] = free_count_++;
    owner_.push_back({model.nodes[k / 2].id, k % 2 == 0 ? 'r' : 'z'});
    node_of_.push_back(static_cast<Index>(k / 2));
  }
}

std::array<Index, 8> DofMap::element_equations(const std::array<int, 4>& nodes, int node_count) const {
  std::array<Index, 8> eq{};
  eq.fill(absent_dof);
  for (int a = 0; a < node_count; ++a) {
    eq[2 * a] = equation(nodes[a], 0);
    eq[2 * a + 1] = equation(nodes[a], 1);
  }
  return eq;
}

}  // namespace saasgaps
