// The element families in the model document (fe/element_family.hpp): elements[].nodes holds 3, 4,
// 6, 8 or 9 node ids, elements[].type names the family (the default follows the node count) and
// elements[].integration the quadrilaterals' rule; each family's shape rules (fe/element_shape.hpp)
// judged once the nodes are placed.

#include <algorithm>

#include "io/json/value_quote.hpp"
#include "io/sections/section_reader.hpp"
#include "solver/fe/element_shape.hpp"

namespace saasgaps::io {

namespace {

constexpr const char* node_counts = "tri3 has 3, saas and quad4i 4, tri6 6, quad8 8, quad9 9";

}  // namespace

std::optional<NodeList> SectionReader::read_element_nodes(const Obj& o) {
  const json* ids = o.find("nodes");
  if (ids != nullptr && ids->is_array() && (ids->size() == 5 || ids->size() == 7)) {
    report(o.at("nodes"), "nodes " + quote(*ids) + " lists " + std::to_string(ids->size()) +
                              " ids, but an element has 3, 4, 6, 8 or 9 nodes (tri3; saas or quad4i; tri6; quad8; "
                              "quad9): corners counter-clockwise, then the mid-side nodes, then the centre");
    return std::nullopt;
  }
  return read_node_list(o, 3, max_element_nodes,
                        "an element has 3, 4, 6, 8 or 9 nodes (tri3; saas or quad4i; tri6; quad8; quad9): corners "
                        "counter-clockwise, then the mid-side nodes, then the centre");
}

bool SectionReader::read_element_family(const Obj& o, int node_count, Element& e) {
  const auto type = choice_field(o, "type", element_type_names);
  const json* given = o.find("type");
  if (given != nullptr && !type) return false;  // reported: not a family's name
  e.type = type ? *type : *default_element_type(node_count);
  const ElementFamily& f = family(e.type);
  if (f.node_count != node_count) {
    report(o.at("type"), "type \"" + std::string(element_type_names.name(e.type)) + "\" has " +
                             std::to_string(f.node_count) + " nodes, but nodes lists " + std::to_string(node_count) +
                             " (" + node_counts + ")");
    return false;
  }
  if (const json* integration = o.find("integration")) {
    if (e.type != ElementType::quad8 && e.type != ElementType::quad9) {
      report(o.at("integration"), "integration " + quote(*integration) + " applies to quad8 and quad9 only; a " +
                                      std::string(element_type_names.name(e.type)) +
                                      " element has one rule (remove integration)");
      return false;
    }
    const auto rule = choice_field(o, "integration", integration_names);
    if (!rule) return false;
    e.integration = *rule;
  }
  return true;
}

void SectionReader::check_element_shape(const Element& e, const json& ids, const Where& pointer) {
  const auto n = static_cast<std::size_t>(e.node_count);
  std::array<Vec2, max_element_nodes> x;
  for (Vec2& p : x) p.setZero();
  for (std::size_t k = 0; k < n; ++k) {
    const Node& node = model_.nodes[static_cast<std::size_t>(e.nodes[k])];
    x[k] = Vec2(node.r, node.z);
  }
  const auto problem = element_shape_problem(e.type, e.integration, x);
  if (!problem) return;
  if (e.type == ElementType::saas || e.type == ElementType::tri3) {
    NodeList corners;
    std::copy_n(e.nodes.begin(), n, corners.nodes.begin());
    corners.count = e.node_count;
    check_shape(corners, ids, pointer);
    return;
  }
  const std::string family_name(element_type_names.name(e.type));
  switch (problem->kind) {
    case ShapeProblem::Kind::clockwise: {
      json fixed = json::array();
      for (const int k : reversed_order(e.type)) {
        if (static_cast<std::size_t>(k) < n) fixed.push_back(ids[static_cast<std::size_t>(k)]);
      }
      report(pointer, "nodes " + quote(ids) + " run clockwise (corner area " + format_number(problem->value) +
                          "); list them counter-clockwise, corners first, then the mid-side nodes in the order "
                          "of the edges, e.g. " + quote(fixed));
      break;
    }
    case ShapeProblem::Kind::degenerate:
      report(pointer, "nodes " + quote(ids) + ": the corners of this " + family_name +
                          " element enclose no area (" + format_number(problem->value) + ")");
      break;
    case ShapeProblem::Kind::midside_off_edge:
    case ShapeProblem::Kind::jacobian:
      report(pointer, "nodes " + quote(ids) + " make a " + family_name + " element that cannot be integrated: " +
                          problem->detail);
      break;
  }
}

}  // namespace saasgaps::io
