#include "solver/assembly/dof_map.hpp"

#include <cassert>

namespace saasgaps {

DofMap::DofMap(std::span<const int> node_ids, std::string_view component_names,
               std::span<const Prescribed> prescribed)
    : components_(static_cast<int>(component_names.size())),
      equation_(component_names.size() * node_ids.size(), 0),
      value_(equation_.size(), 0.0) {
  assert(components_ > 0);
  for (const Prescribed& p : prescribed) {
    assert(p.node >= 0 && static_cast<std::size_t>(p.node) < node_ids.size());
    assert(p.component >= 0 && p.component < components_);
    const std::size_t k = static_cast<std::size_t>(components_ * p.node + p.component);
    equation_[k] = prescribed_dof;
    value_[k] = p.value;
  }
  const auto per_node = static_cast<std::size_t>(components_);
  for (std::size_t k = 0; k < equation_.size(); ++k) {
    if (equation_[k] == prescribed_dof) continue;
    equation_[k] = free_count_++;
    owner_.push_back({node_ids[k / per_node], component_names[k % per_node]});
    node_of_.push_back(static_cast<Index>(k / per_node));
  }
}

namespace {

std::vector<int> node_ids(const Model& model) {
  std::vector<int> ids;
  ids.reserve(model.nodes.size());
  for (const Node& n : model.nodes) ids.push_back(n.id);
  return ids;
}

std::vector<DofMap::Prescribed> displacement_constraints(const Model& model) {
  std::vector<DofMap::Prescribed> p;
  for (const Constraint& c : model.constraints) {
    if (c.u_r) p.push_back({c.node, 0, *c.u_r});
    if (c.u_z) p.push_back({c.node, 1, *c.u_z});
  }
  return p;
}

}  // namespace

DofMap::DofMap(const Model& model) : DofMap(node_ids(model), "rz", displacement_constraints(model)) {}

DofMap::DofMap(const Model& model, std::string_view component_names, std::span<const Prescribed> prescribed)
    : DofMap(node_ids(model), component_names, prescribed) {}

void DofMap::equations(std::span<const int> nodes, std::span<Index> out) const {
  assert(out.size() >= nodes.size() * static_cast<std::size_t>(components_));
  std::size_t k = 0;
  for (int node : nodes) {
    for (int c = 0; c < components_; ++c) out[k++] = equation(node, c);
  }
}

}  // namespace saasgaps
