// The typed fast path of the streamed items (nodes, elements, constraints): the rules of
// read_node, read_element and read_constraint (section_reader.cpp) for an item whose shape is
// already known, without a tree. Each function only accepts: every check that would report sends
// the item back (false) before anything changes, so read_item judges it and words the issue.

#include "io/sections/section_reader.hpp"
#include "solver/fe/element_shape.hpp"

namespace saasgaps::io {

bool SectionReader::read_node_values(const NodeValues& item, std::size_t index) {
  const auto id = item.id.id();
  const double r = item.r.value();
  if (!id || !contains(*radius_, r) || nodes_.contains(*id)) return false;
  item_ = index;
  nodes_.emplace(*id, Entry{as_index(model_.nodes.size()), false, as_index(index)});
  model_.nodes.push_back(Node{*id, r, item.z.value()});
  node_placed_.push_back(true);
  return true;
}

bool SectionReader::read_element_values(const ElementValues& item, std::size_t index) {
  const auto id = item.id.id();
  const auto type = default_element_type(item.node_count);
  if (!id || elements_.contains(*id) || !type) return false;
  NodeList corners;
  corners.count = item.node_count;
  const auto n = static_cast<std::size_t>(item.node_count);
  bool placed = true;
  for (std::size_t k = 0; k < n; ++k) {
    const auto node_id = item.nodes[k].id();
    const Entry* found = node_id ? nodes_.find(*node_id) : nullptr;
    if (found == nullptr) return false;
    const int node = found->index;
    const auto end = corners.nodes.begin() + static_cast<std::ptrdiff_t>(k);
    if (std::find(corners.nodes.begin(), end, node) != end) return false;
    corners.nodes[k] = node;
    placed = placed && node_placed_[static_cast<std::size_t>(node)];
  }
  if (placed) {  // read_element judges the shape only when every node has valid coordinates
    std::array<Vec2, max_element_nodes> x;
    x.fill(Vec2::Zero());
    for (std::size_t k = 0; k < n; ++k) {
      const Node& node = model_.nodes[static_cast<std::size_t>(corners.nodes[k])];
      x[k] = Vec2(node.r, node.z);
    }
    if (element_shape_problem(*type, Integration::full, x)) return false;
  }
  Element e;
  e.id = *id;
  e.nodes = corners.nodes;
  e.node_count = corners.count;
  e.type = *type;
  const auto material_id = item.material.id();
  const Entry* material = material_id ? materials_.find(*material_id) : nullptr;
  if (material == nullptr) return false;
  e.material = material->index;
  e.angle_deg = item.angle ? item.angle->value() : 0.0;
  item_ = index;
  elements_.emplace(*id, Entry{as_index(model_.elements.size()), false, as_index(index)});
  model_.elements.push_back(e);
  return true;
}

bool SectionReader::read_constraint_values(const ConstraintValues& item, std::size_t index) {
  const auto node_id = item.node.id();
  const Entry* found = node_id ? nodes_.find(*node_id) : nullptr;
  if (found == nullptr || (!item.r && !item.z)) return false;
  const int node = found->index;
  if ((item.r && prescribed_.contains({node, 'r'})) || (item.z && prescribed_.contains({node, 'z'}))) return false;
  item_ = index;
  const std::string pointer = "/constraints/" + std::to_string(index);
  Constraint c;
  c.node = node;
  if (item.r) {
    c.u_r = item.r->value();
    prescribed_.emplace(std::pair{node, 'r'}, pointer + "/r");
  }
  if (item.z) {
    c.u_z = item.z->value();
    prescribed_.emplace(std::pair{node, 'z'}, pointer + "/z");
  }
  model_.constraints.push_back(c);
  return true;
}

bool SectionReader::take_nodal_temperatures(std::span<const TemperatureValues> items) {
  // The rules of read_temperatures for items of the usual shape: each node resolves, once.
  std::vector<std::pair<int, double>> values;
  values.reserve(items.size());
  std::vector<bool> given(model_.nodes.size(), false);
  for (const TemperatureValues& item : items) {
    const auto node_id = item.node.id();
    const Entry* found = node_id ? nodes_.find(*node_id) : nullptr;
    if (found == nullptr) return false;
    const auto node = static_cast<std::size_t>(found->index);
    if (given[node]) return false;
    given[node] = true;
    values.emplace_back(found->index, item.T.value());
  }
  typed_temperatures_ = std::move(values);
  return true;
}

}  // namespace saasgaps::io
