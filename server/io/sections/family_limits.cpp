#include "io/sections/family_limits.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "io/json/json_pointer.hpp"
#include "solver/fe/element_family.hpp"

namespace saasgaps::io {

namespace {

/// A quadratic element's edge, by its two corner nodes in either order.
struct CurvedEdge {
  std::size_t element = 0;
  int middle = 0;  ///< the mid-side node's index
};

using EdgeKey = std::pair<int, int>;
EdgeKey key(int a, int b) { return a < b ? EdgeKey{a, b} : EdgeKey{b, a}; }

std::map<EdgeKey, CurvedEdge> quadratic_edges(const Model& model) {
  std::map<EdgeKey, CurvedEdge> edges;
  for (std::size_t e = 0; e < model.elements.size(); ++e) {
    const Element& el = model.elements[e];
    const ElementFamily& f = family(el.type);
    if (!f.quadratic()) continue;
    for (const EdgeNodes& edge : f.edges) {
      edges.emplace(key(el.nodes[static_cast<std::size_t>(edge.first())], el.nodes[static_cast<std::size_t>(edge.last())]),
                    CurvedEdge{e, el.nodes[static_cast<std::size_t>(edge.node[1])]});
    }
  }
  return edges;
}

std::string element_words(const Model& model, std::size_t e) {
  const Element& el = model.elements[e];
  return "element " + std::to_string(el.id) + " (" + std::string(element_type_names.name(el.type)) + ")";
}

int node_id(const Model& model, int n) { return model.nodes[static_cast<std::size_t>(n)].id; }

}  // namespace

std::vector<InputIssue> element_family_input_issues(const Model& model) {
  std::vector<InputIssue> issues;
  const std::map<EdgeKey, CurvedEdge> curved = quadratic_edges(model);
  if (curved.empty()) return issues;

  if (model.gaps) {
    for (std::size_t g = 0; g < model.gaps->elements.size(); ++g) {
      const GapElement& gap = model.gaps->elements[g];
      const std::span<const int> nodes = gap.node_span();
      for (std::size_t k = 0; k < nodes.size(); ++k) {
        const int a = nodes[k], b = nodes[(k + 1) % nodes.size()];
        const auto found = curved.find(key(a, b));
        if (found == curved.end()) continue;
        issues.push_back({pointer_append(pointer_append("/gaps/elements", g), "nodes"),
                          "gap element " + std::to_string(gap.id) + " lies along the edge [" +
                              std::to_string(node_id(model, a)) + ", " + std::to_string(node_id(model, b)) + "] of " +
                              element_words(model, found->second.element) + ", whose mid-side node " +
                              std::to_string(node_id(model, found->second.middle)) +
                              " a gap element cannot carry: gap elements join straight edges of 3- and 4-node "
                              "elements; between quadratic elements use contact surfaces (contact.surfaces)"});
        break;
      }
    }
  }
  return issues;
}

}  // namespace saasgaps::io
